# How a test is declared: a program of Catch2 tests, or a command run as a user runs it.

# raystep_test_program(NAME LABELS label... [FOLDERS folder...] [SOURCES file...] [EXCEPT file...]
#                      [LINK target...] [DEFINE name=value...] [TAGGED tag label...] [GRADE]
#                      [RUNS_PROBES])
# A program of Catch2 tests: the .cpp files in each folder's tests/ and SOURCES, but EXCEPT
# (raystep_sources), each test discovered into ctest with every label given; TAGGED gives the
# tests tagged [tag] the labels after it as well. GRADE links what the grader's checks call
# (raystep_link_grade). RUNS_PROBES leaves the tests out of ctest in a sanitizer build:
# AddressSanitizer reserves more address space than a probe's sandbox allows.
function(raystep_test_program name)
    cmake_parse_arguments(PARSE_ARGV 1 arg "GRADE;RUNS_PROBES" ""
                          "LABELS;FOLDERS;SOURCES;EXCEPT;LINK;DEFINE;TAGGED")
    list(TRANSFORM arg_FOLDERS APPEND /tests)
    raystep_sources(sources FOLDERS ${arg_FOLDERS} SOURCES ${arg_SOURCES} EXCEPT ${arg_EXCEPT})
    add_executable(${name} ${sources})
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

# raystep_test(NAME LABELS label... [PROPERTIES name value...] COMMAND command...): a test that
# runs a command, with its labels and any other properties of a test.
function(raystep_test name)
    cmake_parse_arguments(PARSE_ARGV 1 arg "" "" "LABELS;PROPERTIES;COMMAND")
    add_test(NAME "${name}" COMMAND ${arg_COMMAND})
    set_tests_properties("${name}" PROPERTIES LABELS "${arg_LABELS}" ${arg_PROPERTIES})
endfunction()

# raystep_command_test(NAME EXIT_CODE OUTPUT_REGEX [LABELS label...] [PROPERTIES ...]
#                      COMMAND program args...): a program as a user meets it, run with arguments:
# its exit code, and the output it must match (cmake/RunCommandTest.cmake). Labelled cli unless
# LABELS says otherwise.
function(raystep_command_test name exit_code output_regex)
    cmake_parse_arguments(PARSE_ARGV 3 arg "" "" "LABELS;PROPERTIES;COMMAND")
    if(NOT arg_LABELS)
        set(arg_LABELS cli)
    endif()
    add_test(NAME "raystep command: ${name}"
             COMMAND ${CMAKE_COMMAND} "-DCOMMAND=${arg_COMMAND}" -DEXPECT_EXIT=${exit_code}
                     "-DEXPECT_OUTPUT=${output_regex}" -P ${PROJECT_SOURCE_DIR}/cmake/RunCommandTest.cmake)
    set_tests_properties("raystep command: ${name}" PROPERTIES LABELS "${arg_LABELS}"
                                                               ${arg_PROPERTIES})
endfunction()
