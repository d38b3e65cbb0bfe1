#!/usr/bin/env bash
# A student's first command (README.md): installs what is missing on Debian or Ubuntu (elsewhere
# it prints what to install and stops), then configures and builds once with the student preset,
# every stage from stages/. Run it again after pulling; after editing a stage, scripts/test.sh
# rebuilds only what changed.
set -euo pipefail
cd "$(dirname "$0")/.."

scripts/install-deps.sh --student
cmake --preset student >/dev/null
cmake --build --preset student
echo
echo "Built: build/student/bin/raystep and the public tests. Next: scripts/test.sh 1"
