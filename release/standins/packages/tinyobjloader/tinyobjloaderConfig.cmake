# tinyobjloader for a stand-in (release/standins/): its single header, compiled by the stand-in's
# compiler in the double-precision variant (Debian's shared libraries are built for Linux against
# libstdc++).
include(${CMAKE_CURRENT_LIST_DIR}/../standin_headers.cmake)
raystep_standin_headers(headers tiny_obj_loader.h)
raystep_standin_compiled(raystep_standin_tinyobjloader tiny_obj_loader.cpp
                         "#define TINYOBJLOADER_IMPLEMENTATION\n#include <tiny_obj_loader.h>\n")
target_include_directories(raystep_standin_tinyobjloader SYSTEM PUBLIC ${headers})
target_compile_definitions(raystep_standin_tinyobjloader PUBLIC TINYOBJLOADER_USE_DOUBLE)
add_library(tinyobjloader::tinyobjloader_double ALIAS raystep_standin_tinyobjloader)
