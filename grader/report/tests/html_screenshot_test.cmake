# The HTML report as a browser shows it: headless Chromium opens the example's student page, which
# carries its images inside it as data URLs, and takes a screenshot, which must show a page with
# the example's images (not blank, not broken pictures).
# Run by ctest through `cmake -P`:
#   -DEXAMPLE=path/to/raystep_report_example -DSCRATCH=folder for the report and the screenshot
#
# Chromium is looked for when the test runs, so installing it needs no new configure. Without it
# the test stops with "Chromium is not installed", which ctest reads as skipped
# (SKIP_REGULAR_EXPRESSION in CMakeLists.txt): reported, never passed. scripts/install-deps.sh
# installs Chromium, so CI runs it.
find_program(chromium NAMES chromium chromium-browser google-chrome-stable google-chrome)
if(NOT chromium)
    message(FATAL_ERROR "Chromium is not installed, and this test opens the HTML report in it. "
                        "Debian: apt-get install --no-install-recommends chromium")
endif()

file(REMOVE_RECURSE ${SCRATCH})
execute_process(COMMAND ${EXAMPLE} write ${SCRATCH}/report RESULT_VARIABLE written)
if(NOT written EQUAL 0)
    message(FATAL_ERROR "${EXAMPLE} write ${SCRATCH}/report exited with ${written}")
endif()

# --no-sandbox: Chromium's sandbox refuses to start as root (CI, containers); the page is our own
# report from disk. Its own profile folder keeps the user's untouched. The window is tall enough
# for the whole example page (about 4,700 pixels), render checks' images included.
set(screenshot ${SCRATCH}/screenshot.png)
execute_process(COMMAND ${chromium} --headless --no-sandbox --disable-gpu --hide-scrollbars
                        --no-first-run --user-data-dir=${SCRATCH}/profile
                        --window-size=1200,6000 --screenshot=${screenshot}
                        file://${SCRATCH}/report/student/index.html
                RESULT_VARIABLE ran OUTPUT_VARIABLE output ERROR_VARIABLE output
                TIMEOUT 120)
if(NOT ran EQUAL 0 OR NOT EXISTS ${screenshot})
    message(FATAL_ERROR "${chromium} did not take the screenshot (exit ${ran}):\n${output}")
endif()

execute_process(COMMAND ${EXAMPLE} check-screenshot ${screenshot} RESULT_VARIABLE checked)
if(NOT checked EQUAL 0)
    message(FATAL_ERROR "The screenshot ${screenshot} does not show the report with its images")
endif()
