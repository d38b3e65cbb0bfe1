#!/usr/bin/env bash
# Installs what raystep needs on Debian or Ubuntu, and only what is missing. Elsewhere it prints
# the list and stops: install the same libraries with your package manager (README.md).
set -euo pipefail

packages=(
    # building
    cmake ninja-build g++ pkg-config
    # the stage libraries, their tests and the raystep command
    libglm-dev catch2 libopenimageio-dev openimageio-tools libcli11-dev libtinyobjloader-dev
    # the labels of `raystep demo` (OpenImageIO draws text only with a TrueType font it is given)
    fonts-dejavu-core
    # the grader: its exact oracle, the probe protocol, the sandbox, and its report tests (the XML
    # parsed back, the HTML report shown in a headless browser)
    libcgal-dev libgmp-dev libmpfr-dev nlohmann-json3-dev bubblewrap libxml2-dev chromium
    # its Gradescope test, which measures the autograder's memory
    time
    # raystep-reference bench: the Embree baseline, and the bunny mesh (CGAL's demo data)
    libembree-dev libcgal-demo
)

if ! command -v apt-get >/dev/null || ! command -v dpkg-query >/dev/null; then
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
