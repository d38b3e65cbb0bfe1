# Catch2 2 for a stand-in (release/standins/): the single header, and its main compiled by the
# stand-in's compiler (Debian's libCatch2WithMain.a is built against libstdc++ for Linux). Catch's
# CMake scripts (catch_discover_tests) are Debian's: they run the test programs through the
# toolchain's CROSSCOMPILING_EMULATOR.
include(${CMAKE_CURRENT_LIST_DIR}/../standin_headers.cmake)
raystep_standin_interface(Catch2::Catch2 catch2)
raystep_standin_compiled(raystep_standin_catch2_main catch2_main.cpp
                         "#define CATCH_CONFIG_MAIN\n#include <catch2/catch.hpp>\n")
target_link_libraries(raystep_standin_catch2_main PUBLIC Catch2::Catch2)
add_library(Catch2::Catch2WithMain ALIAS raystep_standin_catch2_main)
list(APPEND CMAKE_MODULE_PATH /usr/lib/cmake/Catch2)
