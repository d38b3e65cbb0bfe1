# Gradescope, from the instructor's zip to a student's grade, as Gradescope runs it:
#   1. the autograder zip, made as docs/instructor.md says (make-autograder-zip.sh);
#   2. unpacked into a fresh folder laid out as /autograder is (source/ the zip, setup.sh and
#      run_autograder beside it, submission/, results/);
#   3. setup.sh run there: it installs nothing that is installed already, builds raystep-grade
#      and the reference probe from scratch, and closes the sources to the probes' user;
#   4. that user (nobody) checked to read none of the repository: solutions/, the rubric, the
#      grader's sources, the build, and scenes/ too (raystep-grade copies what probes read);
#   5. run_autograder on the complete model submission (grader/tests/submissions/model: every
#      stage, oracle and speed checks included), with bubblewrap hidden as Gradescope's container
#      usually hides it, its whole process tree measured (measure_process_tree.py): peak memory
#      within Gradescope's 768 MB, and time within its 10 minutes, both as run here and on half a
#      processor (twice the processor time);
#   6. results.json read back: every check there, each with its full points.
# cmake -DROOT=<repo> -DWORK=<scratch> -P gradescope_test.cmake (as root, like Gradescope)
cmake_minimum_required(VERSION 3.22)
set(megabyte 1048576)
set(memory_limit_mb 768)
set(time_limit_seconds 600)

foreach(program python3 setpriv)
    find_program(${program}_path ${program})
    if(NOT ${program}_path)
        message(FATAL_ERROR "${program} is not installed; this test needs it (Debian: python3, util-linux)")
    endif()
endforeach()
file(REMOVE_RECURSE ${WORK})
set(autograder ${WORK}/autograder)
file(MAKE_DIRECTORY ${autograder}/source ${autograder}/results)

# run(NAME LOG COMMAND...): runs COMMAND with its output in LOG; stops with the log's end if it
# fails.
function(run name log)
    execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_FILE ${log} ERROR_FILE ${log})
    if(NOT status EQUAL 0)
        file(READ ${log} output)
        string(LENGTH "${output}" length)
        if(length GREATER 4000)
            math(EXPR from "${length} - 4000")
            string(SUBSTRING "${output}" ${from} -1 output)
        endif()
        message(FATAL_ERROR "${name} exited with ${status}; the end of ${log}:\n${output}")
    endif()
endfunction()

# 1 and 2: the zip, unpacked as Gradescope does.
run("make-autograder-zip.sh" ${WORK}/zip.log
    bash ${ROOT}/grader/gradescope/make-autograder-zip.sh ${WORK}/autograder.zip)
file(READ ${WORK}/zip.log zip_made)
string(STRIP "${zip_made}" zip_made)
run("unzipping the autograder" ${WORK}/unzip.log
    ${CMAKE_COMMAND} -E chdir ${autograder}/source ${CMAKE_COMMAND} -E tar xf ${WORK}/autograder.zip)
foreach(script setup.sh run_autograder)
    if(NOT EXISTS ${autograder}/source/${script})
        message(FATAL_ERROR "the autograder zip has no ${script} at its top")
    endif()
    file(COPY ${autograder}/source/${script} DESTINATION ${autograder})
endforeach()

# 3: setup.sh, timed.
string(TIMESTAMP setup_start %s)
run("setup.sh" ${WORK}/setup.log
    ${CMAKE_COMMAND} -E env AUTOGRADER=${autograder} bash ${autograder}/setup.sh)
string(TIMESTAMP setup_end %s)
math(EXPR setup_seconds "${setup_end} - ${setup_start}")

# 4: what the probes' user can read.
function(as_nobody result)
    execute_process(COMMAND ${setpriv_path} --reuid=65534 --regid=65534 --clear-groups ${ARGN}
                    RESULT_VARIABLE status OUTPUT_QUIET ERROR_QUIET)
    set(${result} ${status} PARENT_SCOPE)
endfunction()
set(source ${autograder}/source)
file(GLOB solution_files ${source}/solutions/*/*.cpp)
list(GET solution_files 0 solution_file)
foreach(secret ${solution_file} ${source}/grader/rubric/rubric.json
               ${source}/grader/grade/probe_builder.cpp ${source}/grader/grade/checks/stage3_checks.cpp
               ${source}/build/release/bin/raystep-probe-reference
               ${source}/build/release/grader/probe-toolchain.json)
    if(NOT EXISTS ${secret})
        message(FATAL_ERROR "${secret} is not there: the test checks the wrong files")
    endif()
    as_nobody(read head -c 1 ${secret})
    if(read EQUAL 0)
        message(FATAL_ERROR "nobody, the probes' user, can read ${secret}")
    endif()
endforeach()
foreach(folder ${source} ${source}/solutions ${source}/build/release/bin)
    as_nobody(listed ls ${folder})
    if(listed EQUAL 0)
        message(FATAL_ERROR "nobody, the probes' user, can list ${folder}")
    endif()
endforeach()
as_nobody(read head -c 1 ${source}/scenes/stage6/cornell-box.test)
if(read EQUAL 0)
    message(FATAL_ERROR "nobody can read ${source}/scenes: the repository is not shut whole")
endif()

# 5: the model submission graded, measured. Gradescope's container usually has no user
# namespaces, so the sandbox there runs probes with rlimits alone, and the modes setup.sh set are
# all that keeps them out of the sources: the run here hides bubblewrap the same way where it can
# (a private mount namespace with /dev/null over bwrap, which the sandbox then finds unusable).
file(COPY ${ROOT}/grader/tests/submissions/model/ DESTINATION ${autograder}/submission)
set(run_autograder ${CMAKE_COMMAND} -E env AUTOGRADER=${autograder} bash ${autograder}/run_autograder)
find_program(unshare_path unshare)
set(bubblewrap_copies)
foreach(folder /usr/local/bin /usr/bin /bin)
    if(EXISTS ${folder}/bwrap AND NOT IS_SYMLINK ${folder}/bwrap)
        list(APPEND bubblewrap_copies ${folder}/bwrap)
    endif()
endforeach()
set(sandbox "bubblewrap is not installed: probes ran with rlimits alone, as on Gradescope")
if(bubblewrap_copies)
    set(hide "")
    foreach(copy IN LISTS bubblewrap_copies)
        string(APPEND hide "mount --bind /dev/null ${copy} && ")
    endforeach()
    execute_process(COMMAND ${unshare_path} -m --propagation private sh -c "${hide}true"
                    RESULT_VARIABLE hidden OUTPUT_QUIET ERROR_QUIET)
    if(unshare_path AND hidden EQUAL 0)
        set(run_autograder ${unshare_path} -m --propagation private sh -c "${hide}exec \"$@\"" sh
                           ${run_autograder})
        set(sandbox "bubblewrap hidden: probes ran with rlimits alone, as on Gradescope")
    else()
        set(sandbox "bubblewrap could not be hidden here (no mount namespace): probes ran inside it")
    endif()
endif()
run("run_autograder" ${WORK}/run_autograder.log
    ${python3_path} ${CMAKE_CURRENT_LIST_DIR}/measure_process_tree.py ${WORK}/measured.json --
    ${run_autograder})
# The numbers as measure_process_tree.py wrote them (string(JSON) would print 31.81 as
# 31.809999999999999).
file(READ ${WORK}/measured.json measured)
foreach(field memory_method cpu_method)
    string(JSON ${field} GET "${measured}" ${field})
endforeach()
foreach(field peak_bytes sampled_peak_bytes cpu_seconds wall_seconds)
    string(REGEX MATCH "\"${field}\": ([0-9.]+)" _ "${measured}")
    set(${field} ${CMAKE_MATCH_1})
endforeach()
math(EXPR peak_mb "${peak_bytes} / ${megabyte}")
math(EXPR sampled_mb "${sampled_peak_bytes} / ${megabyte}")
math(EXPR limit_bytes "${memory_limit_mb} * ${megabyte}")
if(peak_bytes GREATER_EQUAL limit_bytes)
    message(FATAL_ERROR "run_autograder's processes took ${peak_mb} MB together (${memory_method}), "
                        "over Gradescope's ${memory_limit_mb} MB")
endif()
# On half a processor the run takes at least twice its processor time.
math(EXPR half_processor_limit "${time_limit_seconds} / 2")
if(wall_seconds GREATER_EQUAL time_limit_seconds OR cpu_seconds GREATER_EQUAL half_processor_limit)
    message(FATAL_ERROR "run_autograder took ${wall_seconds} s with ${cpu_seconds} s of processor "
                        "(twice that on half a processor), over Gradescope's ${time_limit_seconds} s")
endif()

# 6: results.json, summed up by Python (CMake's arithmetic has no decimals): the score, the
# points there were, the checks without their full points, and the stage and kind of each check.
file(WRITE ${WORK}/summary.py [=[
import json, sys
results = json.load(open(sys.argv[1], encoding="utf-8"))
tests = results.get("tests", [])
ids = [test.get("extra_data", {}).get("id", test.get("name", "")) for test in tests]
print(json.dumps({
    "score": results.get("score", 0),
    "points": sum(test.get("max_score", 0) for test in tests),
    "tests": len(tests),
    "short": [i for i, test in zip(ids, tests) if test.get("score") != test.get("max_score")],
    "parts": sorted({i.split(".")[0] for i in ids}),
    "kinds": sorted({i.split(".")[1] for i in ids if "." in i}),
}))
]=])
execute_process(COMMAND ${python3_path} ${WORK}/summary.py ${autograder}/results/results.json
                RESULT_VARIABLE status OUTPUT_VARIABLE summary ERROR_VARIABLE problem)
if(NOT status EQUAL 0)
    message(FATAL_ERROR "results.json cannot be read:\n${problem}")
endif()
foreach(field score points tests short parts kinds)
    string(JSON ${field} GET "${summary}" ${field})
endforeach()
foreach(part stage1 stage2 stage3 stage4 stage5 stage6 stage7 stage8 pipeline)
    string(FIND "${parts}" "\"${part}\"" at)
    if(at EQUAL -1)
        message(FATAL_ERROR "results.json has no check of ${part}: ${parts}")
    endif()
endforeach()
foreach(kind unit oracle render speed)
    string(FIND "${kinds}" "\"${kind}\"" at)
    if(at EQUAL -1)
        message(FATAL_ERROR "results.json has no ${kind} check: ${kinds}")
    endif()
endforeach()
if(NOT short STREQUAL "[]" OR NOT score EQUAL points OR NOT score GREATER 0)
    message(FATAL_ERROR "the model submission scored ${score} of ${points}; checks short of their "
                        "points: ${short}\n(results: ${autograder}/results)")
endif()

message(STATUS "autograder zip: ${zip_made}")
message(STATUS "setup.sh: ${setup_seconds} s (its log: ${WORK}/setup.log)")
message(STATUS "sandbox: ${sandbox}")
message(STATUS "run_autograder: ${score} of ${points} points over ${tests} checks in ${wall_seconds} s, "
               "${cpu_seconds} s of processor (at least twice that on Gradescope's half processor)")
message(STATUS "peak memory of the whole tree: ${peak_mb} MB by ${memory_method}; "
               "sampled resident memory: ${sampled_mb} MB")
