#!/usr/bin/env bash
# A student's first command (README.md): installs what is missing on Debian or Ubuntu (elsewhere
# it prints what to install and stops), then configures and builds once with the student preset,
# every stage from stages/: the public tests first, which need only GLM and Catch2, then the
# raystep command. Run it again after pulling; after editing a stage, scripts/test.sh rebuilds only
# what changed.
set -euo pipefail
cd "$(dirname "$0")/.."

# What a first build compiles, in CPU-seconds on one core of the 2-core machine CI runs on: said
# before it starts, divided among this machine's cores. Remeasure: in a fresh release,
# `/usr/bin/time -f %U+%S cmake --build --preset student --target raystep_public_tests`, then the
# same for the whole build (docs/measurements/first-build.md).
public_tests_cpu_seconds=80
rest_cpu_seconds=140
cores=$(nproc 2>/dev/null || sysctl -n hw.ncpu 2>/dev/null || echo 1)
minutes() {
    awk -v s="$1" -v c="$cores" 'BEGIN {
        m = int(s / c / 60 + 0.5)
        if (s / c < 60) print "under a minute"; else if (m == 1) print "about a minute"
        else printf "about %d minutes\n", m }'
}

scripts/install-deps.sh --student
cmake --preset student >/dev/null
if [ ! -f build/student/bin/raystep ]; then
    echo "A first build: the public tests ($(minutes $public_tests_cpu_seconds) on $cores cores)," \
        "then the raystep command ($(minutes $rest_cpu_seconds) more)."
fi
cmake --build --preset student --target raystep_public_tests
echo "Built the public tests. Now the raystep command, which renders, traces and compares."
cmake --build --preset student
echo
echo "Built: build/student/bin/raystep and the public tests. Next: scripts/test.sh 1"
