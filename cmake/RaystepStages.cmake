# The student/solution switch (ARCHITECTURE.md, "Student code or the reference"): every stage is
# a static library `raystep_stageN`, compiled from stages/N_topic/ when N is listed in
# RAYSTEP_STUDENT_STAGES and from solutions/N_topic/ otherwise, and always linked against the
# configured stages below it: with RAYSTEP_STUDENT_STAGES=1, the reference stage 2 calls the
# student's stage 1, which is the point. `raystep_stageN_reference` is the solution linked against
# the solutions below it, for the reference build (`raystep-reference`, used by `raystep trace
# --compare`). Both take their source list from the stage's manifest.txt, the files a student
# edits and the grader takes from a submission.

set(RAYSTEP_HAVE_SOLUTIONS FALSE)
if(EXISTS ${PROJECT_SOURCE_DIR}/solutions)
    set(RAYSTEP_HAVE_SOLUTIONS TRUE)
endif()

# Stage numbers, in lecture order, from the folder names.
set(RAYSTEP_STAGE_NUMBERS)
foreach(folder IN LISTS RAYSTEP_STAGES)
    string(REGEX MATCH "^[0-9]+" number "${folder}")
    list(APPEND RAYSTEP_STAGE_NUMBERS ${number})
endforeach()

# RAYSTEP_STUDENT_STAGES accepts "1;3", "1,3", "1 3", "1; 3" and "all". A student release has
# no solutions/, so there every stage is the student's.
string(REGEX REPLACE "[,; ]+" ";" requested "${RAYSTEP_STUDENT_STAGES}")
list(FILTER requested EXCLUDE REGEX "^$")
if(requested STREQUAL "all" OR NOT RAYSTEP_HAVE_SOLUTIONS)
    set(RAYSTEP_STUDENT_STAGE_NUMBERS ${RAYSTEP_STAGE_NUMBERS})
else()
    set(RAYSTEP_STUDENT_STAGE_NUMBERS)
    foreach(number IN LISTS requested)
        if(NOT number IN_LIST RAYSTEP_STAGE_NUMBERS)
            string(REPLACE ";" " " known "${RAYSTEP_STAGE_NUMBERS}")
            message(FATAL_ERROR
                "RAYSTEP_STUDENT_STAGES: '${number}' is not a stage; the stages are ${known} (or 'all')")
        endif()
        list(APPEND RAYSTEP_STUDENT_STAGE_NUMBERS ${number})
    endforeach()
endif()
list(REMOVE_DUPLICATES RAYSTEP_STUDENT_STAGE_NUMBERS)
string(REPLACE ";" " " shown "${RAYSTEP_STUDENT_STAGE_NUMBERS}")
if(shown STREQUAL "")
    set(shown "none")
endif()
message(STATUS "raystep: stages from stages/ (student code): ${shown}; all others from solutions/")

set(RAYSTEP_STAGE_TARGETS)
set(RAYSTEP_REFERENCE_STAGE_TARGETS)
foreach(number IN LISTS RAYSTEP_STAGE_NUMBERS)
    list(APPEND RAYSTEP_STAGE_TARGETS raystep_stage${number})
    list(APPEND RAYSTEP_REFERENCE_STAGE_TARGETS raystep_stage${number}_reference)
endforeach()

# The files a student edits in FOLDER, as listed in its manifest (comments start with #).
function(raystep_stage_manifest folder out_var)
    file(STRINGS ${PROJECT_SOURCE_DIR}/stages/${folder}/manifest.txt lines)
    set(files)
    foreach(line IN LISTS lines)
        string(STRIP "${line}" line)
        if(line AND NOT line MATCHES "^#")
            list(APPEND files ${line})
        endif()
    endforeach()
    set(${out_var} ${files} PARENT_SCOPE)
endfunction()

# raystep_add_stage(FOLDER): the stage's libraries and its public tests.
function(raystep_add_stage folder)
    string(REGEX MATCH "^[0-9]+" number "${folder}")
    raystep_stage_manifest(${folder} files)

    # A stage may call every stage below it, so each links the ones before it in the same build.
    set(lower)
    set(lower_reference)
    set(student_below FALSE)
    foreach(other IN LISTS RAYSTEP_STAGE_NUMBERS)
        if(other LESS number)
            list(APPEND lower raystep_stage${other})
            list(APPEND lower_reference raystep_stage${other}_reference)
            if(other IN_LIST RAYSTEP_STUDENT_STAGE_NUMBERS)
                set(student_below TRUE)
            endif()
        endif()
    endforeach()

    if(RAYSTEP_HAVE_SOLUTIONS)
        # The solution may go beyond the manifest (a watertight triangle test, float variants),
        # so it is every .cpp of its folder, which must include each manifest file.
        file(GLOB solution_sources CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/solutions/${folder}/*.cpp)
        foreach(file IN LISTS files)
            if(NOT EXISTS ${PROJECT_SOURCE_DIR}/solutions/${folder}/${file})
                message(FATAL_ERROR "solutions/${folder}/${file} is missing: the manifest lists it")
            endif()
        endforeach()
        add_library(raystep_stage${number}_reference STATIC ${solution_sources})
        target_link_libraries(raystep_stage${number}_reference PUBLIC raystep_base ${lower_reference})
        raystep_set_compile_options(raystep_stage${number}_reference)
        raystep_compile_file_by_file(raystep_stage${number}_reference)
    endif()

    if(number IN_LIST RAYSTEP_STUDENT_STAGE_NUMBERS)
        list(TRANSFORM files PREPEND ${PROJECT_SOURCE_DIR}/stages/${folder}/
             OUTPUT_VARIABLE student_sources)
        add_library(raystep_stage${number} STATIC ${student_sources})
        target_link_libraries(raystep_stage${number} PUBLIC raystep_base ${lower})
        raystep_set_compile_options(raystep_stage${number})
        raystep_compile_file_by_file(raystep_stage${number})
        # A stub names its parameters, as the slide does, before the student uses them.
        if(MSVC)
            target_compile_options(raystep_stage${number} PRIVATE /wd4100)
        else()
            target_compile_options(raystep_stage${number} PRIVATE -Wno-unused-parameter)
        endif()
    elseif(student_below)
        # The solution, but over the student's lower stages: compiled a second time, because a
        # program must hold one definition of each lower-stage function, the student's.
        add_library(raystep_stage${number} STATIC ${solution_sources})
        target_link_libraries(raystep_stage${number} PUBLIC raystep_base ${lower})
        raystep_set_compile_options(raystep_stage${number})
        raystep_compile_file_by_file(raystep_stage${number})
    else()
        add_library(raystep_stage${number} ALIAS raystep_stage${number}_reference)
    endif()

    file(GLOB test_sources CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/stages/${folder}/tests/*.cpp)
    if(test_sources)
        add_executable(raystep_stage${number}_tests ${test_sources})
        target_link_libraries(raystep_stage${number}_tests PRIVATE raystep_stage${number}
                                                                   raystep_testing)
        raystep_set_compile_options(raystep_stage${number}_tests)
        raystep_compile_file_by_file(raystep_stage${number}_tests)
        catch_discover_tests(raystep_stage${number}_tests
                             PROPERTIES LABELS "stage${number}")
    endif()
endfunction()
