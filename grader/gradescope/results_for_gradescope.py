#!/usr/bin/env python3
"""Writes the results.json that Gradescope reads, whatever raystep-grade did.

    results_for_gradescope.py GRADER_RESULTS CONSOLE EXIT_STATUS RESULTS

GRADER_RESULTS is the results.json raystep-grade writes, CONSOLE what it printed, EXIT_STATUS its
exit status, RESULTS the file Gradescope reads. When raystep-grade exited 0 and its results.json
is a JSON object, RESULTS is that object. Otherwise RESULTS says the grader failed, not the
student's code, with no score, and shows the end of the console output: decoded as UTF-8 with
every invalid byte replaced, and written by a JSON writer, so that tabs, quotes, backslashes and
control characters arrive as text. RESULTS is written whole or not at all (a temporary file
renamed over it), in ASCII.
"""

import json
import os
import sys

# The console's tail shown on a failure: enough for the grader's own message, well under what
# Gradescope shows in its output box.
CONSOLE_TAIL_BYTES = 2000


def grader_results(path, exit_status):
    """The grade raystep-grade wrote, or the reason it cannot be used."""
    if exit_status != 0:
        return None, f"raystep-grade exited with status {exit_status}"
    try:
        with open(path, "rb") as file:
            results = json.loads(file.read().decode("utf-8"))
    except OSError as error:
        return None, f"raystep-grade wrote no results ({error.strerror})"
    except ValueError as error:
        return None, f"raystep-grade's results are not valid JSON ({error})"
    if not isinstance(results, dict):
        return None, "raystep-grade's results are not a JSON object"
    return results, ""


def console_tail(path):
    """The last bytes of the console output as text, or a note that there was none."""
    try:
        with open(path, "rb") as file:
            file.seek(0, os.SEEK_END)
            file.seek(max(0, file.tell() - CONSOLE_TAIL_BYTES))
            tail = file.read()
    except OSError as error:
        return f"(no console output: {error.strerror})"
    return tail.decode("utf-8", errors="replace")


def failure(reason, console):
    return {
        "score": 0,
        "visibility": "visible",
        "output": "The grader failed, not your code: tell your instructor.\n\n"
        + reason
        + ". The end of its output:\n\n"
        + console_tail(console),
    }


def main(argv):
    if len(argv) != 5:
        print(f"usage: {argv[0]} GRADER_RESULTS CONSOLE EXIT_STATUS RESULTS", file=sys.stderr)
        return 2
    grader_path, console, exit_text, target = argv[1:]
    try:
        exit_status = int(exit_text)
    except ValueError:
        exit_status = -1
    results, reason = grader_results(grader_path, exit_status)
    if results is None:
        results = failure(reason, console)
    temporary = target + ".partial"
    # ASCII with \u escapes: a lone surrogate in the grader's JSON then needs no encoding.
    with open(temporary, "w", encoding="ascii") as file:
        json.dump(results, file, indent=1)
        file.write("\n")
    os.replace(temporary, target)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
