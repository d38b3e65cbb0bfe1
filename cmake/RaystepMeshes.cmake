# The real meshes of Debian's libcgal-demo (bunny00.off, armadillo, elephant), extracted once into
# the build folder: the bench's bunny workloads, the scenes that show them, and the tests tagged
# [meshes] use them. Without the package the bench skips those workloads and says which package
# provides them, and the tests tagged [meshes] are not run.
set(RAYSTEP_CGAL_DATA /usr/share/doc/libcgal-dev/data.tar.gz CACHE FILEPATH
    "CGAL's demo data (Debian's libcgal-demo), where the bunny and the other bench meshes come from")
set(RAYSTEP_BENCH_MESHES ${CMAKE_BINARY_DIR}/meshes)
if(EXISTS ${RAYSTEP_CGAL_DATA} AND NOT EXISTS ${RAYSTEP_BENCH_MESHES}/bunny00.off)
    file(ARCHIVE_EXTRACT INPUT ${RAYSTEP_CGAL_DATA} DESTINATION ${CMAKE_BINARY_DIR}/cgal-data
         PATTERNS data/meshes/bunny00.off data/meshes/armadillo.off data/meshes/elephant.off)
    file(GLOB extracted ${CMAKE_BINARY_DIR}/cgal-data/data/meshes/*.off)
    file(COPY ${extracted} DESTINATION ${RAYSTEP_BENCH_MESHES})
    file(REMOVE_RECURSE ${CMAKE_BINARY_DIR}/cgal-data)
endif()
# The same meshes for the scenes that show them (scenes/stage4/bunny.test and others), which
# name them relative to themselves as ../meshes/NAME.off: copied next to the scenes, out of git.
if(EXISTS ${RAYSTEP_BENCH_MESHES}/bunny00.off AND NOT EXISTS ${PROJECT_SOURCE_DIR}/scenes/meshes/bunny00.off)
    file(GLOB bench_meshes ${RAYSTEP_BENCH_MESHES}/*.off)
    file(COPY ${bench_meshes} DESTINATION ${PROJECT_SOURCE_DIR}/scenes/meshes)
endif()
# Without the meshes the Catch2 tests tagged [meshes] are left out of ctest
# (RAYSTEP_CATCH_TEST_SPEC, for every catch_discover_tests of a program that has such tests).
if(EXISTS ${RAYSTEP_BENCH_MESHES}/bunny00.off AND EXISTS ${PROJECT_SOURCE_DIR}/scenes/meshes/bunny00.off)
    set(RAYSTEP_CATCH_TEST_SPEC "")
else()
    set(RAYSTEP_CATCH_TEST_SPEC "~[meshes]")
    message(STATUS "CGAL's demo meshes were not found (${RAYSTEP_CGAL_DATA}): the tests tagged [meshes] are not run (Debian: libcgal-demo)")
endif()
