# Sourced by the student checks (scripts/check-student-build.sh, scripts/check-student-platforms.sh).
#
# check_command WHAT EXIT PATTERN COMMAND...: runs the command and holds it to exiting EXIT and
# printing a line matching PATTERN (grep -E). Prints `ok` with the first match, or `FAIL` with all
# the command printed, and then adds one to the caller's `problems`.
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
