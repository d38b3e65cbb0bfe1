#!/usr/bin/env python3
"""Every C++ file as clang-format writes it (.clang-format) and within 100 columns.

    scripts/check-format.py [ROOT]        check; exit 1 naming each file that differs
    scripts/check-format.py --fix [ROOT]  format every file in place

The format is pinned to Debian 12's clang-format 14: another version formats some constructs
differently, so with another version, or none, the check is skipped (exit 77, ctest's skip code)
and says why. The grader's corpus of submissions (grader/tests/submissions/) is left as written:
its files are students' code as students write it, and its mutants are diffs against them."""

import pathlib
import re
import shutil
import subprocess
import sys

PINNED_MAJOR = 14
COLUMNS = 100
FOLDERS = ("base", "stages", "solutions", "renderer", "app", "studies", "grader")
LEFT_AS_WRITTEN = "grader/tests/submissions/"


def clang_format() -> str | None:
    for name in (f"clang-format-{PINNED_MAJOR}", "clang-format"):
        program = shutil.which(name)
        if not program:
            continue
        version = subprocess.run([program, "--version"], capture_output=True, text=True).stdout
        if re.search(rf"clang-format version {PINNED_MAJOR}\.", version):
            return program
    return None


def main() -> int:
    arguments = sys.argv[1:]
    fix = "--fix" in arguments
    arguments = [a for a in arguments if a != "--fix"]
    root = pathlib.Path(arguments[0] if arguments else ".").resolve()
    program = clang_format()
    if not program:
        print(f"clang-format {PINNED_MAJOR} was not found (Debian 12: clang-format): "
              "the format is not checked")
        return 77
    sources = [path for folder in FOLDERS for path in sorted((root / folder).rglob("*"))
               if path.suffix in (".h", ".cpp") and path.is_file()
               and not path.relative_to(root).as_posix().startswith(LEFT_AS_WRITTEN)]
    if not sources:
        print(f"no source files under {root}: the check would prove nothing", file=sys.stderr)
        return 1
    if fix:
        subprocess.run([program, "-i", "--style=file", *map(str, sources)], check=True)
    # One clang-format for every file (a process each took a minute and a half): --dry-run names
    # each place it would change, file:line:column, and the first of each file is reported.
    run = subprocess.run([program, "--style=file", "--dry-run", *map(str, sources)],
                         capture_output=True, text=True)
    unformatted = {}
    for match in re.finditer(r"^(.*?):(\d+):\d+: (?:warning|error): code should be clang-formatted",
                             run.stderr, re.MULTILINE):
        unformatted.setdefault(pathlib.Path(match[1]).resolve(), int(match[2]))
    if run.returncode != 0 and not unformatted:
        print(run.stderr, file=sys.stderr)
        return 1
    problems = []
    for source in sources:
        shown = source.relative_to(root).as_posix()
        text = source.read_text(encoding="utf-8")
        if source in unformatted:
            problems.append(f"{shown}:{unformatted[source]}: not as clang-format writes it")
        for number, line in enumerate(text.splitlines(), start=1):
            if len(line) > COLUMNS:
                problems.append(f"{shown}:{number}: {len(line)} columns, more than {COLUMNS}")
    if problems:
        print("\n".join(problems), file=sys.stderr)
        print(f"To fix: scripts/check-format.py --fix, then break the lines longer than {COLUMNS}.",
              file=sys.stderr)
        return 1
    print(f"{len(sources)} files formatted as .clang-format says, within {COLUMNS} columns")
    return 0


if __name__ == "__main__":
    sys.exit(main())
