#!/usr/bin/env bash
# A student's second command (README.md): rebuilds what changed and runs the public tests of the
# stages named, or of every stage. Exit 0 when every test run passes.
#
#   scripts/test.sh            every stage's public tests
#   scripts/test.sh 3          stage 3's
#   scripts/test.sh 3 4        stages 3 and 4
set -euo pipefail
cd "$(dirname "$0")/.."

for stage in "$@"; do
    if ! [[ "$stage" =~ ^[1-9][0-9]*$ ]] || ! ls -d "stages/${stage}_"* >/dev/null 2>&1; then
        echo "scripts/test.sh: no stage '$stage'; the stages are: $(ls stages | grep -Eo '^[0-9]+' | sort -n | tr '\n' ' ')" >&2
        exit 2
    fi
done
if [ ! -f build/student/CMakeCache.txt ]; then
    echo "scripts/test.sh: nothing is built yet; run scripts/setup.sh first" >&2
    exit 2
fi

# The build's progress lines are noise here; a compile error is not, and is shown whole.
if ! build_output=$(cmake --build --preset student 2>&1); then
    echo "$build_output"
    echo "scripts/test.sh: the build failed (the compiler's words above)" >&2
    exit 1
fi
labels=$(IFS='|'; echo "${*:-[0-9]+}")
ctest --preset student -L "^stage(${labels})$" --output-on-failure
