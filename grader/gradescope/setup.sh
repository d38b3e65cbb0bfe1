#!/usr/bin/env bash
# Gradescope runs this once, as root, when it builds the autograder's image
# (docs/instructor.md, "6. Gradescope"). The autograder zip (make-autograder-zip.sh) holds the
# instructor repository with this file and run_autograder at its top; Gradescope unpacks it into
# $AUTOGRADER/source.
#
# It installs only what grading needs (the packages already there are taken as they are), builds
# only raystep-grade, the reference probe and the unpacker, and then closes the repository to
# every user but root: probes never run as root (grader/sandbox/sandbox_user.h), and where
# Gradescope's container has no user namespaces, bubblewrap cannot hide the files, so their modes
# must.
set -euo pipefail
AUTOGRADER=${AUTOGRADER:-/autograder}
source=$AUTOGRADER/source
cd "$source"

scripts/install-deps.sh --grading
cmake --preset release
cmake --build --preset release --target raystep-grade raystep-probe-reference raystep-unpack

# Nothing of the repository or its build is open to others: not solutions/, the rubric, the
# grader's sources, the reference's libraries and probes, nor the history. Everything a sandboxed
# program reads (the headers it compiles against, what it links with, the scenes a render check
# loads, the probes) raystep-grade copies into the submission's work folder, and it refuses to
# grade without bubblewrap while a sandboxed program could enter the repository.
chmod -R go-rwx "$source"
