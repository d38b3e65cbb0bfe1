#!/usr/bin/env bash
# Makes the autograder zip that Gradescope takes (docs/instructor.md, "Gradescope"): this
# repository's files as they are in the working tree (tracked ones, and new ones git does not
# ignore; never build/, out/ or the extracted meshes), with setup.sh and run_autograder of this
# folder copied to its top, where Gradescope looks for them.
#
#   grader/gradescope/make-autograder-zip.sh [ZIP]      (default: build/autograder.zip)
#
# The zip is written by `cmake -E tar`, which keeps each file's mode (run_autograder stays
# executable) and needs nothing that building raystep does not.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
repository=$(cd "$here/../.." && pwd)

zip=${1:-$repository/build/autograder.zip}
case "$zip" in
    /*) ;;
    *) zip=$(pwd)/$zip ;;
esac
case "$zip" in
    *.zip) ;;
    *)
        echo "$0: $zip: the autograder must be a .zip file" >&2
        exit 2
        ;;
esac

if ! git -C "$repository" rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    echo "$0: $repository is not a git checkout: the zip holds the files git knows of" >&2
    exit 1
fi

staging=$(mktemp -d)
trap 'rm -rf "$staging"' EXIT

# The repository's files, copied with their modes through a tar of the list. A tracked file
# deleted from the working tree is left out.
(
    cd "$repository"
    git ls-files -z --cached --others --exclude-standard |
        while IFS= read -r -d '' file; do
            if [ -f "$file" ]; then printf '%s\n' "$file"; fi
        done | sort -u > "$staging/files.txt"
    cmake -E tar cf "$staging/tree.tar" --files-from="$staging/files.txt"
)
mkdir "$staging/autograder"
(cd "$staging/autograder" && cmake -E tar xf "$staging/tree.tar")
cp -p "$here/setup.sh" "$here/run_autograder" "$staging/autograder/"

mkdir -p "$(dirname "$zip")"
rm -f "$zip"
(
    cd "$staging/autograder"
    find . -type f | sed 's|^\./||' | sort > "$staging/zipped.txt"
    cmake -E tar cf "$zip" --format=zip --files-from="$staging/zipped.txt"
)
echo "wrote $zip ($(wc -l < "$staging/zipped.txt") files, $(du -h "$zip" | cut -f1))"
