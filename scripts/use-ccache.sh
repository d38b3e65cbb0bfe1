# Sourced by test-all.sh and check-student-build.sh: where ccache is installed, every CMake build
# they configure afresh compiles through it, so that one run compiles each object once. The
# student release, the mixed build and the Gradescope test's setup.sh all compile most of app/
# and base/ with the release build's flags; without ccache (it is optional, as every package of
# install-deps.sh's "other" list is) they build as before, only slower.
#
#   CMAKE_CXX_COMPILER_LAUNCHER  CMake (3.17 on) takes it as the launcher of a build folder
#                                configured for the first time, and so does every cmake a test
#                                runs (the Gradescope test's setup.sh). A folder configured
#                                before keeps the launcher it has.
#   CCACHE_BASEDIR               the repository: paths under it enter the hash relative to the
#                                build folder, so that build/release, the student release written
#                                to build/student-release and the autograder unpacked under
#                                build/release/grader/tests hit each other's objects. It rewrites
#                                paths on the command line, not a macro's value: the few files that
#                                name their copy's paths are compiled alone, outside the unity
#                                files (grader/grade/build_locations.cpp, app/demo/source_tree.cpp).
#   CCACHE_DIR                   a cache of the repository's own, in build/, read with no
#                                ccache.conf of the user's: a run is the same on a developer's
#                                machine and on a fresh CI machine, and nothing else writes to it.
#   CCACHE_IGNOREOPTIONS         -Werror decides whether a warning fails the build, never what is
#                                compiled: setup.sh, as Gradescope runs it, builds without it and
#                                can take the objects of the release build that test-all.sh made
#                                with it. The other way round cannot happen here: every object is
#                                first compiled by the release build with -Werror, and a compile
#                                that warned has failed that build and is never stored.
#
# The grader's probes, which compile a student's files in the sandbox, never go through ccache:
# raystep-grade runs the compiler probe-toolchain.json names (CMAKE_CXX_COMPILER, not the
# launcher), so nothing a submission compiles is read from or written to this cache.
if command -v ccache >/dev/null; then
    export CMAKE_CXX_COMPILER_LAUNCHER=ccache
    CCACHE_BASEDIR=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
    export CCACHE_BASEDIR
    export CCACHE_DIR=$CCACHE_BASEDIR/build/ccache
    export CCACHE_IGNOREOPTIONS=-Werror
fi
