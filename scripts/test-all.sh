#!/usr/bin/env bash
# The second command of README.md: builds and runs the whole test suite.
#   1. the release build, warnings as errors, and every test;
#   2. the student build (every stage from stages/): every public test must fail with a
#      NotImplemented message and none may crash;
#   3. the debug build under AddressSanitizer and UndefinedBehaviorSanitizer, and every test but
#      the grader's corpus and the checks of the sources themselves (format, layers, docs), which
#      run no compiled code.
# In a student release (no solutions/) only the first: the public tests, which fail until the
# stages are written.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=$(nproc 2>/dev/null || echo 2)

echo "== release build and tests"
cmake --preset release -DRAYSTEP_WARNINGS_AS_ERRORS=ON >/dev/null
cmake --build --preset release
ctest --preset release -j "$jobs"

if [ ! -d solutions ]; then
    echo "== a student release: the tests above are yours to make pass"
    exit 0
fi

echo "== student build: every stub fails cleanly"
scripts/check-student-build.sh

echo "== sanitizer build and tests"
# Probes built by the grader's corpus test would carry AddressSanitizer too, which reserves more
# address space than the sandbox allows: the corpus runs in the release build only.
cmake --preset debug-asan -DRAYSTEP_WARNINGS_AS_ERRORS=ON >/dev/null
cmake --build --preset debug-asan
ctest --preset debug-asan -j "$jobs" -LE '^(corpus|format|layers|docs)$'

echo "== all tests passed"
