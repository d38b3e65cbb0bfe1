#!/usr/bin/env bash
# The student release on the stand-ins for a student's Mac and Windows laptop (release/standins/):
#   libcxx     clang 16 with libc++, Apple's C++ standard library;
#   mingw-w64  a MinGW-w64 cross build, its programs run under Wine.
# For each, the release `raystep-grade release` writes is configured with the student preset and
# the stand-in's toolchain, warnings as errors, and built; then the public tests run twice, judged
# as the student platforms workflow judges them (scripts/check-public-tests.py; under Wine, each
# test program run once for all its tests, --per-program):
#   1. with the stubs: every test case fails with a NotImplemented message, and none crashes;
#   2. with every stage written (the model submission's manifest files copied in, nothing else,
#      and the build run again): every test case passes.
# Last, the raystep command with every stage written: `info`, which reads a scene, and `render`,
# which writes its image where the stand-in has the image module (libc++) and says the module is
# missing where it has none (MinGW: release/standins/mingw-w64.cmake says why).
#
#   scripts/check-student-platforms.sh [libcxx] [mingw-w64]    (default: both)
#
# Needs build/release (the release writer). Where ccache is installed, the builds compile through
# it (scripts/use-ccache.sh), so the second build of each recompiles only the stage files.
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
source scripts/use-ccache.sh
source scripts/check-command.sh
standins=("$@")
[ ${#standins[@]} -eq 0 ] && standins=(libcxx mingw-w64)
problems=0

release=$root/build/platform-release
rm -rf "$release"
# Written here, or copied from RAYSTEP_RELEASE, where scripts/test-all.sh wrote one release for
# this and the other student checks (writing one renders every scene's reference views).
if [ -n "${RAYSTEP_RELEASE:-}" ]; then
    cp -r "$RAYSTEP_RELEASE" "$release"
else
    build/release/bin/raystep-grade release "$release" >/dev/null
fi
model=$root/grader/tests/submissions/model/stages

stubs=$root/build/platform-stubs
rm -rf "$stubs"
cp -r "$release/stages" "$stubs"
trap 'rm -rf "$release" "$stubs"' EXIT

# write_the_stages: the model's manifest files into the release, as a student's edits.
write_the_stages() {
    local manifest stage entry
    for manifest in "$release"/stages/*/manifest.txt; do
        stage=$(basename "$(dirname "$manifest")")
        while read -r entry; do
            case "$entry" in "" | "#"*) continue ;; esac
            cp "$model/$stage/$entry" "$release/stages/$stage/$entry"
        done <"$manifest"
    done
}


# The public tests run side by side (ctest reads CTEST_PARALLEL_LEVEL).
export CTEST_PARALLEL_LEVEL=${CTEST_PARALLEL_LEVEL:-$(nproc 2>/dev/null || echo 2)}
for standin in "${standins[@]}"; do
    toolchain=$root/release/standins/$standin.cmake
    if [ ! -f "$toolchain" ]; then
        echo "no stand-in '$standin': release/standins/ has $(cd release/standins && ls ./*.cmake)" >&2
        exit 2
    fi
    # The student preset's own folder, build/student, so that its test preset finds the tests.
    build=$release/build/student
    rm -rf "$build"
    raystep=("$build/bin/raystep")
    if [ "$standin" = mingw-w64 ]; then
        # Wine's own messages off, and its prefix (its C: drive) inside the build. Its server and
        # services are started here, their output to /dev/null: started by the first test, they
        # would hold that test's output pipe open, and ctest would wait for it to close forever.
        export WINEDEBUG=-all WINEPREFIX=$build/wine
        mkdir -p "$WINEPREFIX"
        wineboot --init >/dev/null 2>&1 </dev/null
        trap 'wineserver -k 2>/dev/null || true; rm -rf "$release" "$stubs"' EXIT
        raystep=(wine "$build/bin/raystep.exe")
    fi
    for stages in stubs written; do
        echo "== $standin, $stages (at $SECONDS s)"
        rm -rf "$release/stages"
        cp -r "$stubs" "$release/stages"
        [ "$stages" = written ] && write_the_stages
        # The toolchain is named once, when the folder is first configured, as CMake takes it; the
        # preset's own toolchain file, named again on the second configure, is then unused.
        toolchain_option=()
        [ -f "$build/CMakeCache.txt" ] || toolchain_option=(--toolchain "$toolchain")
        # libc++ compiles file by file, not in the preset's unity build, so that a file that
        # reaches a header only through libstdc++'s own includes, or through a file its unity
        # file holds before it, fails here as on a Mac. MinGW builds the preset's unity files, as
        # a student's Windows build does.
        unity=ON
        [ "$standin" = libcxx ] && unity=OFF
        (cd "$release" && cmake --preset student "${toolchain_option[@]}" --no-warn-unused-cli \
            -DRAYSTEP_WARNINGS_AS_ERRORS=ON -DCMAKE_UNITY_BUILD=$unity >/dev/null &&
            cmake --build --preset student)
        judge_options=(--junit "$release/build/$standin-$stages.xml")
        # Under Wine each test program runs once for all its tests: ctest's one Windows process
        # per test case costs seconds each (docs/measurements/student-platforms.md).
        [ "$standin" = mingw-w64 ] && judge_options=(--per-program)
        if ! (cd "$release" && python3 "$root/scripts/check-public-tests.py" "$stages" student \
            "${judge_options[@]}"); then
            problems=$((problems + 1))
        fi
    done
    # From the release's root, by relative paths, as a student types them: on Windows, CLI11 takes
    # an argument that starts with / for an option (/o), and a Linux path starts with one.
    cd "$release"
    scene=scenes/stage3/spheres-on-plane.test
    check_command "$standin: raystep info reads a scene" 0 "views" "${raystep[@]}" info "$scene"
    if [ "$standin" = mingw-w64 ]; then
        check_command "$standin: raystep render says the image module is missing" 1 \
            "cannot load the image library" "${raystep[@]}" render "$scene" --view depth
    else
        check_command "$standin: raystep render writes its image through the image module" 0 \
            "^wrote out/stage3/spheres-on-plane.depth.png" "${raystep[@]}" render "$scene" \
            --view depth
    fi
    cd "$root"
done

if [ "$problems" -ne 0 ]; then
    echo "$problems problem(s) on the stand-ins"
    exit 1
fi
echo "the student release builds and tests as it should on: ${standins[*]}"
