#!/usr/bin/env python3
"""Measures how stage 4's timed walk separates right walks from wrong ones, run after run: grades
the corpus's model and the stage-4 entries whose walk the time decides, each on its structure's
oracle check alone, `--runs` times, each in a grader of its own (the walk is measured once per
grader), and prints each run's ratios: the walk through 768 walls against one wall, and against
the reference's (grading/4_accel/stage4_work.cpp); and the processor time its timed runs took in
all, which kWalkBudgetSeconds bounds.

    scripts/measure-stage4-walks.py [--runs 10] [--grader build/release/bin/raystep-grade]

Prints a Markdown table for docs/measurements/stage4-work.md, "The walk's time".
"""

import argparse
import json
import pathlib
import shutil
import subprocess
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent
CORPUS = ROOT / "grader/tests/submissions"
# Each entry, the check that times its walk, and whether the walk is right.
ENTRIES = [
    ("model", "bvh_sah", True),
    ("model", "grid", True),
    ("alternatives/4-bvh-8-bins-leaves-of-2.diff", "bvh_sah", True),
    ("alternatives/4-grid-dda-adds-t-delta.diff", "grid", True),
    ("mutants/4-bvh-never-lowers-search-limit.diff", "bvh_sah", False),
    ("mutants/4-bvh-never-lowers-search-limit-slows-small-scenes.diff", "bvh_sah", False),
    ("mutants/4-bvh-left-child-first.diff", "bvh_sah", False),
    ("mutants/4-grid-walks-to-the-end.diff", "grid", False),
    ("mutants/4-bvh-brute-force-remembering-answers.diff", "bvh_sah", False),
    ("mutants/4-bvh-sorts-every-box-per-ray.diff", "bvh_sah", False),
    ("mutants/4-bvh-brute-force-burns-processor-in-runs-of-no-passes.diff", "bvh_sah", False),
]


def submission(entry, folder):
    """The model's stages/4_accel with the entry's diff applied, in `folder`."""
    shutil.copytree(CORPUS / "model/stages/4_accel", folder / "stages/4_accel")
    if entry != "model":
        subprocess.run(["git", "apply", "-p1", str(CORPUS / entry)], cwd=folder, check=True)
    return folder


def grade(grader, entry, check, scratch):
    folder = submission(entry, scratch / "submission")
    output = scratch / "report"
    subprocess.run([grader, "submission", str(folder), "-o", str(output), "--jobs", "1",
                    "--no-speed", "--check", "stage4.oracle." + check],
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False)
    report = json.loads((output / "instructor/report.json").read_text())
    measured = report["checks"][0]
    metrics = measured.get("metrics", {})
    depth = next((v for k, v in metrics.items() if "walls against 1" in k), float("nan"))
    reference = next((v for k, v in metrics.items() if "against the reference's" in k),
                     float("nan"))
    spent = next((v for k, v in metrics.items() if "CPU seconds in all" in k), float("nan"))
    return depth, reference, spent, measured["outcome"]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--runs", type=int, default=10)
    parser.add_argument("--grader", default=str(ROOT / "build/release/bin/raystep-grade"))
    arguments = parser.parse_args()
    print("| entry | check | right | walls against 1, per run | against the reference | "
          "timed runs' CPU seconds | outcomes |")
    print("|---|---|---|---|---|---|---|")
    for entry, check, right in ENTRIES:
        depths, references, spents, outcomes = [], [], [], []
        for _ in range(arguments.runs):
            with tempfile.TemporaryDirectory() as scratch:
                depth, reference, spent, outcome = grade(arguments.grader, entry, check,
                                                         pathlib.Path(scratch))
            depths.append(depth)
            references.append(reference)
            spents.append(spent)
            outcomes.append(outcome)
        name = pathlib.Path(entry).stem
        passed = sum(outcome == "passed" for outcome in outcomes)
        print(f"| {name} | {check} | {'yes' if right else 'no'} | "
              f"{min(depths):.2f} to {max(depths):.2f} | "
              f"{min(references):.2f} to {max(references):.2f} | "
              f"{min(spents):.1f} to {max(spents):.1f} | "
              f"{passed} of {len(outcomes)} passed |")


if __name__ == "__main__":
    main()
