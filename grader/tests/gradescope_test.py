#!/usr/bin/env python3
"""Gradescope, from the instructor's zip to a student's grade, as Gradescope runs it.

    gradescope_test.py ROOT WORK        (as root, like Gradescope)

  1. the autograder zip, made as docs/instructor.md says (make-autograder-zip.sh);
  2. unpacked into a fresh folder laid out as /autograder is (source/ the zip, setup.sh and
     run_autograder beside it, submission/, results/);
  3. setup.sh run there: it installs nothing that is installed already, builds raystep-grade and
     the reference probe from scratch, and closes the sources to the probes' user;
  4. that user (nobody) checked to read none of the repository: solutions/, the rubric, the
     grader's sources, the build, and scenes/ too (raystep-grade copies what probes read);
  5. run_autograder on the complete model submission (grader/tests/submissions/model: every stage,
     oracle and speed checks included), with bubblewrap hidden as Gradescope's container usually
     hides it, its whole process tree measured (measure_process_tree.py): peak memory within
     Gradescope's 768 MB, and time within its 10 minutes, both as run here and on half a processor
     (twice the processor time);
  6. results.json read back: every check there, each with its full points;
  7. a hostile stage 1 that takes 3 GiB of shared memory, graded and measured the same way: within
     768 MB, with a complete results.json that names the sandbox's rule it broke.
"""

import glob
import json
import os
import shutil
import subprocess
import sys
import time
import zipfile

MEMORY_LIMIT_MB = 768
TIME_LIMIT_SECONDS = 600
MEGABYTE = 1 << 20
HERE = os.path.dirname(os.path.abspath(__file__))


def fail(message):
    sys.exit("gradescope_test.py: " + message)


def run(name, log, command, env=None):
    """Runs COMMAND with its output in LOG; stops with the log's end if it fails."""
    with open(log, "wb") as output:
        status = subprocess.run(command, stdout=output, stderr=subprocess.STDOUT, env=env).returncode
    if status != 0:
        with open(log, "rb") as output:
            end = output.read()[-4000:].decode("utf-8", "replace")
        fail("%s exited with %d; the end of %s:\n%s" % (name, status, log, end))


def as_nobody_succeeds(*command):
    """Whether COMMAND succeeds as nobody, the probes' user."""
    return subprocess.run(["setpriv", "--reuid=65534", "--regid=65534", "--clear-groups",
                           *command], stdout=subprocess.DEVNULL,
                          stderr=subprocess.DEVNULL).returncode == 0


def check_closed_to_nobody(source):
    """4: nobody reads none of the repository, lists none of its folders."""
    secrets = [sorted(glob.glob(os.path.join(source, "solutions", "*", "*.cpp")))[0]]
    secrets += [os.path.join(source, path) for path in (
        "grader/rubric/rubric.json", "grader/grade/probe_builder.cpp",
        "grading/3_intersect/stage3_checks.cpp", "build/release/bin/raystep-probe-reference",
        "build/release/grader/probe-toolchain.json")]
    for secret in secrets:
        if not os.path.exists(secret):
            fail("%s is not there: the test checks the wrong files" % secret)
        if as_nobody_succeeds("head", "-c", "1", secret):
            fail("nobody, the probes' user, can read " + secret)
    for folder in (source, os.path.join(source, "solutions"),
                   os.path.join(source, "build/release/bin")):
        if as_nobody_succeeds("ls", folder):
            fail("nobody, the probes' user, can list " + folder)
    scene = os.path.join(source, "scenes/stage6/cornell-box.test")
    if as_nobody_succeeds("head", "-c", "1", scene):
        fail("nobody can read %s/scenes: the repository is not shut whole" % source)


def hide_bubblewrap(run_autograder):
    """Gradescope's container usually has no user namespaces, so the sandbox there runs probes with
    rlimits alone, and the modes setup.sh set are all that keeps them out of the sources. Where it
    can, the run here hides bubblewrap the same way: a private mount namespace with /dev/null over
    bwrap, which the sandbox then finds unusable. Returns the command and what it did."""
    copies = [os.path.join(folder, "bwrap") for folder in ("/usr/local/bin", "/usr/bin", "/bin")
              if os.path.exists(os.path.join(folder, "bwrap"))
              and not os.path.islink(os.path.join(folder, "bwrap"))]
    if not copies:
        return run_autograder, "bubblewrap is not installed: probes ran with rlimits alone, as on Gradescope"
    hide = "".join("mount --bind /dev/null %s && " % copy for copy in copies)
    unshare = ["unshare", "-m", "--propagation", "private", "sh", "-c"]
    if shutil.which("unshare") and subprocess.run(
            unshare + [hide + "true"], stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL).returncode == 0:
        return (unshare + [hide + 'exec "$@"', "sh", *run_autograder],
                "bubblewrap hidden: probes ran with rlimits alone, as on Gradescope")
    return run_autograder, "bubblewrap could not be hidden here (no mount namespace): probes ran inside it"


def measured_run(work, name, run_autograder, env):
    """run_autograder on what is in submission/, its whole process tree measured into
    WORK/NAME.json; stops when the tree took Gradescope's 768 MB or more."""
    report = os.path.join(work, name + ".json")
    run("run_autograder", os.path.join(work, name + ".log"),
        [sys.executable, os.path.join(HERE, "measure_process_tree.py"), report, "--",
         *run_autograder], env=env)
    with open(report) as file:
        measured = json.load(file)
    if measured["peak_bytes"] >= MEMORY_LIMIT_MB * MEGABYTE:
        fail("run_autograder's processes took %d MB together (%s) grading %s, over Gradescope's %d MB"
             % (measured["peak_bytes"] // MEGABYTE, measured["memory_method"], name, MEMORY_LIMIT_MB))
    return measured


def check_model_results(results_path):
    """6: every stage and every kind of check in results.json, each with its full points."""
    with open(results_path, encoding="utf-8") as file:
        results = json.load(file)
    tests = results.get("tests", [])
    ids = [test.get("extra_data", {}).get("id", test.get("name", "")) for test in tests]
    parts = {i.split(".")[0] for i in ids}
    kinds = {i.split(".")[1] for i in ids if "." in i}
    for part in ("stage1", "stage2", "stage3", "stage4", "stage5", "stage6", "stage7", "stage8",
                 "pipeline"):
        if part not in parts:
            fail("results.json has no check of %s: %s" % (part, sorted(parts)))
    for kind in ("unit", "oracle", "render", "speed"):
        if kind not in kinds:
            fail("results.json has no %s check: %s" % (kind, sorted(kinds)))
    score = results.get("score", 0)
    points = sum(test.get("max_score", 0) for test in tests)
    short = [i for i, test in zip(ids, tests) if test.get("score") != test.get("max_score")]
    if short or score != points or not score > 0:
        fail("the model submission scored %s of %s; checks short of their points: %s\n(results: %s)"
             % (score, points, short, os.path.dirname(results_path)))
    return score, points, len(tests)


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    root, work = (os.path.abspath(path) for path in sys.argv[1:])
    if not shutil.which("setpriv"):
        fail("setpriv is not installed; this test needs it (Debian: util-linux)")
    shutil.rmtree(work, ignore_errors=True)
    autograder = os.path.join(work, "autograder")
    source = os.path.join(autograder, "source")
    os.makedirs(source)
    os.makedirs(os.path.join(autograder, "results"))
    env = dict(os.environ, AUTOGRADER=autograder)

    # 1 and 2: the zip, unpacked as Gradescope does.
    zip_log = os.path.join(work, "zip.log")
    run("make-autograder-zip.sh", zip_log,
        ["bash", os.path.join(root, "grader/gradescope/make-autograder-zip.sh"),
         os.path.join(work, "autograder.zip")])
    with open(zip_log) as file:
        zip_made = file.read().strip()
    with zipfile.ZipFile(os.path.join(work, "autograder.zip")) as archive:
        for member in archive.infolist():
            path = archive.extract(member, source)
            mode = member.external_attr >> 16
            if mode and not member.is_dir():
                os.chmod(path, mode & 0o7777)
    for script in ("setup.sh", "run_autograder"):
        if not os.path.exists(os.path.join(source, script)):
            fail("the autograder zip has no %s at its top" % script)
        shutil.copy2(os.path.join(source, script), autograder)

    # 3: setup.sh, timed.
    start = time.monotonic()
    run("setup.sh", os.path.join(work, "setup.log"),
        ["bash", os.path.join(autograder, "setup.sh")], env=env)
    setup_seconds = time.monotonic() - start

    # 4: what the probes' user can read.
    check_closed_to_nobody(source)

    # 5 and 6: the model submission graded, measured, its results read back.
    shutil.copytree(os.path.join(root, "grader/tests/submissions/model"),
                    os.path.join(autograder, "submission"))
    run_autograder, sandbox = hide_bubblewrap(["bash", os.path.join(autograder, "run_autograder")])
    model = measured_run(work, "model", run_autograder, env)
    # On half a processor the run takes at least twice its processor time.
    if (model["wall_seconds"] >= TIME_LIMIT_SECONDS
            or model["cpu_seconds"] >= TIME_LIMIT_SECONDS / 2):
        fail("run_autograder took %s s with %s s of processor (twice that on half a processor), "
             "over Gradescope's %d s" % (model["wall_seconds"], model["cpu_seconds"],
                                         TIME_LIMIT_SECONDS))
    score, points, checks = check_model_results(os.path.join(autograder, "results/results.json"))

    # 7: a hostile stage 1 that takes 3 GiB of SysV shared memory in a static initializer, outside
    # every probe's address space (hostile/1-shared-memory-3-gib.diff), graded the same way: the
    # whole tree stays within 768 MB, results.json is complete, and the report names the rule the
    # probe broke.
    submission = os.path.join(autograder, "submission")
    shutil.rmtree(submission)
    shutil.rmtree(os.path.join(autograder, "results"))
    os.makedirs(os.path.join(autograder, "results"))
    shutil.copytree(os.path.join(root, "grader/tests/submissions/model/stages/1_vectors"),
                    os.path.join(submission, "stages/1_vectors"))
    run("git apply", os.path.join(work, "hostile-apply.log"),
        ["git", "-C", submission, "apply", "-p1",
         os.path.join(root, "grader/tests/submissions/hostile/1-shared-memory-3-gib.diff")])
    hostile = measured_run(work, "shared-memory", run_autograder, env)
    with open(os.path.join(autograder, "results/results.json"), encoding="utf-8") as file:
        hostile_text = file.read()
    hostile_results = json.loads(hostile_text)
    hostile_checks = len(hostile_results.get("tests", []))
    hostile_score = hostile_results.get("score", 0)
    if hostile_checks == 0 or hostile_score > 0:
        fail("the shared-memory submission got %s points over %d checks; results: %s/results"
             % (hostile_score, hostile_checks, autograder))
    if "system call the sandbox forbids" not in hostile_text:
        fail("the shared-memory submission's results.json does not name the sandbox's rule it "
             "broke; results: %s/results" % autograder)

    print("autograder zip: " + zip_made)
    print("setup.sh: %.0f s (its log: %s)" % (setup_seconds, os.path.join(work, "setup.log")))
    print("sandbox: " + sandbox)
    print("run_autograder: %s of %s points over %d checks in %s s, %s s of processor (at least "
          "twice that on Gradescope's half processor)"
          % (score, points, checks, model["wall_seconds"], model["cpu_seconds"]))
    print("peak memory of the whole tree: %d MB by %s; sampled resident memory: %d MB"
          % (model["peak_bytes"] // MEGABYTE, model["memory_method"],
             model["sampled_peak_bytes"] // MEGABYTE))
    print("the 3 GiB shared-memory submission: %s points over %d checks in %s s, peak memory "
          "%d MB (%s)" % (hostile_score, hostile_checks, hostile["wall_seconds"],
                          hostile["peak_bytes"] // MEGABYTE, hostile["memory_method"]))


if __name__ == "__main__":
    main()
