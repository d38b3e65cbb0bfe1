# Gradescope's autograder, simulated: a folder laid out as /autograder is on Gradescope (source/
# the repository, submission/ the student's files, results/), run_autograder run in it under
# GNU time, and its results.json read back. Checks the file is what Gradescope reads (a score and
# tests) and that the run's largest process stays within Gradescope's default 768 MB.
# cmake -DROOT=<repo> -DWORK=<scratch> -P gradescope_test.cmake (ROOT built with the release preset)
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/autograder/results ${WORK}/autograder/submission)
file(CREATE_LINK ${ROOT} ${WORK}/autograder/source SYMBOLIC)

# The submission: the reference's self-contained stages, as a student would hand them in.
foreach(stage 1_vectors 2_rays 5_transforms 6_shading 7_recursion)
    file(STRINGS ${ROOT}/stages/${stage}/manifest.txt lines REGEX "^[^#]")
    foreach(file IN LISTS lines)
        string(STRIP "${file}" file)
        file(COPY ${ROOT}/solutions/${stage}/${file} DESTINATION ${WORK}/autograder/submission/stages/${stage})
    endforeach()
endforeach()

find_program(GNU_TIME NAMES time PATHS /usr/bin NO_DEFAULT_PATH)
if(NOT GNU_TIME)
    message(FATAL_ERROR "GNU time is not installed (Debian: apt-get install time): it measures the run's memory")
endif()
execute_process(
    COMMAND ${CMAKE_COMMAND} -E env AUTOGRADER=${WORK}/autograder
            ${GNU_TIME} -f "%M %e" ${ROOT}/grader/gradescope/run_autograder
    RESULT_VARIABLE status ERROR_VARIABLE measured)
if(NOT status EQUAL 0)
    message(FATAL_ERROR "run_autograder exited with ${status}")
endif()
string(REGEX MATCH "([0-9]+) ([0-9.]+)[ \n]*$" _ "${measured}")
set(kilobytes ${CMAKE_MATCH_1})
set(seconds ${CMAKE_MATCH_2})

file(READ ${WORK}/autograder/results/results.json results)
string(JSON score GET "${results}" score)
string(JSON tests LENGTH "${results}" tests)
if(score LESS_EQUAL 0 OR tests LESS 10)
    message(FATAL_ERROR "results.json has score ${score} and ${tests} tests:\n${results}")
endif()
string(JSON first_visibility GET "${results}" tests 0 visibility)
math(EXPR megabytes "${kilobytes} / 1024")
if(megabytes GREATER 768)
    message(FATAL_ERROR "the largest process took ${megabytes} MB, over Gradescope's 768 MB")
endif()
message(STATUS "run_autograder: score ${score} over ${tests} tests in ${seconds} s; largest process ${megabytes} MB")
