#!/usr/bin/env python3
"""A student release's public tests, judged one by one on any platform.

    scripts/check-public-tests.py stubs PRESET [--junit FILE | --per-program]
    scripts/check-public-tests.py written PRESET [--junit FILE] [--same-tests-as FILE]
    scripts/check-public-tests.py written PRESET --per-program

Run from the root of a built student release: runs `ctest --preset PRESET`, asks it for a JUnit
report (FILE, by default public-tests-MODE.xml in the current folder) and judges each test in it.
With --per-program, it asks ctest only for its list of tests, runs each test program once for all
of its tests with Catch2's XML reporter, and judges each test the list names by its test case in
that report: for Wine, where ctest's one process per test case costs seconds each.

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
import json
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


def read_programs(preset: str):
    """[(program command, working folder, [(ctest name, Catch2 test case name)])]: ctest's tests
    grouped by the program that runs them. A test's command is an emulator's, if any (wine), the
    program, which lies in the build folder, the test case's name as catch_discover_tests escapes
    it (a backslash before , ; [ and ]), then any arguments the program's tests share."""
    listed = subprocess.run(["ctest", "--preset", preset, "--show-only=json-v1"],
                            capture_output=True, text=True, check=True)
    here = pathlib.Path.cwd().resolve()
    programs = {}
    for test in json.loads(listed.stdout)["tests"]:
        command = test["command"]
        at = next(k for k, part in enumerate(command) if pathlib.Path(part).is_file()
                  and pathlib.Path(part).resolve().is_relative_to(here))
        folder = next((p["value"] for p in test.get("properties", [])
                       if p["name"] == "WORKING_DIRECTORY"), str(here))
        # The program with the arguments after the test case's name, which its tests share.
        key = (tuple(command[:at + 1] + command[at + 2:]), folder)
        case_name = re.sub(r"\\(.)", r"\1", command[at + 1])
        programs.setdefault(key, []).append((test["name"], case_name))
    return [(list(command), folder, tests) for (command, folder), tests in programs.items()]


def run_per_program(preset: str):
    """[(name, status, output)] as read_report gives them, each program run once: "run" for a test
    case whose OverallResult succeeded, "fail" for one that did not, "notrun" for one the program's
    report lacks, the output being the test case's text. A program that crashed (no readable
    report, or Catch2's FatalErrorCondition) fails its every test with the program's last lines."""
    cases = []
    for command, folder, tests in read_programs(preset):
        run = subprocess.run(command + ["--reporter", "xml"], cwd=folder, capture_output=True,
                             text=True, errors="replace")
        start = run.stdout.find("<?xml")
        try:
            report = ElementTree.fromstring(run.stdout[start:]) if start >= 0 else None
        except ElementTree.ParseError:
            report = None
        if report is None or report.find(".//FatalErrorCondition") is not None:
            # The program's last lines once, under its first test.
            first = tests[0][0]
            cases.append((first, "fail", "fatal error condition: the program crashed; its last "
                          "lines:\n" + "\n".join((run.stdout + run.stderr).splitlines()[-12:])))
            cases.extend((name, "fail", f"fatal error condition: the program crashed (under {first})")
                         for name, _ in tests[1:])
            continue
        by_name = {case.get("name"): case for case in report.iter("TestCase")}
        for name, case_name in tests:
            case = by_name.get(case_name)
            if case is None:
                cases.append((name, "notrun", f"not in {command[-1]}'s report"))
                continue
            result = case.find("OverallResult")
            passed = result is not None and result.get("success") == "true"
            # A finished report, so the console report's closing line, which stub_problem asks for.
            text = (line.strip() for line in "".join(case.itertext()).splitlines())
            output = "\n".join(line for line in text if line)
            output += "\ntest cases: (the program's XML report)"
            cases.append((name, "run" if passed else "fail", output))
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
    parser.add_argument("--per-program", action="store_true",
                        help="run each test program once, not one process per test case")
    arguments = parser.parse_args()
    if arguments.per_program and (arguments.junit or arguments.same_tests_as):
        parser.error("--per-program writes no JUnit report: no --junit or --same-tests-as")
    if arguments.per_program:
        cases = run_per_program(arguments.preset)
        # ctest's exit codes, as the check below asks for them.
        failed = any(status != "run" for _, status, _ in cases)
        run = subprocess.CompletedProcess([], 8 if failed else 0)
    else:
        junit = (arguments.junit or pathlib.Path(f"public-tests-{arguments.mode}.xml")).resolve()
        junit.unlink(missing_ok=True)
        # ctest exits 8 when a test fails: the stubs' run must, the written stages' must not.
        run = subprocess.run(["ctest", "--preset", arguments.preset, "--output-junit", str(junit)],
                             capture_output=True, text=True)
        if not junit.is_file():
            print(f"FAIL ctest --preset {arguments.preset} wrote no report "
                  f"(exit {run.returncode}):")
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
