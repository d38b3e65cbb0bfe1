# How a library of ours is declared: by the folders that hold it, so that a new file needs no
# line of CMake.

# raystep_sources(OUT [FOLDERS folder...] [SOURCES file...] [EXCEPT file...]): into OUT, the .cpp
# files directly inside each folder (not in its tests/), with SOURCES added and EXCEPT taken out;
# a relative path is the current source folder's.
function(raystep_sources out)
    cmake_parse_arguments(PARSE_ARGV 1 arg "" "" "FOLDERS;SOURCES;EXCEPT")
    set(sources)
    foreach(folder IN LISTS arg_FOLDERS)
        cmake_path(ABSOLUTE_PATH folder NORMALIZE)
        string(REGEX REPLACE "/$" "" folder "${folder}")
        file(GLOB found CONFIGURE_DEPENDS ${folder}/*.cpp)
        # Not an editor's lock file or macOS's metadata beside a file (.#x.cpp, ._x.cpp).
        list(FILTER found EXCLUDE REGEX "/\\.[^/]*$")
        list(APPEND sources ${found})
    endforeach()
    foreach(file IN LISTS arg_SOURCES)
        cmake_path(ABSOLUTE_PATH file NORMALIZE)
        list(APPEND sources ${file})
    endforeach()
    foreach(file IN LISTS arg_EXCEPT)
        cmake_path(ABSOLUTE_PATH file NORMALIZE)
        if(NOT file IN_LIST sources)
            message(FATAL_ERROR "raystep_sources: EXCEPT names ${file}, which is not among them")
        endif()
        list(REMOVE_ITEM sources ${file})
    endforeach()
    set(${out} ${sources} PARENT_SCOPE)
endfunction()

# raystep_library(NAME STATIC|OBJECT [FOLDERS ...] [SOURCES ...] [EXCEPT ...] [LINK item...]
#                 [DEFINE name=value...] [NLOHMANN]): a library of the files raystep_sources
# finds, compiled with raystep_set_compile_options. LINK is target_link_libraries' list, PUBLIC
# unless a PRIVATE keyword in it says otherwise; DEFINE's definitions are the library's own.
# NLOHMANN: the code uses nlohmann/json (raystep_allow_nlohmann).
function(raystep_library name kind)
    cmake_parse_arguments(PARSE_ARGV 2 arg "NLOHMANN" "" "FOLDERS;SOURCES;EXCEPT;LINK;DEFINE")
    raystep_sources(sources FOLDERS ${arg_FOLDERS} SOURCES ${arg_SOURCES} EXCEPT ${arg_EXCEPT})
    add_library(${name} ${kind} ${sources})
    target_link_libraries(${name} PUBLIC ${arg_LINK})
    target_compile_definitions(${name} PRIVATE ${arg_DEFINE})
    raystep_set_compile_options(${name})
    if(arg_NLOHMANN)
        raystep_allow_nlohmann(${name})
    endif()
endfunction()

# GCC 12 at -O3 sees a null dereference inside nlohmann/json's inlined accessors that cannot
# happen (json.hpp:1311, m_type of a value it has just checked): a false positive in a header
# we do not own, silenced for the code that uses it.
function(raystep_allow_nlohmann target)
    if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
        target_compile_options(${target} PRIVATE -Wno-null-dereference)
    endif()
endfunction()
