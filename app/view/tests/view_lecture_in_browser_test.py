#!/usr/bin/env python3
"""`raystep view` as a lecturer uses it, in headless Chromium: full screen, the demos, and the
controls a scene gets.

    view_lecture_in_browser_test.py RAYSTEP SCENES_FOLDER SCREENSHOT_FOLDER

For windows of 1280 x 720 and 1920 x 1080 with the browser's zoom at 100%, and zoomed in (150%,
200%), the test measures boxes against the window:

- full screen: the scene's images and every control (the parameters the class reads) lie inside
  the window and nothing covers a control; the images neither overlap each other nor the controls;
  the page does not scroll; the images fill at least half
  of the room the header and the controls leave, in width or in height (a whole zoom z uses more
  than z / (z + 1) of it). Again after the page's zoom is set to 4x in full screen, and after the
  browser's zoom changes while in full screen.
- the demos: a demo's figure lies inside the window, under the header, and fills half its room
  (in a narrow window the list goes under the figure, and the page scrolls to it).
- the controls: a stage-2 scene has none (and says so), the soft-shadows scene has stage 8's.

The browser's zoom is what Chromium does for Ctrl-+: the window keeps its size in the screen's
pixels, and the page sees it as fewer CSS pixels at a larger device pixel ratio
(Emulation.setDeviceMetricsOverride). Screenshots of full screen and of a demo go to
SCREENSHOT_FOLDER. Exits 77 (skipped) where no Chromium is installed.
"""

import json
import os
import sys
import time

from headless_chromium import Chromium, find_browser_or_skip
from view_process import ViewProcess

RAYSTEP, SCENES, SCREENSHOTS = sys.argv[1:4]

# (window width, height, browser zoom): a lecture-hall projector at 720 and 1080 lines, each also
# zoomed in, as a lecturer does for the back row.
WINDOWS = ((1280, 720, 1.0), (1920, 1080, 1.0), (1280, 720, 2.0), (1920, 1080, 1.5))

# What is wrong with the page's layout now, as a list of sentences (empty: nothing). `room` is the
# box the images have: from their left to the controls' left, from the top of the render to the
# window's bottom.
LAYOUT_PROBLEMS = r"""
(() => {
  const problems = [];
  const W = window.innerWidth, H = window.innerHeight;
  const box = (e) => e.getBoundingClientRect();
  const name = (e) => e.id || e.name || e.tagName;
  const inside = (e, what) => {
    const b = box(e);
    if (!e.offsetParent && getComputedStyle(e).position !== "fixed") {
      problems.push(what + " " + name(e) + " is not shown");
      return false;
    }
    if (b.left < -0.5 || b.top < -0.5 || b.right > W + 0.5 || b.bottom > H + 0.5) {
      problems.push(`${what} ${name(e)} at [${b.left}, ${b.top}, ${b.right}, ${b.bottom}] ` +
                    `is outside the ${W} x ${H} window`);
      return false;
    }
    return true;
  };
  return { problems, inside, box, W, H };
})()
"""

FULL_SCREEN_PROBLEMS = r"""
(() => {
  const { problems, inside, box, W, H } = %s;
  const root = document.documentElement;
  if (root.scrollHeight > H + 1 || root.scrollWidth > W + 1) {
    problems.push(`the page scrolls: ${root.scrollWidth} x ${root.scrollHeight} in ${W} x ${H}`);
  }
  const controls = [...document.querySelectorAll("#controls input, #controls select")];
  if (controls.length === 0) problems.push("no controls on the page");
  for (const control of controls) {
    if (!inside(control, "control")) continue;
    const b = box(control);
    const hit = document.elementFromPoint((b.left + b.right) / 2, (b.top + b.bottom) / 2);
    if (hit !== control && !control.contains(hit)) {
      problems.push(`control ${control.name} is covered by ${hit && (hit.id || hit.tagName)}`);
    }
    if (!control.value) problems.push(`control ${control.name} shows no value`);
    const label = control.closest("label");
    if (label) inside(label, "the label of");
  }
  const images = [...document.querySelectorAll("#images canvas:not([hidden])")]
    .filter((c) => c.offsetParent && c.width > 1);
  if (images.length < 2) {
    problems.push(`${images.length} images shown, not the render and its reference`);
  }
  images.forEach((canvas) => inside(canvas, "image"));
  const sides = images.map((c) => box(c)).sort((a, b) => a.left - b.left);
  for (let k = 1; k < sides.length; ++k) {
    if (sides[k].left < sides[k - 1].right - 0.5) problems.push("the images overlap");
  }
  const asideBox = box(document.querySelector("aside"));
  if (sides.length && sides[sides.length - 1].right > asideBox.left + 0.5) {
    problems.push("the images run under the controls");
  }
  const render = box(document.getElementById("render"));
  const aside = box(document.querySelector("aside"));
  const left = Math.min(...images.map((c) => box(c).left));
  const right = Math.max(...images.map((c) => box(c).right));
  const room = { width: aside.left - box(document.getElementById("images")).left,
                 height: H - render.top };
  const used = Math.max((right - left) / room.width, render.height / room.height);
  if (used < 0.5) {
    problems.push(`the images use ${(100 * used).toFixed(0)}%% of their room ` +
                  `(${room.width.toFixed(0)} x ${room.height.toFixed(0)}): not fitted`);
  }
  if (!document.body.classList.contains("full-screen")) problems.push("not in full screen");
  const zooms = [...document.getElementById("zoom").options].map((o) => o.value);
  if (zooms.length > 5) problems.push("the zoom list has gathered " + zooms.join(", "));
  return { problems, zoom: document.getElementById("zoom").value, used,
           controls: controls.map((c) => c.name + "=" + c.value) };
})()
""" % LAYOUT_PROBLEMS

DEMO_PROBLEMS = r"""
(() => {
  const { problems, inside, box, W, H } = %s;
  const canvas = document.getElementById("demo-canvas");
  const header = box(document.querySelector("header"));
  if (inside(canvas, "the demo's figure")) {
    const b = box(canvas);
    if (b.top < header.bottom - 0.5) problems.push(`the figure's top ${b.top} is under the header`);
    const column = box(document.getElementById("demo-figure"));
    const used = Math.max(b.width / column.width, b.height / (H - header.bottom));
    if (used < 0.5) problems.push(`the figure uses ${(100 * used).toFixed(0)}%% of its room`);
  }
  return { problems, drawn: [canvas.width, canvas.height],
           shown: [box(canvas).width, box(canvas).height] };
})()
""" % LAYOUT_PROBLEMS


def set_window(browser, width, height, zoom):
    browser.call("Emulation.setDeviceMetricsOverride", session=True, width=round(width / zoom),
                 height=round(height / zoom), deviceScaleFactor=zoom, mobile=False)
    # The page sizes its images again on the resize event.
    time.sleep(0.3)


def click_element(browser, element_id):
    x, y = browser.evaluate("(() => { const r = document.getElementById('%s')"
                            ".getBoundingClientRect(); return [r.left + r.width / 2, "
                            "r.top + r.height / 2]; })()" % element_id)
    browser.click(x, y)


def enter_full_screen(browser):
    if not browser.evaluate("document.body.classList.contains('full-screen')"):
        click_element(browser, "full-screen")  # a click: full screen needs the user's gesture
        browser.wait_until("document.body.classList.contains('full-screen')")
    time.sleep(0.3)


def leave_full_screen(browser):
    browser.evaluate("document.fullscreenElement ? document.exitFullscreen() : null")
    browser.wait_until("!document.body.classList.contains('full-screen')")


def open_scene(browser, name):
    browser.evaluate("(() => { const s = document.getElementById('scene-list'); s.value = '%s';"
                     "s.dispatchEvent(new Event('change')); })()" % name)
    browser.wait_until("document.getElementById('scene-list').value === '%s'" % name)
    shown = ("document.body.dataset.render === 'done' && "
             "document.getElementById('reference').width > 1 && "
             "document.getElementById('reference-caption').textContent === "
             "document.getElementById('render-caption').textContent")
    browser.wait_until(shown, timeout=180)
    # A poll of the tiles sent before the scene was opened can make the page load it again, and ask
    # for its reference again: shown, and still shown a second later.
    time.sleep(1)
    browser.wait_until(shown, timeout=180)


def control_names(browser):
    return browser.evaluate("[...document.querySelectorAll('#controls [name]')]"
                            ".map((c) => c.name)")


def check(result, what, failures):
    if result["problems"]:
        failures.append("%s: %s" % (what, "; ".join(result["problems"])))
    print("%s: %s" % (what, json.dumps({k: v for k, v in result.items() if k != "problems"})))


def main():
    executable = find_browser_or_skip()
    os.makedirs(SCREENSHOTS, exist_ok=True)
    view = ViewProcess(RAYSTEP, [os.path.join(SCENES, "stage2", "perspective-wide.test")])
    browser = Chromium(executable, 1280, 720)
    failures = []
    try:
        browser.navigate(view.address + "/")
        browser.wait_until("document.getElementById('scene-list').value === "
                           "'stage2/perspective-wide.test'")

        # The controls follow what the scene uses: a stage-2 scene has none and says so; the
        # soft-shadows scene, an area light sampled, has stage 8's.
        browser.wait_until("!document.getElementById('no-controls').hidden")
        assert control_names(browser) == [], control_names(browser)
        open_scene(browser, "demos/soft-shadows.test")
        names = control_names(browser)
        assert names == ["offset", "epsilon", "spp", "pixelsampling", "seed", "lightsamples",
                         "lightstratify"], names
        assert browser.evaluate("document.getElementById('no-controls').hidden")
        print("controls: none for stage2/perspective-wide.test; %s for demos/soft-shadows.test"
              % ", ".join(names))

        # Full screen, on the shadow-acne scene (its epsilon is the lecture's parameter) and on
        # soft-shadows (seven controls: the tallest panel).
        for scene in ("stage6/acne-scale-1e4.test", "demos/soft-shadows.test"):
            open_scene(browser, scene)
            short = os.path.splitext(os.path.basename(scene))[0]
            for width, height, zoom in WINDOWS:
                what = "full screen, %s, %dx%d at %d%%" % (short, width, height, zoom * 100)
                set_window(browser, width, height, zoom)
                enter_full_screen(browser)
                check(browser.evaluate(FULL_SCREEN_PROBLEMS), what, failures)
                browser.screenshot(os.path.join(
                    SCREENSHOTS, "full-screen-%s-%dx%d-%d.png" % (short, width, height,
                                                                   zoom * 100)))
                # The page's own zoom at its largest: still no more than fits.
                browser.evaluate("(() => { const z = document.getElementById('zoom');"
                                 "z.value = '4'; z.dispatchEvent(new Event('change')); })()")
                check(browser.evaluate(FULL_SCREEN_PROBLEMS), what + ", zoom 4x chosen", failures)
                leave_full_screen(browser)
            # The browser's zoom changed while in full screen: the images are fitted again.
            set_window(browser, 1920, 1080, 1.0)
            enter_full_screen(browser)
            set_window(browser, 1920, 1080, 2.0)
            check(browser.evaluate(FULL_SCREEN_PROBLEMS),
                  "full screen, %s, 1920x1080 zoomed to 200%% while in full screen" % short,
                  failures)
            leave_full_screen(browser)

        # A demo's figure: in view, in the window and in full screen.
        for width, height, zoom in WINDOWS[:3]:
            set_window(browser, width, height, zoom)
            if browser.evaluate("document.getElementById('demos').hidden"):
                click_element(browser, "show-demos")
            browser.evaluate("document.getElementById('demo-caption').textContent = ''")
            browser.evaluate("[...document.querySelectorAll('#demo-list div')].find((d) => "
                             "d.textContent.includes('shadow-acne:')).querySelector('button')"
                             ".click()")
            browser.wait_until("document.getElementById('demo-caption').textContent"
                               ".startsWith('raystep demo shadow-acne')", timeout=180)
            what = "demo figure, %dx%d at %d%%" % (width, height, zoom * 100)
            check(browser.evaluate(DEMO_PROBLEMS), what, failures)
            browser.screenshot(os.path.join(SCREENSHOTS, "demo-%dx%d-%d.png" % (
                width, height, zoom * 100)))
        enter_full_screen(browser)
        check(browser.evaluate(DEMO_PROBLEMS), "demo figure in full screen", failures)
        leave_full_screen(browser)
    finally:
        browser.close()
        code, out, err = view.interrupt()
    assert not failures, "\n".join(failures)
    assert code == 0, (code, out, err)
    print("screenshots:", SCREENSHOTS)
    return 0


if __name__ == "__main__":
    sys.exit(main())
