# The Windows stand-in: a MinGW-w64 cross build (GCC and its Windows runtime, POSIX threads for
# std::thread), its programs and tests run under Wine, so that what only Linux offers (dlopen,
# /proc, POSIX file calls) fails here as it would on a student's Windows laptop.
#
#   cmake --preset student --toolchain release/standins/mingw-w64.cmake -B build/mingw
#
# Nothing is taken from Linux's /usr/include, which would hide a missing Windows header: the
# header-only libraries (GLM, Catch2 2, CLI11, nlohmann/json, tinyobjloader) are linked into a
# folder of their own (packages/standin_headers.cmake). Debian has no OpenImageIO for MinGW, and
# building it and its C++ dependencies would take longer than CI's whole run: the image module is
# left out (RAYSTEP_IMAGES=OFF), so the commands that read or write an image say it is missing.
# cpp-httplib is left out too (Debian ships it compiled for Linux): `raystep view` is not built.
set(CMAKE_SYSTEM_NAME Windows)
set(CMAKE_SYSTEM_PROCESSOR x86_64)
set(CMAKE_C_COMPILER x86_64-w64-mingw32-gcc-posix)
set(CMAKE_CXX_COMPILER x86_64-w64-mingw32-g++-posix)
set(CMAKE_RC_COMPILER x86_64-w64-mingw32-windres)
# -O1, not the student preset's -O3: a stand-in checks what compiles and runs on another system,
# which -O3 does not change, and GCC compiles these unity files in three quarters of -O3's time
# at -O1 and in twice it at -O0 (docs/measurements/ci-time.md). Set in the cache, not as
# CMAKE_CXX_FLAGS_RELEASE_INIT, to which CMake appends its own -O3.
set(CMAKE_CXX_FLAGS_RELEASE "-O1 -DNDEBUG" CACHE STRING "The MinGW stand-in's optimization")
set(CMAKE_FIND_ROOT_PATH /usr/x86_64-w64-mingw32)
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
# The tests run where the programs can: CTest and Catch2's test discovery start them under Wine.
set(CMAKE_CROSSCOMPILING_EMULATOR wine)
# The MinGW runtime (libstdc++, libgcc, winpthread) linked in, so that Wine needs no DLL path.
foreach(kind EXE SHARED MODULE)
    set(CMAKE_${kind}_LINKER_FLAGS_INIT "-static")
endforeach()

set(RAYSTEP_IMAGES OFF CACHE BOOL "" FORCE)
set(CMAKE_DISABLE_FIND_PACKAGE_PkgConfig ON)
set(CMAKE_DISABLE_FIND_PACKAGE_httplib ON)
set(CMAKE_DISABLE_FIND_PACKAGE_OpenImageIO ON)
foreach(package glm Catch2 CLI11 nlohmann_json tinyobjloader)
    set(${package}_DIR ${CMAKE_CURRENT_LIST_DIR}/packages/${package} CACHE PATH "" FORCE)
endforeach()
