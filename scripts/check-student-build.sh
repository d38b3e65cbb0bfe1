#!/usr/bin/env bash
# What students meet, checked.
#   1. A student release, as `raystep-grade release` writes it (no solutions/, studies/ or
#      grader/, the student's README, the reference images in scenes/), built as its README says
#      (scripts/setup.sh), and scripts/test.sh run as it says.
#      Every public test must fail with a NotImplemented message and no test binary may crash;
#      `raystep render` and `raystep trace` must stop with the message of the stub that stopped
#      them, `raystep trace --compare` too, having found the reference trace the release ships,
#      and with the solutions of stages 1 and 2 put in it must find the pixel the reference's; `raystep check` must report every stage-3 function as not implemented; every
#      `raystep demo` must stop at a stub; `raystep info`, which runs no stage code, must work;
#      `raystep bench`, the studies' command, is not there.
#   2. A mixed build, RAYSTEP_STUDENT_STAGES=1: the reference stage 2 must call the student's
#      stage 1, so a render stops at a stage-1 stub.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
scene=base/tests/data/good/quad.test
stub_message='stage [0-9]+: [A-Za-z_:]+ is not implemented yet, see docs/stage[0-9]+\.md, section "[^"]+"'

release=$(mktemp -d)
trap 'rm -rf "$release"' EXIT
rmdir "$release"
build/release/bin/raystep-grade release "$release" >/dev/null
for folder in solutions studies grader; do
    if [ -e "$release/$folder" ]; then
        echo "FAIL the release holds $folder/"
        exit 1
    fi
done
for instructors in scripts/test-all.sh scripts/render-all.sh docs/instructor.md; do
    if [ -e "$release/$instructors" ]; then
        echo "FAIL the release holds the instructor's $instructors"
        exit 1
    fi
done
if ! grep -q "^scripts/setup.sh$" "$release/README.md"; then
    echo "FAIL the release's README.md is not the student's (docs/student-README.md)"
    exit 1
fi
# Built as its README says, with warnings as errors on top (setup.sh keeps the cached option).
(cd "$release" && cmake --preset student -DRAYSTEP_WARNINGS_AS_ERRORS=ON >/dev/null &&
    scripts/setup.sh)
bin=$release/build/student/bin
problems=0

for tests in "$bin"/raystep_stage*_tests; do
    xml=$("$tests" --reporter xml 2>&1) || true
    # A crash leaves the report unfinished; a finished one ends with </Catch>.
    if ! grep -q '</Catch>' <<<"$xml"; then
        echo "FAIL $tests crashed or stopped before finishing its report"
        problems=$((problems + 1))
        continue
    fi
    report=$(awk '
        /<TestCase name="/ {
            match($0, /name="[^"]*"/); name = substr($0, RSTART + 6, RLENGTH - 7)
            stub = 0; total++
        }
        /is not implemented yet, see docs\/stage/ { stub = 1 }
        /<OverallResult success="true"/ { print "  passed although every stage is a stub: " name; bad++ }
        /<OverallResult success="false"/ { if (!stub) { print "  failed without a NotImplemented message: " name; bad++ } }
        END { printf "%d %d\n", total, bad }' <<<"$xml")
    summary=$(tail -n 1 <<<"$report")
    total=${summary% *}
    bad=${summary#* }
    if [ "$total" -eq 0 ] || [ "$bad" -ne 0 ]; then
        echo "FAIL $tests: $bad of $total test cases did not fail with NotImplemented"
        sed '$d' <<<"$report"
        problems=$((problems + 1))
    else
        echo "ok   $tests: all $total test cases fail with a NotImplemented message"
    fi
done

check_command() {
    local what=$1 expected_exit=$2 pattern=$3
    shift 3
    local output exit_code=0
    output=$("$@" 2>&1) || exit_code=$?
    if [ "$exit_code" -ne "$expected_exit" ] || ! grep -Eq "$pattern" <<<"$output"; then
        echo "FAIL $what: exit $exit_code (expected $expected_exit), printed:"
        echo "$output" | sed 's/^/  /'
        problems=$((problems + 1))
    else
        echo "ok   $what: $(grep -Eo "$pattern" <<<"$output" | head -n 1)"
    fi
}
check_command "scripts/test.sh 1 runs stage 1's public tests, every one failing at a stub" 8 \
    "0% tests passed, [0-9]+ tests failed out of [0-9]+" "$release/scripts/test.sh" 1
check_command "scripts/test.sh of a stage that does not exist exits 2" 2 "no stage '9'" \
    "$release/scripts/test.sh" 9
check_command "raystep render names the stub" 1 "^raystep: $stub_message" \
    "$bin/raystep" render "$scene" --view normal -o "$release/normal.png"
check_command "raystep trace stops at the stub" 1 "^stopped: $stub_message" \
    "$bin/raystep" trace "$scene" 1 1 --view normal
# trace --compare holds a pixel against the reference trace the release ships beside the scene:
# with every stage a stub it stops at the first one.
compare_scene=$release/scenes/stage2/perspective-wide.test
check_command "raystep trace --compare finds the shipped reference trace and stops at the stub" 1 \
    "^stopped: $stub_message" "$bin/raystep" trace "$compare_scene" 0 0 --view rays --compare
# With the solutions of stages 1 and 2 in place of the student's files, the same pixel is the
# reference's. They are swapped into the release and back, each time rebuilding raystep alone:
# a copy of the release would cost a second whole build, minutes, not seconds.
swap_stage_files() {
    local from=$1 to=$2
    for stage in 1_vectors 2_rays; do
        mkdir -p "$to/$stage"
        for file in $(grep -v '^#' "$release/stages/$stage/manifest.txt"); do
            cp "$from/$stage/$file" "$to/$stage/$file"
        done
    done
    cmake --build "$release/build/student" --target raystep >/dev/null
}
student_files=$(mktemp -d)
cp -r "$release/stages/." "$student_files"
swap_stage_files "$root/solutions" "$release/stages"
check_command "raystep trace --compare of the solutions' pixel finds the traces the same" 0 \
    "the traces are the same" "$bin/raystep" trace "$compare_scene" 0 0 --view rays --compare
swap_stage_files "$student_files" "$release/stages"
rm -rf "$student_files"
check_command "raystep check reports every stage-3 function as a stub" 1 \
    "nothing was checked: 7 methods are not implemented" "$bin/raystep" check --stage 3
check_command "raystep info needs no stage" 0 "^primitives" "$bin/raystep" info "$scene"
check_command "raystep render of the full image names the stub" 1 "^raystep: $stub_message" \
    "$bin/raystep" render "$scene" -o "$release/full.png"
for demo in $("$bin/raystep" demo --list | awk 'NR > 1 {print $1}'); do
    check_command "raystep demo $demo stops at a stub" 1 "$stub_message" \
        "$bin/raystep" demo "$demo" -o "$release/demo-$demo.png"
done
check_command "raystep in a release has no bench: the studies are the instructor's" 2 \
    "no command 'bench' in this build; its commands are: render, [a-z, ]+" \
    "$bin/raystep" bench

cmake -S "$root" -B "$root/build/student-stage1" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DRAYSTEP_STUDENT_STAGES=1 -DRAYSTEP_WARNINGS_AS_ERRORS=ON >/dev/null
cmake --build "$root/build/student-stage1" --target raystep
check_command "with stage 1 the student's, the reference camera calls the stage-1 stubs" 1 \
    "^raystep: stage 1: [a-z_]+ is not implemented yet" \
    "$root/build/student-stage1/bin/raystep" render "$scene" --view normal -o "$release/mixed.png"

if [ "$problems" -ne 0 ]; then
    echo "$problems problem(s) in the student builds"
    exit 1
fi
