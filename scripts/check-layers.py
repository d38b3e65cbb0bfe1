#!/usr/bin/env python3
"""The layers of ARCHITECTURE.md, checked on every #include: a file may include its own layer and
the layers below it, never one above. A file's layer is its top folder, but for grading/, whose
stage folders hold both sides: the calls, their JSON and the judges (*_calls, *_json, *_judges) are
app/'s, which a student release holds; the rest is grader/'s. CGAL is stage 3's exact oracle's
alone (grading/3_intersect/exact_kernel.h and the oracle's tests) and Embree the bench baseline's
(studies/structures/embree/): students build neither.

    scripts/check-layers.py [ROOT]

Prints each include that crosses a layer the wrong way as file:line and exits 1; exits 0 when
there is none."""

import pathlib
import re
import sys

# Each layer and the layers its files may include, bottom up.
ALLOWED = {
    "base": {"base"},
    "stages": {"base", "stages"},
    "solutions": {"base", "stages", "solutions"},
    "renderer": {"base", "stages", "renderer"},
    "app": {"base", "stages", "renderer", "app"},
    "studies": {"base", "stages", "solutions", "renderer", "app", "studies"},
    "grader": {"base", "stages", "solutions", "renderer", "app", "studies", "grader"},
}
# The files of grading/ that a student release holds (grader/grade/release.cpp says the same).
SHIPPED_GRADING = re.compile(r"^grading/[^/]+/[^/]+_(calls|json|judges)\.(h|cpp)$")
INCLUDE = re.compile(r'^\s*#\s*include\s*["<]([^">]+)[">]')
# Outside libraries that only some folders may include: (include prefix, folders, why).
CONFINED = [
    ("CGAL/", ("grading/3_intersect/exact_kernel.h", "grading/3_intersect/tests/"),
     "CGAL belongs to stage 3's exact oracle (grading/3_intersect/exact_kernel.h) and its tests"),
    ("embree", ("studies/structures/embree/",), "Embree belongs to studies/structures/embree/"),
]


def layer_of(shown: str) -> str:
    layer = shown.split("/")[0]
    if layer == "grading":
        return "app" if SHIPPED_GRADING.match(shown) else "grader"
    return layer


def problems_in(root: pathlib.Path, source: pathlib.Path):
    shown = source.relative_to(root).as_posix()
    layer = layer_of(shown)
    lines = source.read_text(encoding="utf-8", errors="replace").splitlines()
    for number, line in enumerate(lines, start=1):
        match = INCLUDE.match(line)
        if not match:
            continue
        included = match.group(1)
        top = layer_of(included)
        if top in ALLOWED and top not in ALLOWED[layer]:
            yield (f"{shown}:{number}: {layer}/ includes {included}, a layer above it "
                   f"(allowed: {', '.join(sorted(ALLOWED[layer]))})")
        for prefix, folders, why in CONFINED:
            if included.startswith(prefix) and not shown.startswith(folders):
                yield f"{shown}:{number}: includes {included}: {why}"


def main() -> int:
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".").resolve()
    sources = [path for top in (*ALLOWED, "grading") for path in sorted((root / top).rglob("*"))
               if path.suffix in (".h", ".cpp") and path.is_file()]
    if not sources:
        print(f"no source files under {root}: the check would prove nothing", file=sys.stderr)
        return 1
    problems = [problem for source in sources for problem in problems_in(root, source)]
    if problems:
        print("includes that cross a layer the wrong way (ARCHITECTURE.md, \"Layers\"):",
              file=sys.stderr)
        print("\n".join(problems), file=sys.stderr)
        return 1
    print(f"{len(sources)} files include only their own layer and those below it")
    return 0


if __name__ == "__main__":
    sys.exit(main())
