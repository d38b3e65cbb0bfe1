# A test of what a program loads: runs it under glibc's dynamic loader trace (LD_DEBUG=libs, so
# Linux only) and checks whether a library whose name matches LIBRARY was loaded, and that the
# program exited with 0. Run by ctest through `cmake -P`:
#   -DCOMMAND="prog;arg;..." -DLIBRARY=REGEX -DEXPECT_LOADED=0|1 [-DEXPECT_PNG=PATH]
# With EXPECT_PNG, the program must also have written a PNG file there (checked by its signature).
if(DEFINED EXPECT_PNG)
    file(REMOVE "${EXPECT_PNG}")
endif()
set(ENV{LD_DEBUG} libs)
execute_process(COMMAND ${COMMAND}
                RESULT_VARIABLE exit_code
                OUTPUT_VARIABLE stdout
                ERROR_VARIABLE loader_trace)
unset(ENV{LD_DEBUG})
string(REPLACE ";" " " shown "${COMMAND}")
if(NOT exit_code STREQUAL "0")
    message(FATAL_ERROR "${shown}\nexited with ${exit_code}; it printed:\n${stdout}")
endif()
string(REGEX MATCHALL "calling init: [^\n]*(${LIBRARY})[^\n]*" loaded "${loader_trace}")
list(LENGTH loaded count)
if(EXPECT_LOADED AND count EQUAL 0)
    message(FATAL_ERROR "${shown}\nloaded no library matching ${LIBRARY}")
elseif(NOT EXPECT_LOADED AND NOT count EQUAL 0)
    list(JOIN loaded "\n" shown_loaded)
    message(FATAL_ERROR "${shown}\nloaded ${count} libraries matching ${LIBRARY}:\n${shown_loaded}")
endif()
if(DEFINED EXPECT_PNG)
    if(NOT EXISTS "${EXPECT_PNG}")
        message(FATAL_ERROR "${shown}\ndid not write ${EXPECT_PNG}")
    endif()
    file(READ "${EXPECT_PNG}" signature LIMIT 8 HEX)
    if(NOT signature STREQUAL "89504e470d0a1a0a")
        message(FATAL_ERROR "${shown}\nwrote ${EXPECT_PNG}, which is no PNG (it starts ${signature})")
    endif()
endif()
