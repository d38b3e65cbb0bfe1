#!/usr/bin/env python3
"""Names in anonymous namespaces, checked for twins: the unity builds (the student preset's, and
scripts/test-all.sh's sanitizer build) compile several files of a target as one, so two files of
base/, renderer/, app/ or the sandbox that each define a helper `kUp` or `ray` in `namespace {`
compile until a new file moves them into the same unity file, and then fail far from the change.
A unity file holds files of one target, and a target's files are those of a folder, so a name
must be unique within each folder of those layers. The stages' files compile one by one
(cmake/RaystepCompileOptions.cmake) and are not checked.

    scripts/check-unity-names.py [ROOT]

A name is a twin when two files of the same folder give it in an anonymous namespace, overloads
included, unless both are the same alias (`using Kind = ProbeAnswer::Kind;`). Prints each twin
with the files and lines that define it and exits 1; exits 0 when there is none."""

import collections
import pathlib
import re
import sys

# The layers built as unity files; each of their folders is a unit within which a name must be
# unique, and the sandbox's tests, which sit among the grader's, are one more.
LAYERS = ("base/", "renderer/", "app/", "grader/sandbox/")
SANDBOX_TESTS = "grader/tests/sandbox_"
ALIAS = re.compile(r"^(?:using|namespace)\s+(\w+)\s*=\s*(.+);")
TYPE = re.compile(r"^(?:struct|class|enum(?:\s+class)?|union)\s+(\w+)")
# A declaration's name: the last identifier before its first (, =, {, [ or ;.
DECLARED = re.compile(r"^[^(={\[;]*?\b(\w+)\s*(?:\(|=|\{|\[|;)")
NOT_NAMES = {"operator", "static_assert", "TEST_CASE", "TEMPLATE_TEST_CASE"}


def names_in(source: pathlib.Path):
    """Each (name, alias target or None, line number) that `source` defines at the top of an
    anonymous namespace, as clang-format writes it: from column 0, up to `}  // namespace`."""
    inside = False
    lines = source.read_text(encoding="utf-8", errors="replace").splitlines()
    for number, line in enumerate(lines, start=1):
        if line.startswith("namespace {"):
            inside = True
        elif line.startswith("}  // namespace"):
            inside = False
        elif inside and line[:1].isalpha() and not line.startswith("template"):
            if line.startswith("using ") and "=" not in line:
                continue  # using a::b; brings a name in, it defines none
            alias = ALIAS.match(line)
            if alias:
                yield alias.group(1), alias.group(2).strip(), number
                continue
            declared = TYPE.match(line) or DECLARED.match(line)
            if declared and declared.group(1) not in NOT_NAMES:
                yield declared.group(1), None, number


def units_of(root: pathlib.Path):
    """Each unity-built folder, by the name it is shown with, and its .cpp files."""
    units = collections.defaultdict(list)
    for source in sorted(root.rglob("*.cpp")):
        shown = source.relative_to(root).as_posix()
        if shown.startswith(LAYERS):
            units[shown.rsplit("/", 1)[0] + "/"].append(source)
        elif shown.startswith(SANDBOX_TESTS):
            units[SANDBOX_TESTS + "*"].append(source)
    return units


def twins_in(root: pathlib.Path, sources):
    defined = collections.defaultdict(list)  # name -> [(file, line, alias target)]
    for source in sources:
        for name, target, number in names_in(source):
            defined[name].append((source.relative_to(root).as_posix(), number, target))
    for name, places in sorted(defined.items()):
        files = {shown for shown, _, _ in places}
        targets = {target for _, _, target in places}
        same_alias = None not in targets and len(targets) == 1
        if len(files) > 1 and not same_alias:
            yield name, places

def main() -> int:
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".").resolve()
    units = units_of(root)
    checked = sum(len(sources) for sources in units.values())
    problems = []
    for unit, sources in units.items():
        for name, places in twins_in(root, sources):
            where = ", ".join(f"{shown}:{number}" for shown, number, _ in places)
            problems.append(f"{unit}: `{name}` in anonymous namespaces of {where}")
    if not checked:
        print(f"no source files under {root}: the check would prove nothing", file=sys.stderr)
        return 1
    if problems:
        print("names that two files of a unity-built folder define in anonymous namespaces "
              "(rename one, or share it through a header):", file=sys.stderr)
        print("\n".join(problems), file=sys.stderr)
        return 1
    print(f"{checked} files: no name twice in the anonymous namespaces of a unity-built folder")
    return 0


if __name__ == "__main__":
    sys.exit(main())
