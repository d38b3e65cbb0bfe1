#!/usr/bin/env python3
"""Every command a student release's READMEs and handouts name works, as written, once the
stages are written.

    scripts/check-student-readme.py RELEASE MODEL_STAGES

RELEASE is a student release already built by its scripts/setup.sh. This plays the student who
has written every stage: it copies the files each stage's manifest.txt lists, and nothing else,
from MODEL_STAGES (a right submission's stages/ folder) into RELEASE, then runs each command of
the ```sh blocks of RELEASE/README.md, every stages/*/README.md and every docs/*.md (a line ending
in a backslash goes on on the next), then each command a stage's source or test file names in its
opening comment, in order, from RELEASE's root, and holds its exit code and output against what
the command promises (EXPECTED below). Last, as a student's `git status` would: the commands may
leave no file git lists but the stage files written. A command that no entry of EXPECTED knows
fails too, so that a new command cannot go unchecked.

A block for one platform names it after its language (```sh macos, ```powershell windows-vs;
PLATFORMS below). This check runs on Linux: it runs the linux blocks and skips every other
platform's, saying so command by command; the student platforms workflow runs those on their
systems (.github/workflows/student-platforms.yml in the instructor's repository). A block tagged
instructor (```sh instructor) holds commands that need the instructor's repository (the reference
build, the oracle, the bench), and so does every block of docs/lecturer.md, the lecturer's guide:
they are skipped and listed too. A tag it does not know fails, so that a misspelt one is never
skipped unseen. A command that only reads and tests (REREAD), named again on another page, is held
to its first run's result rather than run again: the stage tests are named on three pages each.
Prints one line per command with its time, and exits 1 when any command failed."""

import pathlib
import re
import shutil
import subprocess
import sys
import threading
import time

RAYSTEP = r"build/student/bin/raystep"

# (command pattern, exit codes, pattern its output must hold). A file the command names in the
# pattern's group "made" must exist after it. The first entry whose pattern matches the whole
# line applies.
EXPECTED = [
    (r"scripts/setup\.sh", {0}, r"Built: build/student/bin/raystep"),
    (r"scripts/test\.sh( [1-9][0-9]*)*", {0}, r"100% tests passed"),
    (r"ctest --preset student .*", {0}, r"100% tests passed"),
    (r"build/student/bin/raystep_stage[1-9][0-9]*_tests( .*)?", {0}, r"All tests passed"),
    (RAYSTEP + r" render .* -o (?P<made>\S+)", {0}, r"^wrote "),
    # Without -o, under out/, which git ignores: the file it names must be there.
    (RAYSTEP + r" render .*", {0}, r"^wrote (?P<made>out/\S+) "),
    (RAYSTEP + r" info .*", {0}, r"views"),
    # The page's server runs until stopped: it must say where the page is within TIMEOUT seconds,
    # and is stopped once it has.
    (RAYSTEP + r" view .*", {"timeout"}, r"open http://127\.0\.0\.1:\d+/"),
    (r"cmake --build --preset student", {0}, r""),
    (RAYSTEP + r" compare .*", {0}, r"^pass"),
    (RAYSTEP + r" trace .* --compare", {0}, r"^the traces are the same$"),
    # An example traces a pixel that shows something: a hit, then the view's value.
    (RAYSTEP + r" trace .*", {0}, r"^closest_hit: (?!miss)[\s\S]*^value: "),
    # A right triangle test that is not watertight lets some rays through shared edges (the
    # families' leaks), so a right stage 3 need not pass every case: exit 1, nothing a stub.
    (RAYSTEP + r" check --stage 3( .*)?", {0, 1}, r"^\d+ of \d+ checks passed[^;]*$"),
    # Every stage written: every public check passes, and the hidden ones are named.
    (RAYSTEP + r" grade( --stage [0-9])?", {0},
     r"^Hidden checks exist and are not run here[\s\S]*^Total: (\d+) / \1 points"),
    # Every stage written: the zip is made, and no function is left a stub to warn of.
    (RAYSTEP + r" submit", {0}, r"^wrote \S*submission\.zip \(\d+ files(?![\s\S]*warning)"),
]

FENCE = re.compile(r"^```(\w*)(?:[ \t]+(\S+))?\s*$")
# The tags a README block may carry after its language, and what the skip line calls them. This
# check runs the linux blocks and the blocks with no tag.
PLATFORMS = {
    "linux": "Linux",
    "macos": "macOS with Homebrew",
    "windows-vs": "Windows with vcpkg and Visual Studio's generator",
    "windows-ninja": "Windows with vcpkg and Ninja",
    "instructor": "the instructor's repository",
}
RUN_HERE = {None, "linux"}
LECTURER_GUIDE = pathlib.Path("docs/lecturer.md")
TIMEOUT = 20
# Commands that write nothing a later command reads and print the same each time: the tests. Named
# again, they are not run again.
REREAD = re.compile(r"scripts/test\.sh( .*)?|ctest --preset student .*|"
                    r"build/student/bin/raystep_stage[1-9][0-9]*_tests( .*)?")


def readme_commands(release: pathlib.Path):
    """(page, line number, command, tag) for each command of each ```sh block and of each block
    for a platform, the top README first; tag is None for a block for every platform."""
    pages = ([release / "README.md"] + sorted(release.glob("stages/*/README.md")) +
             sorted(release.glob("docs/*.md")))
    for page in pages:
        where = page.relative_to(release)
        block = None
        command, first = "", 0
        for number, line in enumerate(page.read_text(encoding="utf-8").splitlines(), start=1):
            fence = FENCE.match(line)
            if fence:
                block = None if block is not None else fence.groups()
                continue
            if block is None:
                continue
            language, tag = block
            if where == LECTURER_GUIDE:
                tag = "instructor"
            if language != "sh" and tag is None:
                continue
            text = line.split("  #")[0].strip()
            if not command and (not text or text.startswith("#")):
                continue
            if not command:
                first = number
            if text.endswith("\\"):
                command += text[:-1].strip() + " "
                continue
            yield where, first, command + text, tag
            command = ""


# A command in a source file's opening comment: in backquotes, a build's program or ctest.
SOURCE_COMMAND = re.compile(r"`((?:ctest|build/)[^`]*)`")


def source_comment_commands(release: pathlib.Path):
    """(file, line number, command, None) for each command the opening // comment of a stage's
    source and test files names: the first directions a student reads, for every platform."""
    for source in sorted(release.glob("stages/*/**/*.cpp")) + sorted(release.glob("stages/*/*.h")):
        lines = source.read_text(encoding="utf-8").splitlines()
        for number, line in enumerate(lines, start=1):
            if not line.startswith("//"):
                break
            for command in SOURCE_COMMAND.findall(line):
                yield source.relative_to(release), number, command, None


def write_the_stages(release: pathlib.Path, model: pathlib.Path):
    """Copies the model's manifest files into the release: what a student's edits amount to."""
    copied = 0
    for manifest in sorted(release.glob("stages/*/manifest.txt")):
        stage = manifest.parent.name
        for entry in manifest.read_text(encoding="utf-8").splitlines():
            entry = entry.strip()
            if not entry or entry.startswith("#"):
                continue
            shutil.copyfile(model / stage / entry, manifest.parent / entry)
            copied += 1
    return copied


def run_until_printed(command: str, release: pathlib.Path, pattern: str):
    """Runs a command that serves until stopped: ("timeout", its output) once a line of it matches
    `pattern` or TIMEOUT seconds have passed, the command then stopped; (exit code, output) if it
    ended before."""
    server = subprocess.Popen(["bash", "-c", "exec " + command], cwd=release, text=True,
                              stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    output = []
    stop = threading.Timer(TIMEOUT, server.kill)
    stop.start()
    try:
        for line in server.stdout:
            output.append(line)
            if re.search(pattern, line):
                break
    finally:
        stop.cancel()
        server.kill()
        returncode = server.wait()
        server.stdout.close()
    text = "".join(output)
    return ("timeout" if returncode < 0 else returncode), text


def expectation(command: str):
    for pattern, code, output in EXPECTED:
        match = re.fullmatch(pattern, command)
        if match:
            return match, code, output
    return None


def main() -> int:
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    release, model = pathlib.Path(sys.argv[1]).resolve(), pathlib.Path(sys.argv[2]).resolve()
    git = ["git", "-C", str(release), "-c", "user.name=raystep",
           "-c", "user.email=raystep@localhost"]
    if not (release / ".git").exists():
        subprocess.run(git + ["init", "-q"], check=True)
        subprocess.run(git + ["add", "-A"], check=True)
        subprocess.run(git + ["commit", "-q", "-m", "the release"], check=True)
    print(f"wrote {write_the_stages(release, model)} stage files from {model}")
    failures = 0
    results = {}  # REREAD command: (exit code, output, where it was first run)
    commands = list(readme_commands(release)) + list(source_comment_commands(release))
    for readme, number, command, tag in commands:
        where = f"{readme}:{number}"
        if tag not in RUN_HERE:
            if tag not in PLATFORMS:
                print(f"FAIL {where}: `{command}` is in a block tagged '{tag}', which this check "
                      f"does not know ({', '.join(PLATFORMS)})")
                failures += 1
            else:
                print(f"skip {where}: `{command}`, for {PLATFORMS[tag]}: not run here")
            continue
        expected = expectation(command)
        if expected is None:
            print(f"FAIL {where}: no check knows what `{command}` should do; add it to EXPECTED")
            failures += 1
            continue
        match, code, output_pattern = expected
        start = time.monotonic()
        first_run = results.get(command)
        if first_run:
            returncode, output, _ = first_run
        elif "timeout" in code:
            returncode, output = run_until_printed(command, release, output_pattern)
        else:
            run = subprocess.run(["bash", "-c", command], cwd=release, capture_output=True,
                                 text=True)
            returncode, output = run.returncode, run.stdout + run.stderr
            if REREAD.fullmatch(command):
                results[command] = (returncode, output, where)
        seconds = time.monotonic() - start
        printed = re.search(output_pattern, output, re.MULTILINE)
        made = match.groupdict().get("made") or (printed.groupdict().get("made") if printed else None)
        problems = []
        if returncode not in code:
            problems.append(f"exit {returncode}, expected {' or '.join(map(str, code))}")
        if not printed:
            problems.append(f"no line matching {output_pattern!r}")
        if made and not (release / made).is_file():
            problems.append(f"{made} was not written")
        if problems:
            print(f"FAIL {where}: `{command}`: {'; '.join(problems)}; it printed:")
            print("\n".join("  " + line for line in output.splitlines()[-40:]))
            failures += 1
        elif first_run:
            print(f"ok   {where}: `{command}` (as run for {first_run[2]})")
        else:
            print(f"ok   {where}: `{command}` ({seconds:.1f} s)")
    status = subprocess.run(git + ["status", "--porcelain", "--untracked-files=all"],
                            capture_output=True, text=True, check=True).stdout.splitlines()
    left = [line for line in status if not line[3:].startswith("stages/")]
    if left:
        print("FAIL the commands left files that git status lists (.gitignore):")
        print("\n".join("  " + line for line in left[:20]))
        failures += 1
    else:
        print("ok   git status lists nothing but the stage files written")
    if failures:
        print(f"{failures} README command(s) did not do what they promise")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
