#!/usr/bin/env python3
"""The HTML report as a browser shows it: headless Chromium opens the example's student page,
which carries its images inside it as data URLs, and takes a screenshot, which must show a page
with the example's images (not blank, not broken pictures).

    html_screenshot_test.py EXAMPLE SCRATCH

EXAMPLE is raystep_report_example, which writes the report and judges the screenshot; SCRATCH
holds both. Chromium is driven as `raystep view`'s browser tests drive it
(app/view/tests/headless_chromium.py). Exits 77 (skipped) where no Chromium is installed:
scripts/install-deps.sh installs it, so CI runs the test.
"""

import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..",
                                "app", "view", "tests"))
from headless_chromium import Chromium, find_browser_or_skip  # noqa: E402

EXAMPLE, SCRATCH = sys.argv[1:3]


def main():
    browser = find_browser_or_skip()
    shutil.rmtree(SCRATCH, ignore_errors=True)
    report = os.path.join(SCRATCH, "report")
    subprocess.run([EXAMPLE, "write", report], check=True, timeout=120)

    # The window is tall enough for the whole example page (about 4,700 pixels), render checks'
    # images included.
    screenshot = os.path.join(SCRATCH, "screenshot.png")
    chromium = Chromium(browser, width=1200, height=6000)
    try:
        chromium.navigate("file://" + os.path.join(os.path.abspath(report), "student",
                                                   "index.html"))
        # The report's own page, not the blank one before it, loaded with every image.
        chromium.wait_until("location.protocol === 'file:' && document.readyState === 'complete' "
                            "&& document.images.length > 0 && "
                            "Array.from(document.images).every(image => image.complete)")
        chromium.screenshot(screenshot)
    finally:
        chromium.close()

    if subprocess.run([EXAMPLE, "check-screenshot", screenshot], timeout=60).returncode != 0:
        print("The screenshot %s does not show the report with its images" % screenshot)
        return 1
    print("the example report renders in Chromium with its images: %s" % screenshot)
    return 0


if __name__ == "__main__":
    sys.exit(main())
