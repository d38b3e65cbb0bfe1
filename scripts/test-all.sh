#!/usr/bin/env bash
# The second command of README.md: builds and runs the whole test suite.
#   1. the release build, warnings as errors, and every test;
#   2. the student build (every stage from stages/): every public test must fail with a
#      NotImplemented message and none may crash; then the student release on the stand-ins for a
#      Mac (clang with libc++) and a Windows laptop (MinGW-w64 under Wine), with the stubs and with
#      every stage written (scripts/check-student-platforms.sh);
#   3. a debug build under AddressSanitizer and UndefinedBehaviorSanitizer of what a student's
#      build holds (base/, the stages, the renderer and the student's tools) and of the grader's
#      sandbox, the code that reads what another process wrote; and their tests. The grader's
#      checks, reports and oracles and the studies, whose tests run in step 1, are left out of it:
#      they were three fifths of its build (docs/measurements/ci-time.md). It runs beside step 2.
# In a student release (no solutions/) only the first: the public tests, which fail until the
# stages are written.
# Where ccache is installed, every build compiles through one cache of the run's own
# (scripts/use-ccache.sh): the student builds and the Gradescope test's setup.sh take most of their
# objects from the release build, a unity build at the student preset's batch size. Each step prints the seconds since the start, and the end the
# cache's hits: docs/measurements/ci-time.md has the figures of a fresh clone.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc 2>/dev/null || echo 2)
source scripts/use-ccache.sh
# step WHAT: names the step that starts, and when, in seconds since the run started.
step() { echo "== $1 (at $SECONDS s)"; }

step "release build"
cmake --preset release -DRAYSTEP_WARNINGS_AS_ERRORS=ON >/dev/null
cmake --build --preset release
step "release tests"
ctest --preset release -j "$jobs"

if [ ! -d solutions ]; then
    step "a student release: the tests above are yours to make pass"
    exit 0
fi

# The student checks, mostly one command at a time, and the sanitizer run, compiles and tests
# that fill both cores, side by side: together they take about two minutes less than one after
# the other (docs/measurements/ci-time.md). The sanitizer run's output is kept in a log of its own and
# printed when it ends.
sanitizer_log=$PWD/build/sanitizer-run.log
sanitizer_run() {
    step "sanitizer build"
    # A unity build of 16 files a unit, the release preset's: the sanitizers make each
    # instantiated template dear to compile, and one unity file compiles it once for sixteen
    # files. The same batches as the release build's, so that a file that compiles only beside
    # another fails there first. Line tables only (-g1), not the Debug type's full -g: a
    # sanitizer's report names each frame's file and line from them, and the largest unity file
    # compiles in four fifths of the time.
    cmake --preset debug-asan -DRAYSTEP_WARNINGS_AS_ERRORS=ON -DCMAKE_UNITY_BUILD=ON \
        -DCMAKE_UNITY_BUILD_BATCH_SIZE=16 -DCMAKE_CXX_FLAGS_DEBUG=-g1 >/dev/null
    local sanitized=(raystep raystep-reference raystep_base_tests raystep_renderer_tests
        raystep_app_tests raystep_command_tests raystep_bench_command_tests
        raystep_sandbox_tests)
    # Every stage's public tests, by its folder's number (stages/11_surface_detail: 11).
    local folder
    for folder in stages/[0-9]*_*/; do
        folder=$(basename "$folder")
        sanitized+=("raystep_stage${folder%%_*}_tests")
    done
    cmake --build --preset debug-asan --target "${sanitized[@]}"
    step "sanitizer tests"
    # The tests of those programs, by label; of them, the page in a browser and the studies' runs
    # (browser, measurement) run the code the others run, and the test that writes the public
    # case files needs raystep-grade: the release build's writes them instead, for the tests of
    # `raystep grade` that read them. Two more repeat what other tests of this pass run, at ten to
    # twenty times their release cost (docs/measurements/ci-time.md): `raystep info` on each bad
    # scene, a sanitized process each, where load_scene's test reads every one of those scenes
    # in-process; and the path tracing demo's 576-path reference, whose renders the renderer's
    # path-traced tests run and whose figure the other demos' tests make.
    build/release/bin/raystep-grade public-cases build/debug-asan/grader/tests/grading >/dev/null
    local elsewhere='^(raystep grade: the release writer writes'
    elsewhere+='|raystep command: info on every bad scene|path_tracing_demo: light sampling beats)'
    ctest --preset debug-asan -j "$jobs" -L '^(base|renderer|app|stage[0-9]+|cli|view|sandbox)$' \
        -LE '^(browser|measurement)$' -E "$elsewhere"
}
# In a process group of its own (set -m), so that a failure here stops all of it.
set -m
sanitizer_run >"$sanitizer_log" 2>&1 &
sanitizer=$!
set +m
trap 'kill -- -"$sanitizer" 2>/dev/null || true' EXIT

step "student build: every stub fails cleanly"
# One release for the student checks, each of which works on a copy of its own.
export RAYSTEP_RELEASE=$PWD/build/pristine-release
rm -rf "$RAYSTEP_RELEASE"
build/release/bin/raystep-grade release "$RAYSTEP_RELEASE" >/dev/null
scripts/check-student-build.sh
step "student release on the Mac and Windows stand-ins"
# MinGW first: its tests under Wine run one program at a time, which the sanitizer run beside them
# fills; the libc++ build, file by file, fills both cores alone at the end.
scripts/check-student-platforms.sh mingw-w64 libcxx
rm -rf "$RAYSTEP_RELEASE"
unset RAYSTEP_RELEASE

step "the sanitizer run, begun beside the student checks"
sanitized=0
wait "$sanitizer" || sanitized=$?
trap - EXIT
cat "$sanitizer_log"
if [ "$sanitized" -ne 0 ]; then
    echo "the sanitizer run failed (exit $sanitized): its output is above"
    exit 1
fi

step "all tests passed"
if command -v ccache >/dev/null; then
    ccache --show-stats
fi
