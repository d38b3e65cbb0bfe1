#!/usr/bin/env bash
# What a student who has written nothing yet sees, checked: builds the student configuration
# (every stage from stages/, build/student) and fails unless
#   - every public test fails, each with a NotImplemented message, and no test binary crashes;
#   - `raystep render` and `raystep trace` stop with the message of the stub that stopped them;
#   - `raystep info`, which runs no stage code, works.
set -euo pipefail
cd "$(dirname "$0")/.."

cmake --preset student -DRAYSTEP_WARNINGS_AS_ERRORS=ON >/dev/null
cmake --build --preset student
bin=build/student/bin
scene=core/tests/data/good/quad.test
stub_message='stage [0-9]+: [A-Za-z_:]+ is not implemented yet, see docs/stage[0-9]+\.md, section "[^"]+"'
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
        head -n -1 <<<"$report"
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
out_dir=$(mktemp -d)
trap 'rm -rf "$out_dir"' EXIT
check_command "raystep render names the stub" 1 "^raystep: $stub_message" \
    "$bin/raystep" render "$scene" --view normal -o "$out_dir/normal.png"
check_command "raystep trace stops at the stub" 1 "^stopped: $stub_message" \
    "$bin/raystep" trace "$scene" 1 1 --view normal
check_command "raystep info needs no stage" 0 "^primitives" "$bin/raystep" info "$scene"

if [ "$problems" -ne 0 ]; then
    echo "$problems problem(s) in the student build"
    exit 1
fi
