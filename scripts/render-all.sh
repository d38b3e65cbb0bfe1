#!/usr/bin/env bash
# The first command of README.md: installs what is missing, builds, and renders every scene
# under scenes/ with the reference code into out/, one folder per scene and one image per view.
# A scene names the views that show its idea on a comment line `# views: depth normal ...`;
# without one it gets the finished image, `full`.
set -euo pipefail
cd "$(dirname "$0")/.."

scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release

raystep=build/release/bin/raystep-reference
if [ ! -x "$raystep" ]; then
    echo
    echo "This is a student release: there is no reference build to render with. The reference"
    echo "images are in scenes/<stage>/reference/; render with your own code with"
    echo "  build/release/bin/raystep render SCENE --view VIEW -o FILE"
    exit 0
fi
count=0
while IFS= read -r scene; do
    relative=${scene#scenes/}
    folder="out/${relative%.test}"
    views=$(sed -n 's/^# views: *//p' "$scene" | head -n 1)
    for view in ${views:-full}; do
        "$raystep" render "$scene" --view "$view" -o "$folder/$view.png" >/dev/null
    done
    echo "rendered $scene into $folder/ (${views:-full})"
    count=$((count + 1))
done < <(find scenes -name '*.test' | sort)

echo
echo "$count scenes rendered with the reference code: the images are in $(pwd)/out/"
