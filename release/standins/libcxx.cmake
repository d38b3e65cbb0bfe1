# The macOS stand-in: clang 16 with libc++, the C++ standard library Apple ships, so that what
# only libstdc++ offers (floating from_chars, headers that other headers happen to include, its
# file-time representation) fails here as it would on a student's Mac.
#
#   cmake --preset student --toolchain release/standins/libcxx.cmake -B build/libcxx
#
# Debian's compiled C++ libraries are built against libstdc++, and a libc++ program cannot call
# them. Each is taken another way (packages/ here):
#   Catch2 2        its single header, with its main compiled in this build;
#   tinyobjloader   its single header, compiled in this build;
#   OpenImageIO     Debian's, linked by the image module alone and compiled against libstdc++: the
#                   module's plain C table (base/image/image_library_table.h) is the one thing it
#                   shares with the programs, which is what lets a Mac's module differ as well;
#                   building OpenImageIO and its C++ dependencies against libc++ would take longer
#                   than CI's whole run;
#   cpp-httplib     left out: Debian ships it compiled, so `raystep view` is not built here.
set(CMAKE_C_COMPILER clang-16)
set(CMAKE_CXX_COMPILER clang++-16)
set(CMAKE_CXX_FLAGS_INIT "-stdlib=libc++")
# -O0, not the student preset's -O3: a stand-in checks what compiles and runs on another system,
# which the optimiser does not change. This build compiles file by file, in three quarters of
# -O3's time at -O0, and the public tests still run in seconds (docs/measurements/ci-time.md).
# Set in the cache, not as CMAKE_CXX_FLAGS_RELEASE_INIT, to which CMake appends its own -O3.
set(CMAKE_CXX_FLAGS_RELEASE "-O0 -DNDEBUG" CACHE STRING "The libc++ stand-in's optimization")
foreach(kind EXE SHARED MODULE)
    set(CMAKE_${kind}_LINKER_FLAGS_INIT "-stdlib=libc++")
endforeach()

set(CMAKE_DISABLE_FIND_PACKAGE_PkgConfig ON)
set(CMAKE_DISABLE_FIND_PACKAGE_httplib ON)
foreach(package Catch2 tinyobjloader OpenImageIO)
    set(${package}_DIR ${CMAKE_CURRENT_LIST_DIR}/packages/${package} CACHE PATH "" FORCE)
endforeach()
