#!/usr/bin/env python3
"""`raystep view` in a student release, as scripts/check-student-build.sh runs it.

    view_release_check.py RAYSTEP SCENE stubs|written

SCENE is a scene of the release, with its reference shipped beside it. With every stage a stub,
the page's render must stop and name the stub, and a click's trace and its comparison with the
shipped reference trace must stop at it too. With every stage written, the render must finish and
the click's comparison find the traces the same. Both: the reference image is the shipped one.
Prints one line saying what it found; exits 1 when it is not what it should be.
"""

import re
import sys
import time

from view_process import ViewProcess

RAYSTEP, SCENE, STAGES = sys.argv[1:4]
STUB = re.compile(r"stage [0-9]+: [A-Za-z_:]+ is not implemented yet")


def main():
    view = ViewProcess(RAYSTEP, [SCENE])
    try:
        scene = view.json("/api/state")["scene"]
        assert scene["reference_source"] == "shipped beside the scene", scene
        view_name = scene["reference_views"][0]
        status, content_type, body = view.request("/api/reference?view=" + view_name)
        assert status == 200 and body.startswith(b"\x89PNG"), (status, body[:100])

        generation = view.json("/api/render?view=" + view_name)["generation"]
        deadline = time.time() + 120
        while True:
            header, _ = view.frame("/api/tiles?generation=%d&since=0" % generation)
            if header["state"] in ("done", "failed") or time.time() > deadline:
                break
            time.sleep(0.1)
        trace = view.json("/api/trace?x=0&y=0&view=" + view_name)
        compared = view.json("/api/compare?x=0&y=0&view=" + view_name)
        comparison = compared.get("comparison")
        assert comparison, compared.get("comparison_unavailable")
        if STAGES == "stubs":
            assert header["state"] == "failed" and STUB.search(header["error"]), header
            assert trace["stopped"] and STUB.search(trace["lines"][-1]), trace["lines"]
            assert comparison["stopped"] and STUB.search(comparison["stop"]), comparison
            print("the page's render, trace and comparison stop at " + header["error"])
        else:
            assert header["state"] == "done", header
            assert not trace["stopped"], trace["lines"]
            assert comparison["first_difference"] is None and not comparison["stopped"], comparison
            print("the page renders %s and its comparison finds the traces the same" % view_name)
    finally:
        code, out, err = view.interrupt()
    assert code == 0, (code, out, err)
    return 0


if __name__ == "__main__":
    sys.exit(main())
