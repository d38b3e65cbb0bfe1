#!/usr/bin/env python3
"""Measures the false-fail rate of stage 8's checks: grades stage 8 of the corpus's model and of
each stage-8 alternative (grader/tests/submissions/alternatives/8-*.diff) at many statistical
seeds (`raystep-grade submission --seed S`) and counts, per check, the seeds at which a right
submission lost points. With --mutants, grades each stage-8 mutant the same way and counts the
seeds at which it lost points in stage 8, which should be all of them.

    scripts/measure-stage8-checks.py [--seeds 100] [--first 1] [--jobs 2] [--mutants]
        [--grader build/release/bin/raystep-grade]

Prints a Markdown table for docs/measurements/stage8-checks.md.
"""

import argparse
import collections
import concurrent.futures
import json
import pathlib
import shutil
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent
CORPUS = ROOT / "grader/tests/submissions"


def submission(entry, folder):
    """The model's stage-8 files, with the entry's diff applied unless it is the model."""
    stages = folder / "sub" / "stages"
    stages.mkdir(parents=True)
    shutil.copytree(CORPUS / "model/stages/8_sampling", stages / "8_sampling")
    if entry is not None:
        subprocess.run(["git", "apply", "-p1", str(entry)], cwd=folder / "sub", check=True)
    return folder / "sub"


def grade(grader, sub, seed, output):
    """Each stage-8 check's (score, max_score) at this seed."""
    subprocess.run([str(grader), "submission", str(sub), "--stage", "8", "--no-speed",
                    "--jobs", "1", "--seed", str(seed), "-o", str(output)],
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False)
    report = json.loads((output / "instructor/report.json").read_text())
    return {c["id"]: (c["score"], c["max_score"]) for c in report["checks"] if c["max_score"] > 0}


def measure(grader, entry, seeds, work):
    name = "model" if entry is None else entry.stem
    folder = work / name
    sub = submission(entry, folder)
    lost = collections.Counter()
    stage_lost = 0
    for seed in seeds:
        scores = grade(grader, sub, seed, folder / f"report-{seed}")
        shutil.rmtree(folder / f"report-{seed}", ignore_errors=True)
        for check, (score, maximum) in scores.items():
            if score < maximum:
                lost[check] += 1
        if sum(s for s, _ in scores.values()) < sum(m for _, m in scores.values()):
            stage_lost += 1
    return name, lost, stage_lost, sorted(scores)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--seeds", type=int, default=100)
    parser.add_argument("--first", type=int, default=1)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--mutants", action="store_true")
    parser.add_argument("--grader", default=str(ROOT / "build/release/bin/raystep-grade"))
    args = parser.parse_args()

    folder = "mutants" if args.mutants else "alternatives"
    entries = sorted((CORPUS / folder).glob("8-*.diff"))
    if not args.mutants:
        entries = [None] + entries
    seeds = range(args.first, args.first + args.seeds)
    with tempfile.TemporaryDirectory() as work_text:
        work = pathlib.Path(work_text)
        with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
            results = list(pool.map(lambda e: measure(args.grader, e, seeds, work), entries))

    checks = results[0][3]
    print(f"Seeds {args.first} to {args.first + args.seeds - 1}: the seeds at which each entry "
          f"lost points, per check and in stage 8 as a whole.\n")
    print("| entry | " + " | ".join(c.removeprefix("stage8.") for c in checks) + " | stage 8 |")
    print("|---" * (len(checks) + 2) + "|")
    for name, lost, stage_lost, _ in results:
        print(f"| {name} | " + " | ".join(str(lost[c]) for c in checks) +
              f" | {stage_lost} of {args.seeds} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
