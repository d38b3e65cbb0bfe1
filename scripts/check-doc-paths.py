#!/usr/bin/env python3
"""Every repository path a document names exists: a newcomer who follows one finds the file.

    scripts/check-doc-paths.py ROOT FILE...

A path is a span in backquotes with a slash, no space and no leading slash (`renderer/render_plan.h`, `grader/`,
`stages/*/manifest.txt`, where `*` must match something), or a top-level file in backquotes
(`README.md`), or the target of a relative Markdown link. Spans with `<` or `>` are placeholders
(`build/<preset>/bin/`), paths under what ROOT/.gitignore anchors (`out/`) are made by running
something, and fenced code blocks are commands: all three are left alone. Paths are taken from
ROOT, links from the document's folder. Prints each missing path as file:line and exits 1; exits
0 when every path exists."""

import pathlib
import re
import sys

SPAN = re.compile(r"`([^`\s]+)`")
LINK = re.compile(r"\]\(([^)\s]+)\)")


def made_by_running(root: pathlib.Path):
    ignore = root / ".gitignore"
    lines = ignore.read_text(encoding="utf-8").splitlines() if ignore.exists() else []
    return tuple(line.strip("/") + "/" for line in lines if line.startswith("/"))


def missing_in(root: pathlib.Path, document: pathlib.Path):
    top_files = {path.name for path in root.iterdir() if path.is_file()}
    generated = made_by_running(root)
    in_fence = False
    lines = document.read_text(encoding="utf-8").splitlines()
    for number, line in enumerate(lines, start=1):
        if line.lstrip().startswith("```"):
            in_fence = not in_fence
            continue
        if in_fence:
            continue
        for span in SPAN.findall(line):
            if "<" in span or ">" in span or "://" in span or span.startswith("/"):
                continue
            if (span + "/").startswith(generated):
                continue
            if "/" not in span and span not in top_files and not re.fullmatch(
                    r"[A-Z]+\.md", span):
                continue
            if not any(root.glob(span.rstrip("/"))):
                yield f"{document}:{number}: `{span}` does not exist under {root}"
        for target in LINK.findall(line):
            if "://" in target or target.startswith(("#", "mailto:")):
                continue
            relative = target.split("#")[0]
            if relative and not (document.parent / relative).exists():
                yield f"{document}:{number}: the link ({target}) leads nowhere"


def main() -> int:
    if len(sys.argv) < 3:
        print(__doc__, file=sys.stderr)
        return 2
    root = pathlib.Path(sys.argv[1]).resolve()
    problems = [problem for name in sys.argv[2:]
                for problem in missing_in(root, pathlib.Path(name))]
    if problems:
        print("\n".join(problems), file=sys.stderr)
        return 1
    print(f"every path in {', '.join(sys.argv[2:])} exists")
    return 0


if __name__ == "__main__":
    sys.exit(main())
