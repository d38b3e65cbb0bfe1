# raystep_set_compile_options(TARGET): the warnings and floating-point rules every target of ours
# compiles with.
#
# -ffp-contract=off: a fused multiply-add rounds once where a*b + c rounds twice, so a compiler
# that fuses where it likes (clang does on ARM, GCC does in GNU mode) makes results differ between
# a student's laptop and the grader, and breaks the exact-negation argument of the watertight
# triangle test. MSVC does not contract under its default /fp:precise.
function(raystep_set_compile_options target)
    if(MSVC)
        target_compile_options(${target} PRIVATE /W4 /permissive-)
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
    endif()
endfunction()
