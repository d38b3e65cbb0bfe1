# A test of a program as a user meets it: run with arguments, its exit code and the output it
# must match (cmake/RunCommandTest.cmake). Labelled cli.
function(raystep_command_test name exit_code output_regex)
    add_test(NAME "raystep command: ${name}"
             COMMAND ${CMAKE_COMMAND} "-DCOMMAND=${ARGN}" -DEXPECT_EXIT=${exit_code}
                     "-DEXPECT_OUTPUT=${output_regex}" -P ${PROJECT_SOURCE_DIR}/cmake/RunCommandTest.cmake)
    set_tests_properties("raystep command: ${name}" PROPERTIES LABELS "cli")
endfunction()

