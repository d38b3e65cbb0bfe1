#!/usr/bin/env bash
# What students meet, checked.
#   1. A student release, as `raystep-grade release` writes it (no solutions/, studies/ or
#      grader/, of grading/ only the calls and judges, no workflow but Classroom's, each
#      platform's list of libraries, the student's README, the reference images in scenes/),
#      built as its README says (scripts/setup.sh), and scripts/test.sh run as it says.
#      Every public test must fail with a NotImplemented message and no test binary may crash;
#      `raystep render` and `raystep trace` must stop with the message of the stub that stopped
#      them, `raystep trace --compare` too, having found the reference trace the release ships;
#      `raystep check` must report every stage-3 function as not implemented; every
#      `raystep demo` must stop at a stub; `raystep info`, which runs no stage code, must work;
#      `raystep bench`, the studies' command, is not there; `raystep grade` must run the public
#      checks of grading/ (every one not implemented) and say that hidden checks exist;
#      `raystep view`'s page must name the stub in its render, its trace and its comparison.
#   2. The same release with every stage written (the model submission's manifest files copied
#      in, nothing else): every command its READMEs name works as written
#      (scripts/check-student-readme.py), `trace --compare` finding the traces the same among them,
#      and so must `raystep view`'s comparison.
#   3. A mixed build, RAYSTEP_STUDENT_STAGES=1: the reference stage 2 must call the student's
#      stage 1, so a render stops at a stage-1 stub.
#   4. Handing in, on the stubs (so before 2 writes the stages): the release's GitHub Classroom
#      workflow (.github/workflows/classroom.yml), its `run:` and `command:` lines run in order as
#      GitHub would (the package installation skipped only where it would need a root this user
#      lacks): the public tests failing on the stubs, and each stage's `raystep grade` finding
#      every check not implemented, its points those of the checks the release holds cases for;
#      `raystep submit`'s zip holding exactly the manifests' files, all of which the grader's
#      unpacker takes.
#
# Where ccache is installed, the builds compile through it (scripts/use-ccache.sh); the release is
# written inside build/ so that the cache's base directory, the repository, holds it, and its
# objects with the release build's flags come from the cache.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
source scripts/use-ccache.sh
source scripts/check-command.sh
scene=base/tests/data/good/quad.test
stub_message='stage [0-9]+: [A-Za-z_:]+ is not implemented yet, see docs/stage[0-9]+\.md, section "[^"]+"'

release=$root/build/student-release
rm -rf "$release"
trap 'rm -rf "$release"' EXIT
# Written here, or copied from RAYSTEP_RELEASE, where scripts/test-all.sh wrote one release for
# this and the other student checks (writing one renders every scene's reference views).
if [ -n "${RAYSTEP_RELEASE:-}" ]; then
    cp -r "$RAYSTEP_RELEASE" "$release"
else
    build/release/bin/raystep-grade release "$release" >/dev/null
fi
for folder in solutions studies grader release; do
    if [ -e "$release/$folder" ]; then
        echo "FAIL the release holds $folder/"
        exit 1
    fi
done
# Of grading/'s stage folders, the release holds the calls, their JSON and the judges, which
# `raystep grade` runs the public checks with: no check, oracle or test (grader/grade/release.cpp).
held=$(cd "$release" && find grading -mindepth 2 -type f ! -path 'grading/public/*' | sort)
shipped=$(cd "$root" && ls grading/*/*_calls.* grading/*/*_json.* grading/*/*_judges.* | sort)
if [ "$held" != "$shipped" ] || [ ! -f "$release/grading/CMakeLists.txt" ]; then
    echo "FAIL the release's grading/ holds other files than the stages' calls, JSON and judges:"
    diff <(echo "$shipped") <(echo "$held") || true
    exit 1
fi
if [ -e "$release/docs/instructor.md" ]; then
    echo "FAIL the release holds the instructor's guide, docs/instructor.md"
    exit 1
fi
scripts=$(cd "$release/scripts" && ls | tr '\n' ' ')
if [ "$scripts" != "install-deps.sh setup.sh test.sh " ]; then
    echo "FAIL the release's scripts/ holds $scripts; a student's are install-deps.sh setup.sh test.sh"
    exit 1
fi
# The release's only workflow is Classroom's: the instructor's (.github/, the student platforms
# workflow) would run, and fail, on every push of a student's.
workflows=$(cd "$release/.github/workflows" && ls | tr '\n' ' ')
if [ "$workflows" != "classroom.yml " ]; then
    echo "FAIL the release's .github/workflows/ holds $workflows; a student's holds classroom.yml"
    exit 1
fi
# Each platform's list of libraries and the presets that use them (README.md, "Set up and build").
for file in Brewfile vcpkg.json CMakePresets.json cmake/RaystepVcpkg.cmake; do
    if [ ! -f "$release/$file" ]; then
        echo "FAIL the release has no $file, which its README's set-up needs"
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

# Every public test fails at a stub, none crashing: the judge the student platforms workflow and
# the stand-ins run too (scripts/check-public-tests.py).
if ! (cd "$release" && python3 "$root/scripts/check-public-tests.py" stubs student \
    --junit "$release/build/public-tests-stubs.xml"); then
    problems=$((problems + 1))
fi

check_command "scripts/test.sh 1 runs stage 1's public tests, every one failing at a stub" 8 \
    "0% tests passed, [0-9]+ tests failed out of [0-9]+" "$release/scripts/test.sh" 1
check_command "scripts/test.sh of a stage that does not exist exits 2" 2 "no stage '12'" \
    "$release/scripts/test.sh" 12
check_command "raystep render names the stub" 1 "^raystep: $stub_message" \
    "$bin/raystep" render "$scene" --view normal -o "$release/normal.png"
check_command "raystep trace stops at the stub" 1 "^stopped: $stub_message" \
    "$bin/raystep" trace "$scene" 1 1 --view normal
# trace --compare holds a pixel against the reference trace the release ships beside the scene:
# with every stage a stub it stops at the first one.
compare_scene=$release/scenes/stage2/perspective-wide.test
check_command "raystep trace --compare finds the shipped reference trace and stops at the stub" 1 \
    "^stopped: $stub_message" "$bin/raystep" trace "$compare_scene" 0 0 --view rays --compare
# raystep view: the page's render, a click's trace and its comparison with the shipped reference
# trace all stop at the stub, and the page names it.
check_command "raystep view names the stub in its render, trace and comparison" 0 \
    "stop at $stub_message" python3 "$root/app/view/tests/view_release_check.py" "$bin/raystep" \
    "$compare_scene" stubs
check_command "raystep check reports every stage-3 function as a stub" 1 \
    "nothing was checked: 7 methods are not implemented" "$bin/raystep" check --stage 3
check_command "raystep info needs no stage" 0 "^primitives" "$bin/raystep" info "$scene"
check_command "raystep render of the full image names the stub" 1 "^raystep: $stub_message" \
    "$bin/raystep" render "$scene" -o "$release/full.png"
for demo in $("$bin/raystep" demo --list | awk 'NR > 1 {print $1}'); do
    check_command "raystep demo $demo stops at a stub" 1 "$stub_message" \
        "$bin/raystep" demo "$demo" -o "$release/demo-$demo.png"
done
check_command "raystep grade runs the public checks, each not implemented, and names the hidden" 1 \
    "^Hidden checks exist and are not run here" "$bin/raystep" grade
check_command "raystep grade reports every public check of stage 1 as not implemented" 1 \
    "not implemented +0 / [0-9]+ +stage1\.unit" "$bin/raystep" grade --stage 1
check_command "raystep grade finds no public check passed" 1 \
    "^  total +0 / [0-9]+ +0 of [0-9]+" "$bin/raystep" grade
check_command "raystep in a release has no bench: the studies are the instructor's" 2 \
    "no command 'bench' in this build; its commands are: render, [a-z, ]+" \
    "$bin/raystep" bench

# The workflow's steps, read without a YAML library (python3-yaml is not among the packages
# scripts/install-deps.sh installs): each step's name, its `run:` or `command:` line, its
# max-score ("none" for a step that sets up), and whether it may fail (continue-on-error); never
# an empty field, which bash's read would merge with the tab beside it.
workflow_steps=$(python3 - "$release/.github/workflows/classroom.yml" <<'PYTHON'
import re, sys
steps = []
for line in open(sys.argv[1]):
    step = re.match(r"^\s+- name: (.*)$", line)
    if step:
        steps.append([step.group(1).strip(), "", "none", "no"])
        continue
    field = re.match(r"^\s+(run|command|max-score|continue-on-error): (.*)$", line)
    if field and steps:
        column = {"run": 1, "command": 1, "max-score": 2, "continue-on-error": 3}[field.group(1)]
        steps[-1][column] = "yes" if field.group(2).strip() == "true" else field.group(2).strip()
for name, command, points, may_fail in steps:
    if command:
        print(f"{name}\t{command}\t{points}\t{may_fail}")
PYTHON
)
# The points `raystep grade --stage N` can give each stage: the rubric's points of the checks the
# release holds a case file for (grading/public/, samples worth none) and of stage 3's functions on
# its case files (stage3.cases.*), which the workflow's max-scores must be.
public_points=$(python3 - "$release/grading" <<'PYTHON'
import collections, json, pathlib, re, sys
grading = pathlib.Path(sys.argv[1])
rubric = json.loads(re.sub(r"^\s*//.*$", "", (grading / "rubric.json").read_text(), flags=re.M))
points = collections.Counter()
for case_file in grading.glob("public/*.json"):
    check = json.loads(case_file.read_text().splitlines()[0] + "]}")
    if check["kind"] != "sample":
        points[check["stage"]] += rubric["checks"][check["check"]]["points"]
for check, entry in rubric["checks"].items():
    if check.startswith("stage3.cases."):
        points[3] += entry["points"]
print(" ".join(f"{stage}:{points[stage]:g}" for stage in sorted(points)))
PYTHON
)
stages_graded=0
while IFS=$'\t' read -r name command points may_fail; do
    if [[ "$command" == *install-deps.sh* ]] && [ "$(id -u)" -ne 0 ] && ! sudo -n true 2>/dev/null; then
        echo "skip workflow step '$name' ($command): installing packages needs root, which this user lacks"
        continue
    fi
    # As GitHub runs it: a shell in the repository (the command grader's with only PATH and
    # HOME set).
    exit_code=0
    output=$(cd "$release" && env -i PATH="$PATH" HOME="$HOME" sh -c "$command" 2>&1) ||
        exit_code=$?
    # The public tests, on the stubs: they fail, and the workflow goes on to the grade.
    if [ "$may_fail" = yes ]; then
        summary=$(grep -Eo "0% tests passed, [0-9]+ tests failed out of [0-9]+" <<<"$output" || true)
        if [ "$exit_code" -ne 8 ] || [ -z "$summary" ]; then
            echo "FAIL workflow step '$name' ($command): exit $exit_code (expected 8, every" \
                "public test failing on a stub), printed:"
            echo "$output" | tail -n 20 | sed 's/^/  /'
            problems=$((problems + 1))
        else
            echo "ok   workflow step '$name' ($command): exit 8, $summary, and the workflow goes on"
        fi
        continue
    fi
    # A step with points grades one stage, the number its command ends with; the others set up.
    if [ "$points" = none ]; then
        if [ "$exit_code" -ne 0 ]; then
            echo "FAIL workflow step '$name' ($command): exit $exit_code, printed:"
            echo "$output" | tail -n 20 | sed 's/^/  /'
            problems=$((problems + 1))
        else
            echo "ok   workflow step '$name' runs"
        fi
        continue
    fi
    stage=${command##* }
    stages_graded=$((stages_graded + 1))
    expected_points=$(grep -Eo "(^| )$stage:[0-9.]+" <<<"$public_points" | cut -d: -f2)
    if [ "$points" != "$expected_points" ]; then
        echo "FAIL workflow step '$name' gives $points points; raystep grade's checks of stage" \
            "$stage are worth ${expected_points:-nothing} ($public_points)"
        problems=$((problems + 1))
    fi
    # The command grader reads max-score with parseInt: 1.5 points would be paid as 1.
    if ! [[ "$points" =~ ^[0-9]+$ ]]; then
        echo "FAIL workflow step '$name' gives $points points: GitHub Classroom's command grader" \
            "pays whole points only (parseInt), so a stage's public checks must add up to one"
        problems=$((problems + 1))
    fi
    # On the stubs: exit 1, the checks not run named (the pipeline's all run), every check run not
    # implemented.
    if [ "$exit_code" -ne 1 ] ||
        ! grep -Eq "^(Hidden checks exist and are not run here|Every check of the rubric for these stages ran here)" <<<"$output" ||
        ! grep -Eq "^  total +0 / $points " <<<"$output" ||
        grep -Eq "^  (passed|failed) " <<<"$output"; then
        echo "FAIL workflow step '$name' ($command): exit $exit_code (expected 1, every check of" \
            "stage $stage not implemented, $points points at stake), printed:"
        echo "$output" | tail -n 20 | sed 's/^/  /'
        problems=$((problems + 1))
    else
        echo "ok   workflow step '$name' ($command, $points points): exit 1, every check not" \
            "implemented"
    fi
done <<<"$workflow_steps"
# Every stage the rubric has checks for and the whole pipeline (stage 0, the render checks of every
# stage together). A stage with public tests and no checks yet (stage 11: docs/stage11.md, "What
# the grader checks") is run by the workflow's public tests alone.
rubric_stages=$(python3 - "$release/grading/rubric.json" <<'PYTHON'
import json, pathlib, re, sys
rubric = json.loads(re.sub(r"^\s*//.*$", "", pathlib.Path(sys.argv[1]).read_text(), flags=re.M))
print(len({check.split(".")[0] for check in rubric["checks"]}))
PYTHON
)
if [ "$stages_graded" -ne "$rubric_stages" ]; then
    echo "FAIL the workflow grades $stages_graded stages and the pipeline; the rubric has checks" \
        "for $((rubric_stages - 1)) stages and the pipeline"
    problems=$((problems + 1))
fi

# raystep submit in the release: the zip holds exactly the manifests' files, and the grader's
# unpacker takes every one of them.
manifest_files=$(cd "$release" && for manifest in stages/*/manifest.txt; do
    sed -e 's/^[ \t\r]*//' -e 's/[ \t\r]*$//' -e '/^#/d' -e '/^$/d' -e "s|^|$(dirname "$manifest")/|" "$manifest"
done | sort)
check_command "raystep submit from a stage folder lists the files and writes the zip" 0 \
    "wrote $release/build/submission.zip \([0-9]+ files" \
    bash -c "cd '$release/stages/2_rays' && '$bin/raystep' submit -o '$release/build/submission.zip'"
zipped=$(python3 -m zipfile -l "$release/build/submission.zip" | awk 'NR > 1 {print $1}' | sort)
if [ "$zipped" != "$manifest_files" ]; then
    echo "FAIL submission.zip does not hold exactly the manifests' files:"
    diff <(echo "$manifest_files") <(echo "$zipped") | sed 's/^/  /'
    problems=$((problems + 1))
else
    echo "ok   submission.zip holds exactly the $(wc -l <<<"$zipped") files the manifests list"
fi
mkdir "$release/unpacked"
mapfile -t manifest_names < <(xargs -n 1 basename <<<"$manifest_files")
unpack_exit=0
listing=$("$root/build/release/bin/raystep-unpack" "$release/unpacked" 1048576 33554432 \
    "${manifest_names[@]}" <"$release/build/submission.zip") || unpack_exit=$?
taken=$(grep -c '"taken":true' <<<"$listing" || true)
if [ "$unpack_exit" -ne 0 ] || [ "$taken" -ne "${#manifest_names[@]}" ]; then
    echo "FAIL raystep-unpack took $taken of the zip's ${#manifest_names[@]} files (exit $unpack_exit):"
    echo "$listing" | sed 's/^/  /'
    problems=$((problems + 1))
else
    echo "ok   the grader's unpacker (raystep-unpack) takes all $taken files of the zip"
fi
check_command "raystep submit does not replace its zip without --force" 1 "already exists" \
    bash -c "cd '$release' && '$bin/raystep' submit -o '$release/build/submission.zip'"

if ! scripts/check-student-readme.py "$release" grader/tests/submissions/model/stages; then
    problems=$((problems + 1))
fi
check_command "raystep view with every stage written finds the click's trace the reference's" 0 \
    "finds the traces the same" python3 "$root/app/view/tests/view_release_check.py" \
    "$bin/raystep" "$compare_scene" written

# The release preset's batches, so that the files other than stage 1's come from its objects.
cmake -S "$root" -B "$root/build/student-stage1" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_UNITY_BUILD=ON -DCMAKE_UNITY_BUILD_BATCH_SIZE=16 \
    -DRAYSTEP_STUDENT_STAGES=1 -DRAYSTEP_WARNINGS_AS_ERRORS=ON >/dev/null
cmake --build "$root/build/student-stage1" --target raystep
check_command "with stage 1 the student's, the reference camera calls the stage-1 stubs" 1 \
    "^raystep: stage 1: [a-z_]+ is not implemented yet" \
    "$root/build/student-stage1/bin/raystep" render "$scene" --view normal -o "$release/mixed.png"

if [ "$problems" -ne 0 ]; then
    echo "$problems problem(s) in the student builds"
    exit 1
fi
