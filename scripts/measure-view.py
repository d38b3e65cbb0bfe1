#!/usr/bin/env python3
"""What `raystep view` costs a render: each scene's view rendered three times by the page's server
(the render thread's own time, the tiles kept as they finish) and three times by `raystep render`,
in one run, the fastest of each printed side by side. docs/measurements/raystep-view.md.

    scripts/measure-view.py [RAYSTEP] [SCENE ...]
"""

import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(__file__), "..", "app", "tests", "view"))
from view_process import ViewProcess  # noqa: E402

RUNS = 3


def render_seconds(raystep, scene, output):
    out = subprocess.run([raystep, "render", scene, "--view", "full", "-o", output],
                         capture_output=True, text=True, check=True).stdout
    return float(re.search(r", ([0-9.]+) s on ", out).group(1))


def main():
    raystep = sys.argv[1] if len(sys.argv) > 1 else "build/release/bin/raystep"
    scenes = sys.argv[2:] or ["scenes/stage4/bunny.test", "scenes/stage7/mirror-spheres.test",
                              "scenes/stage8/soft-shadows.test"]
    output = os.path.join(tempfile.mkdtemp(), "render.png")
    print("| scene | raystep view | raystep render | ratio |")
    print("|---|---|---|---|")
    for scene in scenes:
        view = ViewProcess(raystep, [scene])
        served = []
        for _ in range(RUNS):
            generation = view.json("/api/render?view=full")["generation"]
            served.append(view.wait_for_render(generation)[0]["seconds"])
        view.interrupt()
        rendered = [render_seconds(raystep, scene, output) for _ in range(RUNS)]
        print("| %s | %.3f s | %.3f s | %.2f |" % (scene, min(served), min(rendered),
                                                    min(served) / min(rendered)))


if __name__ == "__main__":
    main()
