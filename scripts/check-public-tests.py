#!/usr/bin/env python3
"""A student release's public tests, judged one by one on any platform.

    scripts/check-public-tests.py stubs PRESET [--junit FILE]
    scripts/check-public-tests.py written PRESET [--junit FILE] [--same-tests-as FILE]

Run from the root of a built student release: runs `ctest --preset PRESET`, asks it for a JUnit
report (FILE, by default public-tests-MODE.xml in the current folder) and judges each test in it.

    stubs    every stage a stub: every test must fail at a stub, its output naming the function
             and its handout ("stage 3: intersect_sphere is not implemented yet, see
             docs/stage3.md"), and none may crash: Catch2 must have finished its report ("test
             cases:" and no "fatal error condition", Catch2's words for a signal or a Windows
             exception).
    written  every stage written (the model submission's files copied in): every test must pass.
             With --same-tests-as, the tests must be the same ones the stubs' report names, so that
             no test went missing between the two builds.

The check of scripts/check-student-build.sh, made to run where bash and Catch2's XML reporter are
not at hand: the student platforms workflow (.github/workflows/student-platforms.yml) runs it on
Linux, macOS and Windows. Exits 0 when every test is as the mode says, 1 otherwise."""

import argparse
import pathlib
import re
import subprocess
import sys
import xml.etree.ElementTree as ElementTree

# Matched with every space taken out, of the output too: Catch2's console report wraps its lines at
# 80 columns, breaking the message at a space or after a slash ("see docs/\n  stage3.md").
STUB_MESSAGE = re.compile(r"stage[0-9]+:[A-Za-z_:]+isnotimplementedyet,seedocs/stage[0-9]+\.md")
# Catch2 2 and 3 both end their console report with "test cases: ..." (or "All tests passed"),
# also after a fatal signal, which they report as "... due to a fatal error condition: SIGSEGV".
FINISHED = re.compile(r"^(test cases:|All tests passed)", re.MULTILINE)
CRASHED = re.compile(r"fatal error condition")


def read_report(path: pathlib.Path):
    """[(name, status, output)] for each test case of a ctest JUnit report."""
    cases = []
    for case in ElementTree.parse(path).getroot().iter("testcase"):
        output = case.findtext("system-out") or ""
        cases.append((case.get("name"), case.get("status"), output))
    return cases


def stub_problem(status: str, output: str):
    if status != "fail":
        return "passed although every stage is a stub" if status == "run" else f"status {status}"
    if CRASHED.search(output) or not FINISHED.search(output):
        return "crashed, or stopped before Catch2 finished its report"
    if not STUB_MESSAGE.search(re.sub(r"\s+", "", output)):
        return "failed without a NotImplemented message"
    return None


def written_problem(status: str, output: str):
    if status == "run":
        return None
    if status == "fail":
        return "failed with every stage written"
    return f"status {status} (not run)"


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("mode", choices=["stubs", "written"])
    parser.add_argument("preset", help="the CMake test preset (student, student-vs)")
    parser.add_argument("--junit", type=pathlib.Path)
    parser.add_argument("--same-tests-as", type=pathlib.Path)
    arguments = parser.parse_args()
    junit = (arguments.junit or pathlib.Path(f"public-tests-{arguments.mode}.xml")).resolve()
    junit.unlink(missing_ok=True)

    # ctest exits 8 when a test fails: the stubs' run must, the written stages' must not.
    run = subprocess.run(["ctest", "--preset", arguments.preset, "--output-junit", str(junit)],
                         capture_output=True, text=True)
    if not junit.is_file():
        print(f"FAIL ctest --preset {arguments.preset} wrote no report (exit {run.returncode}):")
        print("\n".join("  " + line for line in (run.stdout + run.stderr).splitlines()[-30:]))
        return 1
    cases = read_report(junit)
    judge = stub_problem if arguments.mode == "stubs" else written_problem
    problems = []
    for name, status, output in cases:
        problem = judge(status, output)
        if problem:
            problems.append(f"  {name}: {problem}")
            problems.extend("    " + line for line in output.splitlines()[-12:])
    if not cases:
        problems.append("  ctest ran no test: the public tests were not built or not found")
    expected_exit = 8 if arguments.mode == "stubs" else 0
    if run.returncode != expected_exit and cases:
        problems.append(f"  ctest exited {run.returncode}, not {expected_exit}")
    if arguments.same_tests_as:
        before = {name for name, _, _ in read_report(arguments.same_tests_as)}
        now = {name for name, _, _ in cases}
        for name in sorted(before - now):
            problems.append(f"  {name}: ran on the stubs, missing now")
        for name in sorted(now - before):
            problems.append(f"  {name}: new, not run on the stubs")

    if problems:
        print(f"FAIL {arguments.mode}: {len(cases)} public tests, not all as they should be:")
        print("\n".join(problems))
        return 1
    if arguments.mode == "stubs":
        print(f"ok   stubs: all {len(cases)} public tests fail at a stub, with its message, "
              "and none crashed")
    else:
        print(f"ok   written: all {len(cases)} public tests pass")
    return 0


if __name__ == "__main__":
    sys.exit(main())
