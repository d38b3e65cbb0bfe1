#!/usr/bin/env python3
"""run_autograder when the grader fails: whatever raystep-grade prints or leaves behind,
results.json is valid JSON (strict UTF-8, no raw control characters) that Gradescope can show.

    gradescope_failure_test.py ROOT WORK

Each case runs run_autograder with RAYSTEP_GRADE naming a stand-in grader that misbehaves, and
reads results.json back with Python's strict decoder and parser.
"""

import json
import os
import shutil
import subprocess
import sys


def fail(message):
    sys.exit("gradescope_failure_test.py: " + message)


def run_case(root, work, name, grader):
    """Runs run_autograder with GRADER (a bash script, given the submission folder as $2 and the
    output folder as $4) as the grader; returns the score and the output of its results.json."""
    autograder = os.path.join(work, name)
    os.makedirs(os.path.join(autograder, "submission"))
    os.makedirs(os.path.join(autograder, "source/grader"))
    os.symlink(os.path.join(root, "grader/gradescope"),
               os.path.join(autograder, "source/grader/gradescope"))
    script = os.path.join(work, name + "-grader")
    with open(script, "w") as file:
        file.write("#!/usr/bin/env bash\n" + grader + "\n")
    os.chmod(script, 0o700)
    ran = subprocess.run(["bash", os.path.join(root, "grader/gradescope/run_autograder")],
                         env=dict(os.environ, AUTOGRADER=autograder, RAYSTEP_GRADE=script),
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    if ran.returncode != 0:
        fail("%s: run_autograder exited with %d:\n%s"
             % (name, ran.returncode, ran.stdout.decode("utf-8", "replace")))
    with open(os.path.join(autograder, "results/results.json"), "rb") as file:
        raw = file.read()
    try:
        results = json.loads(raw.decode("utf-8"))
    except ValueError as error:
        fail("%s: results.json is not valid JSON in UTF-8: %s" % (name, error))
    if not isinstance(results, dict):
        fail("%s: results.json is not a JSON object" % name)
    return results.get("score"), results.get("output", "")


def expect(name, score, output, expected_score, *texts):
    """The score is EXPECTED_SCORE (None: any), and each text appears in the output as it is."""
    if expected_score is not None and score != expected_score:
        fail("%s: score %s, expected %s" % (name, score, expected_score))
    for text in texts:
        if text not in output:
            fail("%s: the output lacks %r:\n%r" % (name, text, output))


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    root, work = (os.path.abspath(path) for path in sys.argv[1:])
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)

    # A grader that prints a tab, quotes, a backslash, control characters (an escape sequence,
    # NUL, DEL) and bytes that are not UTF-8, then exits 3 without results: its output is shown
    # with each invalid byte as U+FFFD and the control characters kept as characters.
    name = "unprintable-output"
    score, output = run_case(root, work, name, r"""printf 'compiler said:\there "quoted" C:\\path\n\033[31mred\033[0m \001\002\000\177 bad \377\376 \303\050 end\n'
exit 3""")
    expect(name, score, output, 0, "The grader failed, not your code", "exited with status 3",
           "compiler said:\there", '"quoted"', "C:\\path", "\x1b", "31mred",
           "\x01\x02\x00\x7f bad \ufffd\ufffd \ufffd( end")

    # A grader that exits 0 but leaves its results.json cut off.
    name = "cut-off-results"
    score, output = run_case(root, work, name, """mkdir -p "$4/instructor" && printf '{"score": 10, "tests": [{"name": "stage' > "$4/instructor/results.json" """)
    expect(name, score, output, 0, "not valid JSON")

    # A grader that cannot be started at all.
    name = "missing-grader"
    score, output = run_case(root, work, name, "exec /nonexistent/raystep-grade")
    expect(name, score, output, None, "exited with status 127", "No such file")

    # A grader that graded: its results go to Gradescope as they are, text with escapes included.
    name = "graded"
    score, output = run_case(root, work, name, r"""mkdir -p "$4/instructor" && printf '{"score": 7.5, "output": "tab\\there \\"q\\" \\\\ \\u00e9", "tests": []}\n' > "$4/instructor/results.json" """)
    expect(name, score, output, 7.5, 'tab\there "q" \\ \u00e9')
    print("run_autograder wrote valid results.json in every case")


if __name__ == "__main__":
    main()
