#!/usr/bin/env python3
"""The public case files are made by raystep-oracle, and each says how on its second line. This
check makes each again, into a scratch folder, and fails unless the result is byte for byte the
committed file: when the oracle or a family changes, the files must be remade (the line says how).

    case_files_test.py ORACLE CASES SCRATCH
"""

import glob
import os
import shlex
import shutil
import subprocess
import sys

ORACLE, CASES, SCRATCH = sys.argv[1:4]
MADE_BY = "#   raystep-oracle cases "


def main():
    files = sorted(glob.glob(os.path.join(CASES, "*.cases")))
    if not files:
        print("no case files in %s" % CASES)
        return 1
    shutil.rmtree(SCRATCH, ignore_errors=True)
    stale = []
    for path in files:
        name = os.path.basename(path)
        with open(path, "rb") as file:
            committed = file.read()
        made_by = committed.split(b"\n")[1].decode()
        if not made_by.startswith(MADE_BY):
            print("%s:2: '%s' does not say how raystep-oracle made it ('%s...')"
                  % (path, made_by, MADE_BY))
            return 1
        as_written = made_by[len(MADE_BY):]
        arguments = [SCRATCH if word == "FOLDER" else word for word in shlex.split(as_written)]
        if subprocess.run([ORACLE, "cases", *arguments, "--threads", "2"],
                          stdout=subprocess.DEVNULL).returncode != 0:
            print("raystep-oracle failed to remake %s" % name)
            return 1
        with open(os.path.join(SCRATCH, name), "rb") as file:
            if file.read() != committed:
                stale.append("  %s: remake it with raystep-oracle cases %s"
                             % (name, as_written.replace("FOLDER", CASES)))
    if stale:
        print("case files that the oracle now decides differently:\n" + "\n".join(stale))
        return 1
    print("%d case files, each as the oracle makes it" % len(files))
    return 0


if __name__ == "__main__":
    sys.exit(main())
