# raystep_standin_headers(OUT ENTRY...): sets OUT to a folder of the build that holds the named
# entries of Debian's /usr/include and nothing else, so that a stand-in compiler finds these
# header-only libraries without finding Linux's own headers beside them.
function(raystep_standin_headers out)
    set(folder ${CMAKE_BINARY_DIR}/standin-headers)
    file(MAKE_DIRECTORY ${folder})
    foreach(entry IN LISTS ARGN)
        if(NOT EXISTS /usr/include/${entry})
            message(FATAL_ERROR "The stand-in needs /usr/include/${entry}: scripts/install-deps.sh")
        endif()
        if(NOT EXISTS ${folder}/${entry})
            file(CREATE_LINK /usr/include/${entry} ${folder}/${entry} SYMBOLIC)
        endif()
    endforeach()
    set(${out} ${folder} PARENT_SCOPE)
endfunction()

# raystep_standin_interface(TARGET ENTRY...): TARGET as an imported header-only library of those
# entries.
function(raystep_standin_interface target)
    raystep_standin_headers(folder ${ARGN})
    add_library(${target} INTERFACE IMPORTED)
    set_target_properties(${target} PROPERTIES INTERFACE_INCLUDE_DIRECTORIES ${folder})
endfunction()

# raystep_standin_compiled(TARGET FILE CONTENT): TARGET as a static library of this build, from
# one source file FILE whose text is CONTENT (a header-only library's implementation, compiled
# with the stand-in's compiler and standard library).
function(raystep_standin_compiled target file content)
    set(source ${CMAKE_BINARY_DIR}/standin-sources/${file})
    file(CONFIGURE OUTPUT ${source} CONTENT "${content}")
    add_library(${target} STATIC ${source})
endfunction()
