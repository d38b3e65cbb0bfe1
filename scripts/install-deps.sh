#!/usr/bin/env bash
# Installs what raystep needs on Debian or Ubuntu, and only what is missing. Elsewhere it prints
# the list and stops: install the same libraries with your package manager (README.md; on macOS
# the Brewfile lists them, on Windows vcpkg.json).
#
#   scripts/install-deps.sh             everything: building, the tests, the demos, the bench
#   scripts/install-deps.sh --grading   only what grading needs (Gradescope's setup.sh)
#   scripts/install-deps.sh --student   only what a student release builds with (scripts/setup.sh)
#
# Every name below is a package of both Debian 12 and Ubuntu 22.04 (Gradescope's image), so that
# one list serves both; docs/instructor.md, "Gradescope", has the versions each one ships.
set -euo pipefail

# What `raystep-grade` needs to be built and to grade: the compiler and build tools, the stage
# libraries (Catch2 too: configuring declares the stages' tests), OpenImageIO for the render
# checks' images, CLI11 and tinyobjloader for the commands, the exact oracle (CGAL over GMP and
# MPFR), the probe protocol and reports (nlohmann-json), the sandbox (bubblewrap), submissions'
# archives of every kind (libarchive), and Python for run_autograder's JSON when the grader itself
# cannot run.
# What a student release builds with: the stages and their tests, the raystep command (whose
# `grade` reads the public checks' JSON: nlohmann-json; whose `view` serves its page with
# cpp-httplib).
student_packages=(
    cmake ninja-build g++ pkg-config
    libglm-dev catch2 libopenimageio-dev libcli11-dev libtinyobjloader-dev nlohmann-json3-dev
    libcpp-httplib-dev
)
grading_packages=(
    cmake ninja-build g++ pkg-config
    libglm-dev catch2 libopenimageio-dev libcli11-dev libtinyobjloader-dev
    libcgal-dev libgmp-dev libmpfr-dev nlohmann-json3-dev bubblewrap libarchive-dev python3
)
# What the rest needs: OpenImageIO's command-line tools (iv, idiff) to look at renders; the labels
# of `raystep demo` (OpenImageIO draws text only with a TrueType font it is given); the report
# tests (the XML parsed back with libxml2, the HTML report and `raystep view` in headless
# Chromium, `raystep view` served by cpp-httplib); `raystep-reference bench` (the Embree
# baseline, and the bunny mesh of CGAL's demo data); the format check (clang-format 14, Debian
# 12's); ccache, through which scripts/test-all.sh compiles each object once for its several
# builds (scripts/use-ccache.sh); matplotlib, which draws the studies' charts and the chart of
# the grader's HTML report (scripts/draw-charts.py; without it a report has no chart); and the
# stand-ins for a student's Mac and Windows laptop (release/standins/,
# scripts/check-student-platforms.sh): clang 16 with libc++, and MinGW-w64 with Wine. The build
# configures without any of them, and the tests that need one say so and are skipped.
other_packages=(
    openimageio-tools fonts-dejavu-core libxml2-dev chromium libcpp-httplib-dev libembree-dev
    libcgal-demo clang-format ccache python3-matplotlib
    clang-16 libc++-16-dev libc++abi-16-dev g++-mingw-w64-x86-64-posix wine wine64
)

case "${1:-}" in
    "") packages=("${grading_packages[@]}" "${other_packages[@]}") ;;
    --grading) packages=("${grading_packages[@]}") ;;
    --student) packages=("${student_packages[@]}") ;;
    *)
        echo "usage: $0 [--grading | --student]" >&2
        exit 2
        ;;
esac

if ! command -v apt-get >/dev/null || ! command -v dpkg-query >/dev/null; then
    if [ "$(uname -s)" = Darwin ]; then
        echo "This is macOS: the Brewfile lists what to install, and README.md says how:" >&2
        echo "  brew bundle --no-upgrade" >&2
        echo "  cmake --preset student && cmake --build --preset student" >&2
        exit 1
    fi
    echo "This is not a Debian or Ubuntu system. Install these (or your system's equivalents):" >&2
    printf '  %s\n' "${packages[@]}" >&2
    exit 1
fi

missing=()
for package in "${packages[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
        missing+=("$package")
    fi
done
if [ ${#missing[@]} -eq 0 ]; then
    exit 0
fi

if [ "$(id -u)" -eq 0 ]; then
    as_root=()
elif command -v sudo >/dev/null; then
    as_root=(sudo)
else
    echo "Installing needs root, and sudo is not available. As root, run:" >&2
    echo "  apt-get update && apt-get install -y ${missing[*]}" >&2
    exit 1
fi

echo "Installing: ${missing[*]}"
"${as_root[@]}" apt-get update -q
DEBIAN_FRONTEND=noninteractive "${as_root[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
