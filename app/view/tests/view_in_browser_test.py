#!/usr/bin/env python3
"""`raystep view` in a real browser: a student's page, a click, and the trace it shows.

    view_in_browser_test.py RAYSTEP RAYSTEP_REFERENCE SCENE WORK_FOLDER SCREENSHOT

A copy of SCENE gets what a student release ships beside a scene (the reference's images and
trace, written by RAYSTEP_REFERENCE), and then a light of half the brightness, as a student's
bug would make it (the comparison notes, too, that the scene changed since its trace). In
headless Chromium the test waits for the render, clicks a pixel, and checks the panel's lines
against `raystep trace` and its comparison against `raystep trace --compare`; then switches the
view, moves the reference slider, and edits the scene. The page's screenshot is kept at
SCREENSHOT. Exits 77 (skipped) where no Chromium is installed.
"""

import os
import re
import shutil
import subprocess
import sys
import time

from headless_chromium import Chromium, find_browser_or_skip
from view_process import ViewProcess

RAYSTEP, REFERENCE, SCENE, WORK, SCREENSHOT = sys.argv[1:6]


def run(*command, expect=0):
    result = subprocess.run(command, capture_output=True, text=True, timeout=300)
    assert result.returncode == expect, "%s exited %d: %s" % (
        " ".join(command), result.returncode, result.stderr)
    return result.stdout


def student_scene():
    """A copy of SCENE with the reference's files beside it, and a light the reference lacks."""
    os.makedirs(os.path.join(WORK, "reference"), exist_ok=True)
    name = os.path.splitext(os.path.basename(SCENE))[0]
    scene = os.path.join(WORK, name + ".test")
    shutil.copy(SCENE, scene)
    reference = os.path.join(WORK, "reference", name)
    run(REFERENCE, "render", scene, "--view", "full", "-o", reference + ".full.png",
        "--trace-data", reference + ".trace.exr")
    run(REFERENCE, "render", scene, "--view", "normal", "-o", reference + ".normal.png")
    text = open(scene).read()
    point = re.search(r"^point( \S+){3}( \S+){3}$", text, re.MULTILINE)
    assert point, "the scene needs a point light for its student to get wrong"
    words = point.group(0).split()
    wrong = " ".join(words[:4] + [str(float(w) * 0.5) for w in words[4:]])
    with open(scene, "w") as file:
        file.write(text.replace(point.group(0), wrong, 1))
    return scene


def panel_lines(browser):
    return browser.evaluate(
        "[...document.querySelectorAll('#trace-lines li')].map((li) => li.textContent)")


def click_pixel(browser, x, y, view):
    box = browser.evaluate("(() => { const r = document.getElementById('render')"
                           ".getBoundingClientRect(); return [r.left, r.top, r.width]; })()")
    width = browser.evaluate("document.getElementById('render').width")
    zoom = box[2] / width
    browser.click(box[0] + (x + 0.5) * zoom, box[1] + (y + 0.5) * zoom)
    browser.wait_until("(() => { const p = document.getElementById('trace-panel'); return "
                       "p.dataset.state === 'ready' && p.dataset.pixel === '%d,%d' && "
                       "p.dataset.view === '%s'; })()" % (x, y, view))


def set_control(browser, name, value):
    browser.evaluate("(() => { const c = document.querySelector('#controls [name=%s]');"
                     "c.value = '%s'; c.dispatchEvent(new Event('change')); })()" % (name, value))


def comparison_rows(browser):
    return browser.evaluate(
        "[...document.querySelectorAll('#comparison tbody tr')].map((tr) => "
        "[...tr.cells].map((td) => td.textContent))")


def rows_of_trace_compare(text):
    """The rows `raystep trace --compare` prints: [marker, quantity, this build, reference]."""
    lines = text.splitlines()
    start = next(k for k, line in enumerate(lines) if line.strip().startswith("quantity"))
    rows = []
    for line in lines[start + 1:]:
        if not line.startswith((">> ", "   ")):
            break
        cells = re.split(r"\s{2,}", line[3:].strip())
        rows.append([">>" if line.startswith(">>") else ""] + cells)
    return rows


def wait_for_render(browser, generation_before=None):
    condition = "document.body.dataset.render === 'done'"
    if generation_before is not None:
        condition += " && Number(document.body.dataset.generation) > %d" % generation_before
    browser.wait_until(condition, timeout=120)
    return int(browser.evaluate("document.body.dataset.generation"))


def main():
    executable = find_browser_or_skip()
    os.makedirs(WORK, exist_ok=True)
    scene = student_scene()
    view = ViewProcess(RAYSTEP, [scene])
    browser = Chromium(executable)
    try:
        browser.navigate(view.address + "/")
        generation = wait_for_render(browser)

        # A click on a pixel of the floor: the panel holds raystep trace's lines, one for one.
        x, y = 240, 400
        click_pixel(browser, x, y, "full")
        expected = run(RAYSTEP, "trace", scene, str(x), str(y), "--view", "full").splitlines()
        assert panel_lines(browser) == expected, "the panel's lines are not raystep trace's"

        # The comparison is trace --compare's, first difference marked where it marks it.
        compare = run(RAYSTEP, "trace", scene, str(x), str(y), "--view", "full", "--compare",
                      expect=1)
        rows = comparison_rows(browser)
        assert rows == rows_of_trace_compare(compare), (rows, compare)
        marked = [row for row in rows if row[0] == ">>"]
        assert len(marked) == 1, rows
        verdict = browser.evaluate("document.getElementById('comparison-verdict').textContent")
        assert verdict in compare, (verdict, compare)
        print("clicked (%d, %d): %d trace lines and %d compared rows as raystep trace gives them,"
              " the first difference at %s" % (x, y, len(expected), len(rows), marked[0][1]))
        os.makedirs(os.path.dirname(SCREENSHOT), exist_ok=True)
        browser.screenshot(SCREENSHOT)
        print("screenshot:", SCREENSHOT)

        # The view switch: the normal view, its reference beside it, its trace.
        browser.evaluate("document.querySelector('#views button[data-view=\"normal\"]').click()")
        generation = wait_for_render(browser, generation)
        click_pixel(browser, x, y, "normal")
        expected = run(RAYSTEP, "trace", scene, str(x), str(y), "--view", "normal").splitlines()
        assert panel_lines(browser) == expected, "the normal view's lines are not raystep trace's"
        caption = browser.evaluate("document.getElementById('reference-caption').textContent")
        assert caption == "normal", caption

        # The reference under a slider.
        browser.evaluate("(() => { const m = document.getElementById('reference-mode');"
                         "m.value = 'slider'; m.dispatchEvent(new Event('change')); })()")
        browser.wait_until("!document.getElementById('slider').hidden")

        # One server renders one image: another page (here a plain request) asks for the depth
        # view, and this page's buttons and caption follow the render it now draws.
        view.json("/api/render?view=depth")
        browser.wait_until("document.querySelector('#views [aria-pressed=\"true\"]').dataset.view"
                           " === 'depth' && document.getElementById('render-caption')"
                           ".textContent === 'depth'")
        generation = wait_for_render(browser, generation)

        # A control value the server refuses stays said, its field marked, while the image is
        # the last render's; a value it takes renders again. The scene's controls are its
        # point light's shadow-ray offset: it has no sampling to turn.
        names = browser.evaluate("[...document.querySelectorAll('#controls [name]')]"
                                 ".map((c) => c.name)")
        assert names == ["offset", "epsilon"], names
        set_control(browser, "offset", "along-ray")
        generation = wait_for_render(browser, generation)
        set_control(browser, "epsilon", "abc")
        browser.wait_until("document.querySelector('#controls [name=epsilon]')"
                           ".classList.contains('refused')")
        time.sleep(1.5)  # three of the tiles' polls, which used to write over it
        status = browser.evaluate("document.getElementById('status').textContent")
        assert status.startswith("not rendered: control epsilon"), status
        set_control(browser, "epsilon", "1e-4")
        generation = wait_for_render(browser, generation)
        assert not browser.evaluate("document.querySelector('#controls [name=epsilon]')"
                                    ".classList.contains('refused')")

        # An edit of the scene file renders again without a click; a broken one shows file:line
        # and leaves no trace of the scene before it; mended, it renders again.
        text = open(scene).read()
        with open(scene, "w") as file:
            file.write(text + "\nsphere 1 2\n")
        browser.wait_until("!document.getElementById('scene-error').hidden")
        error = browser.evaluate("document.getElementById('scene-error').textContent")
        assert re.search(r"\.test:\d+: ", error), error
        browser.wait_until("document.getElementById('status').textContent.startsWith("
                           "'the scene does not load')")
        assert browser.evaluate("document.getElementById('trace-lines').children.length") == 0
        assert browser.evaluate("document.getElementById('comparison-box').hidden")
        with open(scene, "w") as file:
            file.write(text.replace("\npoint ", "\npoint 0 1.5 0 0.1 0.1 0.1\n# point ", 1))
        generation = wait_for_render(browser, generation)
        browser.wait_until("document.getElementById('scene-error').hidden")

        # The lecturer's side: a demo at one value of its own parameter, a demo's scene explored
        # live with its parameter as a control, and full screen.
        browser.evaluate("document.getElementById('show-demos').click()")
        browser.evaluate("(() => { const s = document.querySelector("
                         "'#demo-list select[aria-label=\"triangle test\"]');"
                         "s.value = 'intersect_triangle_halfspaces';"
                         "s.dispatchEvent(new Event('change')); })()")
        browser.wait_until("(() => { const c = document.getElementById('demo-caption')"
                           ".textContent; return c.startsWith('raystep demo watertight --size ') "
                           "&& c.endsWith(' (triangle test: intersect_triangle_halfspaces)'); })()")
        browser.evaluate("[...document.querySelectorAll('#demo-list div')].find((d) => "
                         "d.textContent.includes('shadow-acne:')).querySelectorAll('button')[1]"
                         ".click()")
        browser.wait_until("document.getElementById('scene-list').value === "
                           "'stage6/acne-scale-1e4.test'")
        # Under the slider, the Cornell box's reference (480 x 480) never stands over the acne
        # scene (480 x 360): the overlay stays hidden until the scene's own reference arrives.
        overlay_size = ("(() => { const o = document.getElementById('reference-overlay'); "
                        "return o.hidden ? null : [o.width, o.height]; })()")
        shown = browser.evaluate(overlay_size)
        assert shown in (None, [480, 360]), shown
        epsilon = browser.wait_until("document.querySelector('#controls [name=epsilon]').value")
        assert epsilon == "1e-12", epsilon
        wait_for_render(browser, generation)
        status = browser.evaluate("document.getElementById('status').textContent")
        assert status.startswith("shaded: done"), status
        assert browser.wait_until(overlay_size) == [480, 360]
        box = browser.evaluate("(() => { const r = document.getElementById('full-screen')"
                               ".getBoundingClientRect(); return [r.left + 5, r.top + 5]; })()")
        browser.click(*box)
        browser.wait_until("document.body.classList.contains('full-screen')")
        browser.screenshot(SCREENSHOT.replace(".png", "-lecture.png"))
    finally:
        browser.close()
        code, out, err = view.interrupt()
    assert code == 0, (code, out, err)
    return 0


if __name__ == "__main__":
    sys.exit(main())
