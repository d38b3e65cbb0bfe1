# run_autograder when the grader fails: whatever raystep-grade prints or leaves behind,
# results.json is valid JSON (strict UTF-8, no raw control characters) that Gradescope can show.
# Each case runs run_autograder with RAYSTEP_GRADE naming a stand-in grader that misbehaves, and
# reads results.json back with Python's strict decoder and parser.
# cmake -DROOT=<repo> -DWORK=<scratch> -P gradescope_failure_test.cmake
cmake_minimum_required(VERSION 3.22)
find_program(PYTHON3 python3)
if(NOT PYTHON3)
    message(FATAL_ERROR "python3 is not installed: run_autograder writes results.json with it")
endif()
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})

# Reads a results.json strictly and prints its score and its output, each character of the
# output but printable ASCII, tab and newline written as \uXXXX (U+FFFD, the replacement for an
# invalid byte, as \ufffd; NUL as \u0000, which a CMake string could not hold); exits non-zero,
# saying why, when the file is not valid JSON in UTF-8.
file(WRITE ${WORK}/read_results.py [=[
import json, sys
raw = open(sys.argv[1], "rb").read()
results = json.loads(raw.decode("utf-8"))
if not isinstance(results, dict):
    sys.exit("results.json is not a JSON object")
output = "".join(c if c in "\t\n" or " " <= c <= "~" else "\\u%04x" % ord(c)
                 for c in results.get("output", ""))
print(json.dumps({"score": results.get("score"), "output": output}))
]=])

# run_case(NAME GRADER_SCRIPT): runs run_autograder with GRADER_SCRIPT (bash, given the
# submission folder as $2 and the output folder as $4) as the grader; sets score and output.
function(run_case name grader)
    set(autograder ${WORK}/${name})
    file(MAKE_DIRECTORY ${autograder}/submission ${autograder}/source/grader)
    file(CREATE_LINK ${ROOT}/grader/gradescope ${autograder}/source/grader/gradescope SYMBOLIC)
    file(WRITE ${WORK}/${name}-grader "#!/usr/bin/env bash\n${grader}\n")
    file(CHMOD ${WORK}/${name}-grader PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE)
    execute_process(COMMAND ${CMAKE_COMMAND} -E env AUTOGRADER=${autograder}
                            RAYSTEP_GRADE=${WORK}/${name}-grader
                            bash ${ROOT}/grader/gradescope/run_autograder
                    RESULT_VARIABLE status OUTPUT_VARIABLE printed ERROR_VARIABLE printed)
    if(NOT status EQUAL 0)
        message(FATAL_ERROR "${name}: run_autograder exited with ${status}:\n${printed}")
    endif()
    execute_process(COMMAND ${PYTHON3} ${WORK}/read_results.py ${autograder}/results/results.json
                    RESULT_VARIABLE status OUTPUT_VARIABLE read ERROR_VARIABLE problem)
    if(NOT status EQUAL 0)
        message(FATAL_ERROR "${name}: results.json is not valid JSON in UTF-8:\n${problem}")
    endif()
    string(JSON score GET "${read}" score)
    string(JSON output GET "${read}" output)
    set(score "${score}" PARENT_SCOPE)
    set(output "${output}" PARENT_SCOPE)
endfunction()

# expect_in_output(NAME TEXT...): each TEXT appears in the output as it is.
function(expect_in_output name)
    foreach(text IN LISTS ARGN)
        string(FIND "${output}" "${text}" at)
        if(at EQUAL -1)
            message(FATAL_ERROR "${name}: the output lacks '${text}':\n${output}")
        endif()
    endforeach()
endfunction()

# A grader that prints a tab, quotes, a backslash, control characters (an escape sequence, NUL,
# DEL) and bytes that are not UTF-8, then exits 3 without results.
run_case(unprintable-output [=[
printf 'compiler said:\there "quoted" C:\\path\n\033[31mred\033[0m \001\002\000\177 bad \377\376 \303\050 end\n'
exit 3]=])
if(NOT score STREQUAL "0")
    message(FATAL_ERROR "unprintable-output: score ${score}, expected 0")
endif()
string(ASCII 9 tab)
expect_in_output(unprintable-output "The grader failed, not your code" "exited with status 3"
                 "compiler said:${tab}here" "\"quoted\"" "C:\\path" "\\u001b"
                 "31mred" "\\u0001\\u0002\\u0000\\u007f bad \\ufffd\\ufffd \\ufffd( end")

# A grader that exits 0 but leaves its results.json cut off.
run_case(cut-off-results [=[
mkdir -p "$4/instructor" && printf '{"score": 10, "tests": [{"name": "stage' > "$4/instructor/results.json"]=])
if(NOT score STREQUAL "0")
    message(FATAL_ERROR "cut-off-results: score ${score}, expected 0")
endif()
expect_in_output(cut-off-results "not valid JSON")

# A grader that cannot be started at all.
run_case(missing-grader "exec /nonexistent/raystep-grade")
expect_in_output(missing-grader "exited with status 127" "No such file")

# A grader that graded: its results go to Gradescope as they are, text with escapes included.
run_case(graded [=[
mkdir -p "$4/instructor" && printf '{"score": 7.5, "output": "tab\\there \\"q\\" \\\\ \\u00e9", "tests": []}\n' > "$4/instructor/results.json"]=])
if(NOT score STREQUAL "7.5")
    message(FATAL_ERROR "graded: score ${score}, expected raystep-grade's 7.5")
endif()
expect_in_output(graded "tab${tab}here \"q\" \\ \\u00e9")
message(STATUS "run_autograder wrote valid results.json in every case")
