#!/usr/bin/env bash
# How long the model submission (grader/tests/submissions/model) takes to grade, the figures the
# grading goals are held to (docs/measurements/grading-time.md): without the speed checks, with
# them, and both again from a cache that the first runs filled (a regrade, or a batch's second
# submission onward). Each line: the grader's own times (build, checks), the wall time, the
# processor time the whole machine spent meanwhile (/proc/stat: the grader's sandboxed compiles and
# probes are no children that a `time` of the grader would count), and the load average before
# it, which should be near 0 for figures to compare, and for the processor time to be the grade's.
#
#   scripts/bench-grading.sh [BUILD]     (default: build/release)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/release}
grade=$build/bin/raystep-grade
if [ ! -x "$grade" ]; then
    echo "no $grade: build the release first (cmake --build --preset release)" >&2
    exit 2
fi
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# busy_ticks: the machine's processor time so far, in clock ticks, idle and waiting left out.
busy_ticks() {
    awk '/^cpu / { print $2 + $3 + $4 + $7 + $8 }' /proc/stat
}

# run NAME ARGUMENTS...: one grade of the model into a fresh folder, and its line.
run() {
    local name=$1
    shift
    local load busy_before
    load=$(cut -d' ' -f1 /proc/loadavg)
    busy_before=$(busy_ticks)
    /usr/bin/time -f "%e" -o "$work/time" "$grade" submission \
        grader/tests/submissions/model -o "$work/$name" "$@" >"$work/$name.log" 2>&1
    local times busy
    times=$(grep '^times:' "$work/$name.log" | sed 's/^times: //')
    busy=$(($(busy_ticks) - busy_before))
    awk -v name="$name" -v load="$load" -v times="$times" -v busy="$busy" \
        -v hertz="$(getconf CLK_TCK)" \
        '{ printf "%-28s %6.1f s wall, %6.1f s of processor (load before %s): %s\n", name, $1,
           busy / hertz, load, times }' "$work/time"
}

run "without speed" --no-speed
run "with speed"
run "without speed, cache filled" --no-speed --cache "$work/cache"
run "without speed, from cache" --no-speed --cache "$work/cache"
run "with speed, from cache" --cache "$work/cache"
