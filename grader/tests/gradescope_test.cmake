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
#   6. results.json read back: every check there, each with its full points;
#   7. a hostile stage 1 that takes 3 GiB of shared memory, graded and measured the same way: within
#      768 MB, with a complete results.json that names the sandbox's rule it broke.
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
               ${source}/grader/grade/probe_builder.cpp ${source}/grading/3_intersect/stage3_checks.cpp
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
# measured_run(NAME): run_autograder on what is in submission/, its whole process tree measured
# into ${WORK}/NAME.json; stops when the tree took Gradescope's 768 MB or more. Sets peak_mb,
# sampled_mb, memory_method, cpu_method, cpu_seconds and wall_seconds in the caller.
function(measured_run name)
    run("run_autograder" ${WORK}/${name}.log
        ${python3_path} ${CMAKE_CURRENT_LIST_DIR}/measure_process_tree.py ${WORK}/${name}.json --
        ${run_autograder})
    # The numbers as measure_process_tree.py wrote them (string(JSON) would print 31.81 as
    # 31.809999999999999).
    file(READ ${WORK}/${name}.json measured)
    foreach(field memory_method cpu_method)
        string(JSON ${field} GET "${measured}" ${field})
        set(${field} ${${field}} PARENT_SCOPE)
    endforeach()
    foreach(field peak_bytes sampled_peak_bytes cpu_seconds wall_seconds)
        string(REGEX MATCH "\"${field}\": ([0-9.]+)" _ "${measured}")
        set(${field} ${CMAKE_MATCH_1})
    endforeach()
    set(cpu_seconds ${cpu_seconds} PARENT_SCOPE)
    set(wall_seconds ${wall_seconds} PARENT_SCOPE)
    math(EXPR peak_mb "${peak_bytes} / ${megabyte}")
    math(EXPR sampled_mb "${sampled_peak_bytes} / ${megabyte}")
    set(peak_mb ${peak_mb} PARENT_SCOPE)
    set(sampled_mb ${sampled_mb} PARENT_SCOPE)
    math(EXPR limit_bytes "${memory_limit_mb} * ${megabyte}")
    if(peak_bytes GREATER_EQUAL limit_bytes)
        message(FATAL_ERROR "run_autograder's processes took ${peak_mb} MB together "
                            "(${memory_method}) grading ${name}, over Gradescope's "
                            "${memory_limit_mb} MB")
    endif()
endfunction()
measured_run(model)
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

set(model_peak_mb ${peak_mb})
set(model_sampled_mb ${sampled_mb})
set(model_memory_method ${memory_method})
set(model_seconds ${wall_seconds})
set(model_cpu_seconds ${cpu_seconds})

# 7: a hostile stage 1 that takes 3 GiB of SysV shared memory in a static initializer, outside
# every probe's address space (hostile/1-shared-memory-3-gib.diff), graded the same way: the whole
# tree stays within 768 MB, results.json is complete, and the report names the rule the probe
# broke.
file(REMOVE_RECURSE ${autograder}/submission ${autograder}/results)
file(MAKE_DIRECTORY ${autograder}/submission/stages ${autograder}/results)
file(COPY ${ROOT}/grader/tests/submissions/model/stages/1_vectors
     DESTINATION ${autograder}/submission/stages)
find_program(git_path git REQUIRED)
run("git apply" ${WORK}/hostile-apply.log ${CMAKE_COMMAND} -E chdir ${autograder}/submission
    ${git_path} apply -p1 ${ROOT}/grader/tests/submissions/hostile/1-shared-memory-3-gib.diff)
measured_run(shared-memory)
file(READ ${autograder}/results/results.json hostile_results)
string(JSON hostile_tests LENGTH "${hostile_results}" tests)
string(JSON hostile_score GET "${hostile_results}" score)
if(hostile_tests EQUAL 0 OR hostile_score GREATER 0)
    message(FATAL_ERROR "the shared-memory submission got ${hostile_score} points over "
                        "${hostile_tests} checks; results: ${autograder}/results")
endif()
string(FIND "${hostile_results}" "system call the sandbox forbids" named)
if(named EQUAL -1)
    message(FATAL_ERROR "the shared-memory submission's results.json does not name the sandbox's "
                        "rule it broke; results: ${autograder}/results")
endif()

message(STATUS "autograder zip: ${zip_made}")
message(STATUS "setup.sh: ${setup_seconds} s (its log: ${WORK}/setup.log)")
message(STATUS "sandbox: ${sandbox}")
message(STATUS "run_autograder: ${score} of ${points} points over ${tests} checks in ${model_seconds} s, "
               "${model_cpu_seconds} s of processor (at least twice that on Gradescope's half processor)")
message(STATUS "peak memory of the whole tree: ${model_peak_mb} MB by ${model_memory_method}; "
               "sampled resident memory: ${model_sampled_mb} MB")
message(STATUS "the 3 GiB shared-memory submission: ${hostile_score} points over ${hostile_tests} "
               "checks in ${wall_seconds} s, peak memory ${peak_mb} MB (${memory_method})")
