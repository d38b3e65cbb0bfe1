#!/usr/bin/env python3
"""Measures how much the public tests print for one bug: in a student release (raystep-grade
release), every stage's test program on the stubs, and on the corpus's model submission with one
mutant applied (grader/tests/submissions/mutants/), the mutant's stage's test program and every
later stage's, which build on it.

    scripts/measure-failure-output.py [--release build/failure-output]
        [--grader build/release/bin/raystep-grade] [--fresh] [--own-stage] [CASE ...]

CASE is `stubs`, `model` (the model alone, every test passing), a mutant's name
(`1-cross-sign-flipped`), or a diff against the model named like a mutant (`/tmp/1-my-bug.diff`,
its first digit the stage); `all-mutants` is every mutant. The
default: stubs, 1-cross-sign-flipped, 1-length-overflows, 2-row-zero-at-bottom. Prints one
Markdown row per test program: its lines in all, its failing test cases, and the most lines one
test case printed, with that test case, for docs/measurements/failure-output.md. The release is
written once and kept (--fresh writes it anew); source scripts/use-ccache.sh first to compile
through ccache.
"""

import argparse
import pathlib
import re
import shutil
import subprocess
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent
CORPUS = ROOT / "grader/tests/submissions"
DEFAULT_CASES = ["stubs", "1-cross-sign-flipped", "1-length-overflows", "2-row-zero-at-bottom"]
STAGES = range(1, 10)
RULE = re.compile(r"^-{79}$")
DOTS = re.compile(r"^\.{79}$")
SUMMARY = re.compile(r"^={79}$")


def run(command, cwd, quiet=True):
    output = subprocess.DEVNULL if quiet else None
    subprocess.run(command, cwd=cwd, stdout=output, stderr=output, check=True)


def test_cases(lines):
    """Each failing test case's name and the lines Catch's console reporter printed for it: from
    the rule above its name to the next test case's rule or the summary."""
    starts = []
    for k, line in enumerate(lines):
        # A test case's header: a rule, its name (one line or more), a rule, where it is, dots.
        if RULE.match(line) and (not starts or k > starts[-1][1]):
            end = next((j for j in range(k + 1, len(lines)) if RULE.match(lines[j])), None)
            if end is not None and end + 2 < len(lines) and DOTS.match(lines[end + 2]):
                starts.append((k, end))
    summary = next((k for k, line in enumerate(lines) if SUMMARY.match(line)), len(lines))
    cases = []
    for n, (first, name_end) in enumerate(starts):
        last = starts[n + 1][0] if n + 1 < len(starts) else summary
        cases.append((" ".join(line.strip() for line in lines[first + 1:name_end]), last - first))
    return cases


def measure(release, stage):
    program = release / f"build/student/bin/raystep_stage{stage}_tests"
    result = subprocess.run([str(program)], cwd=release, capture_output=True, text=True)
    lines = (result.stdout + result.stderr).splitlines()
    cases = test_cases(lines)
    name, most = max(cases, key=lambda case: case[1]) if cases else ("", 0)
    return len(lines), len(cases), most, name


def build(release, stages):
    run(["cmake", "--build", "--preset", "student", "--target"] +
        [f"raystep_stage{n}_tests" for n in stages], release)


def sync(source, target):
    """Makes `target` hold `source`'s files, rewriting only those that differ: ninja then rebuilds
    only what the case changed."""
    for path in source.rglob("*"):
        copy = target / path.relative_to(source)
        if path.is_dir():
            copy.mkdir(parents=True, exist_ok=True)
        elif not copy.exists() or copy.read_bytes() != path.read_bytes():
            shutil.copyfile(path, copy)


def stage_folder(stage):
    return next((CORPUS / "model/stages").glob(f"{stage}_*")).name


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("cases", nargs="*", default=DEFAULT_CASES)
    parser.add_argument("--release", type=pathlib.Path, default=ROOT / "build/failure-output")
    parser.add_argument("--grader", default=str(ROOT / "build/release/bin/raystep-grade"))
    parser.add_argument("--fresh", action="store_true", help="write the release anew")
    parser.add_argument("--own-stage", action="store_true",
                        help="a mutant's stage's test program only, not the later stages'")
    args = parser.parse_args()
    release = args.release.resolve()
    mutants = sorted(path.stem for path in (CORPUS / "mutants").glob("*.diff"))
    cases = [name for case in args.cases for name in (mutants if case == "all-mutants" else [case])]

    # The release, configured as its README says
    if args.fresh and release.exists():
        shutil.rmtree(release)
    if not release.exists():
        run([args.grader, "release", str(release)], ROOT)
    run(["cmake", "--preset", "student"], release)
    stubs = release / "stubs"
    if not stubs.exists():
        shutil.copytree(release / "stages", stubs)

    print("| case | test program | lines | failing test cases | most lines in one test case |"
          " that test case |")
    print("|---|---|---|---|---|---|")
    for case in cases:
        # Every stage's stubs, or the model with the mutant applied to its stage
        case_stages = release / "build/case-stages"
        if case_stages.exists():
            shutil.rmtree(case_stages)
        shutil.copytree(stubs, case_stages)
        if case == "stubs":
            stages = list(STAGES)
        else:
            diff = pathlib.Path(case).resolve() if case.endswith(".diff") else (
                CORPUS / "mutants" / f"{case}.diff")
            stage = 1 if case == "model" else int(diff.name.split("-")[0])
            for n in STAGES:
                folder = stage_folder(n)
                shutil.copytree(CORPUS / "model/stages" / folder, case_stages / folder,
                                dirs_exist_ok=True)
            if case != "model":
                run(["git", "apply", "-p2", str(diff)], case_stages)
            stages = [n for n in STAGES if n == stage or (n > stage and not args.own_stage)]
        sync(case_stages, release / "stages")
        build(release, stages)
        for n in stages:
            lines, failing, most, name = measure(release, n)
            if case not in ("stubs", "model") and failing == 0:
                continue
            name = name.replace("|", "\\|")
            print(f"| {case} | stage {n} | {lines:,} | {failing} | {most} | {name} |")
            sys.stdout.flush()
    sync(stubs, release / "stages")


if __name__ == "__main__":
    main()
