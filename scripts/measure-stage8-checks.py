#!/usr/bin/env python3
"""Measures how often stage 8's checks fail: builds the stage-8 probe of the corpus's model and of
each stage-8 alternative (grader/tests/submissions/alternatives/8-*.diff) once, then runs the
statistical checks on it at many seeds (`raystep-grade seeds`), which counts, per check, the seeds
at which a right submission failed. With --mutants, does the same for each stage-8 mutant over
every stage-8 check, which should fail at every seed.

    scripts/measure-stage8-checks.py [--count 100] [--first 1] [--jobs 2] [--mutants]
        [--entries '8-jittered-*'] [--checks stage8.render.]
        [--grader build/release/bin/raystep-grade]

Prints one Markdown table per entry, for docs/measurements/stage8-checks.md.
"""

import argparse
import concurrent.futures
import pathlib
import shutil
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent
CORPUS = ROOT / "grader/tests/submissions"


def built_probe(grader, entry, folder):
    """The stage-8 probe of the model's files with the entry's diff applied (none: the model)."""
    stages = folder / "sub" / "stages"
    stages.mkdir(parents=True)
    shutil.copytree(CORPUS / "model/stages/8_sampling", stages / "8_sampling")
    if entry is not None:
        subprocess.run(["git", "apply", "-p1", str(entry)], cwd=folder / "sub", check=True)
    work = folder / "work"
    work.mkdir()
    subprocess.run([str(grader), "submission", str(folder / "sub"), "--stage", "8", "--no-speed",
                    "--jobs", "1", "--keep-work", "--work", str(work), "-o",
                    str(folder / "report")],
                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False)
    probes = list(work.glob("*/probes/stage8/probe"))
    if len(probes) != 1:
        raise RuntimeError(f"no stage-8 probe built for {entry or 'the model'} in {work}")
    return probes[0]


def sweep(grader, entry, args, work):
    name = "model" if entry is None else entry.stem
    folder = work / name
    probe = built_probe(grader, entry, folder)
    prefix = args.checks or ("stage8." if args.mutants else "stage8.statistics.")
    table = subprocess.run([str(grader), "seeds", str(probe), "--checks", prefix, "--first",
                            str(args.first), "--count", str(args.count)],
                           capture_output=True, text=True, check=True).stdout
    return name, table


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--count", type=int, default=100)
    parser.add_argument("--first", type=int, default=1)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--mutants", action="store_true")
    parser.add_argument("--entries", default="8-*",
                        help="the diffs whose name matches this pattern (default: 8-*; the model "
                        "is swept only with the default)")
    parser.add_argument("--checks", help="the checks whose id starts with this (default: "
                        "stage8.statistics., or stage8. with --mutants)")
    parser.add_argument("--grader", default=str(ROOT / "build/release/bin/raystep-grade"))
    args = parser.parse_args()

    folder = "mutants" if args.mutants else "alternatives"
    entries = sorted((CORPUS / folder).glob(args.entries + ".diff"))
    if not args.mutants and args.entries == "8-*":
        entries = [None] + entries
    with tempfile.TemporaryDirectory() as work_text:
        work = pathlib.Path(work_text)
        # The sandbox's user must reach the probes the grader builds in there.
        work.chmod(0o755)
        with concurrent.futures.ThreadPoolExecutor(args.jobs) as pool:
            results = list(pool.map(lambda e: sweep(args.grader, e, args, work), entries))
    for name, table in results:
        print(f"#### {name}\n\n{table}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
