#!/usr/bin/env bash
# Gradescope runs this once, as root, when it builds the autograder's image (docs/instructor.md,
# "Gradescope"). The autograder zip (make-autograder-zip.sh) holds the instructor repository with
# this file and run_autograder at its top; Gradescope unpacks it into $AUTOGRADER/source.
#
# It installs only what grading needs (the packages already there are taken as they are), builds
# only raystep-grade and the reference probe, and then closes the repository to every user but
# root: probes run as nobody (grader/sandbox/sandbox_user.h), and where Gradescope's container
# has no user namespaces, bubblewrap cannot hide the files, so their modes must.
set -euo pipefail
AUTOGRADER=${AUTOGRADER:-/autograder}
source=$AUTOGRADER/source
cd "$source"

scripts/install-deps.sh --grading
cmake --preset release
cmake --build --preset release --target raystep-grade raystep-probe-reference

# Nothing of the repository or its build is readable by others: not solutions/, the rubric, the
# grader's sources, the reference's libraries and probes, nor the build's record of them. The
# probe builder copies what a submission compiles against and links with into the submission's
# work folder, so a probe's compile and link read nothing here. A probe reads only scenes/ (the
# render checks name scene files there, and the meshes they load sit beside them): the folders
# above it can be passed through, not listed.
chmod -R go-rwx "$source"
chmod go+x "$AUTOGRADER" "$source"
chmod -R go+rX "$source/scenes"
