#!/usr/bin/env python3
"""Names in anonymous namespaces, checked for twins within each target. A unity build (the
student preset's, scripts/test-all.sh's sanitizer build) compiles several files of a target as
one, so two files of a target that each define a helper `kUp` or `ray` in `namespace {` compile
until a new file moves them into the same unity file, and then fail far from the change: in a
student's build, or only in the sanitizer build, at the end of CI. Checked for every target a
unity build may join, whatever the batch size; the stages' files compile one by one and are left
out. CMake lists the targets' files at configure time (cmake/RaystepUnitySources.cmake).

    scripts/check-unity-names.py ROOT UNITY_SOURCES

UNITY_SOURCES has a line "TARGET<TAB>absolute path" per file. A name is a twin when two files of
one target give it in an anonymous namespace, overloads included, unless both are the same alias
(`using Kind = ProbeAnswer::Kind;`). Prints each twin with the files and lines that define it and
exits 1; exits 0 when there is none."""

import collections
import pathlib
import re
import sys

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


def targets_in(listing: pathlib.Path):
    """Each target of the listing CMake writes, and its files."""
    targets = collections.defaultdict(list)
    for line in listing.read_text(encoding="utf-8").splitlines():
        target, _, path = line.partition("\t")
        if path:
            targets[target].append(pathlib.Path(path))
    return targets


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
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    root = pathlib.Path(sys.argv[1]).resolve()
    targets = targets_in(pathlib.Path(sys.argv[2]))
    checked = sum(len(sources) for sources in targets.values())
    if not checked:
        print(f"no files listed in {sys.argv[2]}: the check would prove nothing", file=sys.stderr)
        return 1
    problems = []
    for target, sources in sorted(targets.items()):
        for name, places in twins_in(root, sources):
            where = ", ".join(f"{shown}:{number}" for shown, number, _ in places)
            problems.append(f"{target}: `{name}` in anonymous namespaces of {where}")
    if problems:
        print("names that two files of a target define in anonymous namespaces, which a unity "
              "build joins (rename one, or share it through a header):", file=sys.stderr)
        print("\n".join(problems), file=sys.stderr)
        return 1
    print(f"{checked} files of {len(targets)} targets: no name twice in the anonymous namespaces "
          "of a target")
    return 0


if __name__ == "__main__":
    sys.exit(main())
