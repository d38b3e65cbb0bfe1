# How a test is declared: a program of Catch2 tests, or a command run as a user runs it.

# raystep_test_program(NAME LABELS label... SOURCES file... [LINK target...] [DEFINE name=value...]
#                      [TAGGED tag label...] [GRADE] [RUNS_PROBES])
# A program of Catch2 tests, each discovered into ctest with every label given; TAGGED gives the
# tests tagged [tag] the labels after it as well. GRADE links what the grader's checks call
# (raystep_link_grade). RUNS_PROBES leaves the tests out of ctest in a sanitizer build:
# AddressSanitizer reserves more address space than a probe's sandbox allows.
function(raystep_test_program name)
    cmake_parse_arguments(PARSE_ARGV 1 arg "GRADE;RUNS_PROBES" "" "LABELS;SOURCES;LINK;DEFINE;TAGGED")
    add_executable(${name} ${arg_SOURCES})
    target_link_libraries(${name} PRIVATE raystep_testing ${arg_LINK})
    target_compile_definitions(${name} PRIVATE ${arg_DEFINE})
    raystep_set_compile_options(${name})
    if(arg_GRADE)
        raystep_link_grade(${name})
        raystep_allow_nlohmann(${name})
    endif()
    if(arg_RUNS_PROBES AND CMAKE_CXX_FLAGS MATCHES "sanitize=address")
        return()
    endif()
    # catch_discover_tests would split a list of labels given in PROPERTIES, so they are set by a
    # script that ctest reads after the discovered tests, on the list of their names. A test spec
    # of patterns side by side asks for all of them ("~[meshes][measurement]").
    set(spec ${RAYSTEP_CATCH_TEST_SPEC})
    set(labels_script "")
    if(arg_TAGGED)
        list(POP_FRONT arg_TAGGED tag)
        if(NOT arg_TAGGED)
            message(FATAL_ERROR "raystep_test_program(${name}): TAGGED ${tag} names no label")
        endif()
        catch_discover_tests(${name} TEST_SPEC ${spec}[${tag}] TEST_LIST ${name}_tagged)
        string(APPEND labels_script "set_tests_properties(\${${name}_tagged} PROPERTIES LABELS "
                                    "\"${arg_LABELS};${arg_TAGGED}\")\n")
        set(spec ${spec}~[${tag}])
    endif()
    catch_discover_tests(${name} TEST_SPEC ${spec} TEST_LIST ${name}_names)
    string(APPEND labels_script
           "set_tests_properties(\${${name}_names} PROPERTIES LABELS \"${arg_LABELS}\")\n")
    file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/${name}_labels.cmake "${labels_script}")
    set_property(DIRECTORY APPEND PROPERTY TEST_INCLUDE_FILES
                 ${CMAKE_CURRENT_BINARY_DIR}/${name}_labels.cmake)
endfunction()

# raystep_command_test(NAME EXIT_CODE OUTPUT_REGEX PROGRAM ARGS...): a program as a user meets it,
# run with arguments: its exit code, and the output it must match (cmake/RunCommandTest.cmake).
# Labelled cli.
function(raystep_command_test name exit_code output_regex)
    add_test(NAME "raystep command: ${name}"
             COMMAND ${CMAKE_COMMAND} "-DCOMMAND=${ARGN}" -DEXPECT_EXIT=${exit_code}
                     "-DEXPECT_OUTPUT=${output_regex}" -P ${PROJECT_SOURCE_DIR}/cmake/RunCommandTest.cmake)
    set_tests_properties("raystep command: ${name}" PROPERTIES LABELS "cli")
endfunction()
