# raystep_set_compile_options(TARGET): the warnings, floating-point rules and optimization every
# target of ours compiles with.
#
# -ffp-contract=off: a fused multiply-add rounds once where a*b + c rounds twice, so a compiler
# that fuses where it likes (clang does on ARM, GCC does in GNU mode) makes results differ between
# a student's laptop and the grader, and breaks the exact-negation argument of the watertight
# triangle test. MSVC does not contract under its default /fp:precise.
#
# /bigobj: the student presets build in unity files of 16 sources, and one that instantiates
# nlohmann/json and CLI11 can pass the 65,279 sections of MSVC's default object format (C1128).
function(raystep_set_compile_options target)
    if(MSVC)
        target_compile_options(${target} PRIVATE /W4 /permissive- /bigobj)
        if(RAYSTEP_WARNINGS_AS_ERRORS)
            target_compile_options(${target} PRIVATE /WX)
        endif()
    else()
        target_compile_options(${target} PRIVATE -ffp-contract=off
                                                 -Wall -Wextra -Wpedantic -Wshadow
                                                 -Wnon-virtual-dtor -Wcast-align -Wunused
                                                 -Woverloaded-virtual -Wnull-dereference)
        if(RAYSTEP_WARNINGS_AS_ERRORS)
            target_compile_options(${target} PRIVATE -Werror)
        endif()
        # A program of tests (its name ends in _tests) compiles at -O1 where a release build is
        # -O3 (not in the stand-ins, already lower): its own code is set-up and assertions, and
        # what it tests is the libraries', at -O3. The largest unity file of tests, app/'s, then
        # compiles in 25 s instead of 41, and the tests take as long as before.
        if(target MATCHES "_tests$" AND CMAKE_CXX_FLAGS_RELEASE MATCHES "-O3")
            target_compile_options(${target} PRIVATE $<$<CONFIG:Release>:-O1>)
        endif()
        # Under the sanitizers, the code a ray runs through (base/'s math, the renderer, the demos'
        # and views' images, the stages' references) compiles at -O1, as AddressSanitizer's own
        # documentation advises; everything else stays at the Debug type's -O0. At -O0 the tests
        # that render took three quarters of the sanitizer run's test time, and -O1 cuts that
        # time by two thirds for no longer a build (docs/measurements/ci-time.md).
        if(CMAKE_CXX_FLAGS MATCHES "-fsanitize=" AND
           target MATCHES "^raystep_(base|render|demo|views|stage[0-9]+_reference)$")
            target_compile_options(${target} PRIVATE $<$<CONFIG:Debug>:-O1>)
        endif()
    endif()
endfunction()

# raystep_compile_file_by_file(TARGET): TARGET's files compile one by one even in a unity build
# (CMAKE_UNITY_BUILD, which the release and student presets and scripts/test-all.sh's sanitizer
# build turn on; every other target compiles whole at any batch size, so no two files may share a
# name in an anonymous namespace: scripts/check-unity-names.py). A stage's files are a student's:
# helpers of the same name in two of them are theirs to write, and a unity build would join them
# into one file where the names clash.
function(raystep_compile_file_by_file target)
    set_target_properties(${target} PROPERTIES UNITY_BUILD OFF)
endfunction()

# Static libraries archived by GCC's own ar and ranlib (gcc-ar), which name GCC's LTO plugin to
# binutils. Binutils' ar and ranlib, told none, load every plugin of bfd-plugins/ on each call, and
# where LLVM is installed those are LLVM's, whose libraries take longer to load than the archive
# takes to write (docs/measurements/ci-time.md). Not on a Mac, where GCC's gcc-ar would hand the
# plugin to Apple's ar, which takes none.
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND NOT APPLE AND CMAKE_CXX_COMPILER_AR AND
   CMAKE_CXX_COMPILER_RANLIB)
    set(CMAKE_AR ${CMAKE_CXX_COMPILER_AR})
    set(CMAKE_RANLIB ${CMAKE_CXX_COMPILER_RANLIB})
endif()
