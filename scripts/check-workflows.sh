#!/usr/bin/env bash
# Every GitHub Actions workflow of the repository, validated as GitHub would read it: this
# repository's own (.github/workflows/, the student platforms workflow) and the one the student
# release ships (release/github/classroom.yml, GitHub Classroom's autograding). No workflow can
# run here, so this is what can be checked of them before GitHub runs them.
#
#   scripts/check-workflows.sh              validate with the validators installed
#   scripts/check-workflows.sh --install    install them first (npm), then validate
#   scripts/check-workflows.sh FILE...      validate these files instead
#
# Two validators, from npm, installed outside the repository, under $RAYSTEP_WORKFLOW_TOOLS
# (/tmp/raystep-workflow-tools unless set):
#   @action-validator/cli   SchemaStore's JSON schema of workflows (github-workflow.json, built
#                           into the package), and that every path glob matches a file;
#   @actions/workflow-parser  GitHub's own parser and template schema, which also reads every
#                           ${{ }} expression and the contexts each key may use
#                           (scripts/check-workflows.mjs).
# Without node, or with neither validator installed, it says what to install and exits 77, which
# ctest counts as skipped (the "docs" test in CMakeLists.txt). Exits 1 when a workflow is invalid.
set -euo pipefail
cd "$(dirname "$0")/.."
tools=${RAYSTEP_WORKFLOW_TOOLS:-/tmp/raystep-workflow-tools}
packages=(@action-validator/cli@0.6.0 @action-validator/core@0.6.0 @actions/workflow-parser@0.3.61)

if [ "${1:-}" = "--install" ]; then
    shift
    npm install --prefix "$tools" --no-audit --no-fund --loglevel=error "${packages[@]}"
fi
if [ $# -gt 0 ]; then
    files=("$@")
else
    files=(.github/workflows/*.yml release/github/*.yml)
fi

action_validator=$tools/node_modules/.bin/action-validator
workflow_parser=$tools/node_modules/@actions/workflow-parser/dist/index.js
if ! command -v node >/dev/null || { [ ! -x "$action_validator" ] && [ ! -f "$workflow_parser" ]; }; then
    echo "skipped: no workflow validator is installed under $tools (it needs node and npm);"
    echo "  scripts/check-workflows.sh --install installs them there: ${packages[*]}"
    exit 77
fi

problems=0
if [ -x "$action_validator" ]; then
    for file in "${files[@]}"; do
        if output=$("$action_validator" "$file" 2>&1); then
            echo "ok   $file: valid by SchemaStore's workflow schema (action-validator)"
        else
            echo "FAIL $file: not valid by SchemaStore's workflow schema (action-validator):"
            # Its report is JSON: the leaves' paths and details say what is wrong and where.
            grep -E '"(path|detail)"' <<<"$output" | sed 's/^ */  /' | sort -u | head -n 40
            problems=$((problems + 1))
        fi
    done
else
    echo "skip SchemaStore's schema: @action-validator/cli is not installed under $tools"
fi
if [ -f "$workflow_parser" ]; then
    node scripts/check-workflows.mjs "$tools" "${files[@]}" || problems=$((problems + 1))
else
    echo "skip GitHub's parser: @actions/workflow-parser is not installed under $tools"
fi

if [ "$problems" -ne 0 ]; then
    echo "$problems problem(s) in the workflows"
    exit 1
fi
