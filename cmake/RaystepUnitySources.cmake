# raystep_write_unity_sources(FILE): writes FILE, one line per C++ file a unity build may join
# with others of its target: "TARGET<TAB>absolute path". A target whose files compile one by one
# (raystep_compile_file_by_file: the stages') and a file with SKIP_UNITY_BUILD_INCLUSION are left
# out, as are generated files. scripts/check-unity-names.py reads it: two files of one target
# that define the same name in an anonymous namespace break a unity build whenever its batches
# put them together, whatever the batch size and however the build is configured.

# The targets defined in DIRECTORY and below it, into the variable OUT.
function(raystep_targets_below directory out)
    get_property(targets DIRECTORY ${directory} PROPERTY BUILDSYSTEM_TARGETS)
    get_property(subdirectories DIRECTORY ${directory} PROPERTY SUBDIRECTORIES)
    foreach(subdirectory IN LISTS subdirectories)
        raystep_targets_below(${subdirectory} below)
        list(APPEND targets ${below})
    endforeach()
    set(${out} ${targets} PARENT_SCOPE)
endfunction()

function(raystep_write_unity_sources file)
    raystep_targets_below(${PROJECT_SOURCE_DIR} targets)
    set(lines "")
    foreach(target IN LISTS targets)
        get_target_property(type ${target} TYPE)
        if(type STREQUAL "INTERFACE_LIBRARY" OR type STREQUAL "UTILITY")
            continue()
        endif()
        get_target_property(unity ${target} UNITY_BUILD)
        if(NOT unity MATCHES "NOTFOUND$" AND NOT unity)
            continue()  # one by one in every build
        endif()
        get_target_property(directory ${target} SOURCE_DIR)
        get_target_property(sources ${target} SOURCES)
        foreach(source IN LISTS sources)
            if(source MATCHES "^\\$<" OR NOT source MATCHES "\\.(cpp|cc|cxx)$")
                continue()
            endif()
            get_filename_component(path ${source} ABSOLUTE BASE_DIR ${directory})
            if(NOT path MATCHES "^${PROJECT_SOURCE_DIR}/")
                continue()
            endif()
            get_source_file_property(skip ${path} DIRECTORY ${directory}
                                     SKIP_UNITY_BUILD_INCLUSION)
            if(NOT skip)
                string(APPEND lines "${target}\t${path}\n")
            endif()
        endforeach()
    endforeach()
    file(WRITE ${file} "${lines}")
endfunction()
