#!/usr/bin/env python3
"""The student README's set-up commands are what the student platforms workflow runs.

    scripts/check-platform-steps.py README WORKFLOW

README (docs/student-README.md) has a block of commands for each platform, its fence naming the
platform after the language (```sh macos, ```powershell windows-vs). WORKFLOW
(.github/workflows/student-platforms.yml) has a matrix of platforms (`platform:` in its
`include:` list) and steps that run one command each (`run:`) for the platforms their `if:`
names. Each README block must be run, command for command and in the README's order, by steps of
the workflow whose `if:` holds for that platform; each platform of the matrix must have a README
block, and each README block a platform in the matrix. So a student types what the hosted runners
ran, word for word.

The `if:` expressions are read as far as this workflow writes them: matrix.platform compared with
== and != to quoted names, startsWith(matrix.platform, '...'), joined by || and &&. The workflow
is read without a YAML library (python3-yaml is not among the packages scripts/install-deps.sh
installs), one `- name:` or `- uses:` step at a time. Exits 0 when every block is run, 1
otherwise, naming each command that is not."""

import pathlib
import re
import sys

FENCE = re.compile(r"^```(\w*)(?:[ \t]+(\S+))?\s*$")
STEP = re.compile(r"^\s*- (name|uses): ?(.*)$")
FIELD = re.compile(r"^\s+(if|run|name): (.*)$")
MATRIX_PLATFORM = re.compile(r"^\s+platform: ([\w-]+)\s*$")


def readme_blocks(path: pathlib.Path):
    """[(platform, first line number, [commands])] for each block that names a platform."""
    blocks, block = [], None
    for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), start=1):
        fence = FENCE.match(line)
        if fence and block is None:
            block = (fence.group(2), number + 1, [])
            continue
        if line.startswith("```") and block is not None:
            if block[0] is not None:
                blocks.append(block)
            block = None
            continue
        command = line.split("  #")[0].strip()
        if block is not None and command:
            block[2].append(command)
    return blocks


def workflow_steps(path: pathlib.Path):
    """The matrix's platforms, and [(name, if, run)] for each step of the file, in order; run is
    None for a step that uses an action or runs a block of lines."""
    platforms, steps = [], []
    for line in path.read_text(encoding="utf-8").splitlines():
        platform = MATRIX_PLATFORM.match(line)
        if platform:
            platforms.append(platform.group(1))
            continue
        step = STEP.match(line)
        if step:
            steps.append({"name": step.group(2) if step.group(1) == "name" else "",
                          "if": None, "run": None})
            continue
        field = FIELD.match(line)
        if field and steps:
            key, value = field.group(1), field.group(2).strip()
            if key == "run" and value in ("|", ">", "|-", ">-"):
                value = None
            steps[-1][key] = value
    return platforms, steps


def runs_on(condition, platform: str) -> bool:
    """Whether a step's `if:` holds for matrix.platform == platform (no `if:`: always)."""
    if condition is None:
        return True
    expression = condition.replace("${{", "").replace("}}", "")
    expression = re.sub(r"startsWith\(\s*matrix\.platform\s*,\s*'([\w-]+)'\s*\)",
                        lambda m: repr(platform.startswith(m.group(1))), expression)
    expression = re.sub(r"matrix\.platform\s*(==|!=)\s*'([\w-]+)'",
                        lambda m: repr((platform == m.group(2)) == (m.group(1) == "==")),
                        expression)
    expression = expression.replace("||", " or ").replace("&&", " and ")
    if not re.fullmatch(r"[\s()]*((True|False|or|and|not)[\s()]*)+", expression):
        raise ValueError(f"an `if:` this check cannot read: {condition}")
    return eval(expression)  # only True, False, and, or, not and parentheses remain


def main() -> int:
    if len(sys.argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    readme, workflow = pathlib.Path(sys.argv[1]), pathlib.Path(sys.argv[2])
    platforms, steps = workflow_steps(workflow)
    blocks = readme_blocks(readme)
    failures = 0
    for platform, line, commands in blocks:
        where = f"{readme}:{line}"
        if platform not in platforms:
            print(f"FAIL {where}: a block for '{platform}', which is not a platform of "
                  f"{workflow}'s matrix ({', '.join(platforms)})")
            failures += 1
            continue
        # Each command in turn, from the step after the one that ran the command before it.
        next_step, names = 0, []
        for position, command in enumerate(commands):
            found = next((index for index in range(next_step, len(steps))
                          if steps[index]["run"] == command
                          and runs_on(steps[index]["if"], platform)), None)
            if found is None:
                after = f" after `{commands[position - 1]}`" if position else ""
                print(f"FAIL {where}: `{command}` is not run by a step of {workflow} for "
                      f"{platform}{after}")
                failures += 1
                break
            names.append(steps[found]["name"] or steps[found]["run"])
            next_step = found + 1
        else:
            print(f"ok   {where}: {platform}'s {len(commands)} commands, run in order by the "
                  f"steps {', '.join(repr(name) for name in names)}")
    for platform in platforms:
        if platform not in {block[0] for block in blocks}:
            print(f"FAIL {workflow}: the platform {platform} has no block of commands in {readme}")
            failures += 1
    if not blocks:
        print(f"FAIL {readme}: no block of commands names a platform")
        failures += 1
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
