#!/usr/bin/env bash
# Gradescope runs this once, when it builds the autograder's image (docs/instructor.md,
# "Gradescope"). The autograder zip holds the instructor repository with this file and
# run_autograder at its top; Gradescope unpacks it into $AUTOGRADER/source.
set -euo pipefail
AUTOGRADER=${AUTOGRADER:-/autograder}
cd "$AUTOGRADER/source"
scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release --target raystep-grade raystep-probe-reference
