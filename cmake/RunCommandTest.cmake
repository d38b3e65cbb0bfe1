# A test that runs a program and checks what a user would see: the exit code, and a regular
# expression over everything it printed. Run by ctest through `cmake -P`:
#   -DCOMMAND="prog;arg;..." -DEXPECT_EXIT=N -DEXPECT_OUTPUT=REGEX [-DEXPECT_FILE=PATH]
execute_process(COMMAND ${COMMAND}
                RESULT_VARIABLE exit_code
                OUTPUT_VARIABLE stdout
                ERROR_VARIABLE stderr)
set(output "${stdout}${stderr}")
string(REPLACE ";" " " shown "${COMMAND}")
if(NOT exit_code STREQUAL EXPECT_EXIT)
    message(FATAL_ERROR "${shown}\nexited with ${exit_code}, expected ${EXPECT_EXIT}; it printed:\n${output}")
endif()
if(DEFINED EXPECT_OUTPUT AND NOT output MATCHES "${EXPECT_OUTPUT}")
    message(FATAL_ERROR "${shown}\nprinted:\n${output}\nwhich does not match: ${EXPECT_OUTPUT}")
endif()
if(DEFINED EXPECT_FILE AND NOT EXISTS "${EXPECT_FILE}")
    message(FATAL_ERROR "${shown}\ndid not write ${EXPECT_FILE}")
endif()
