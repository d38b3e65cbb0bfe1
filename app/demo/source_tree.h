#pragma once

#include <filesystem>

namespace raystep {

/// The source tree this program was built from, as CMake configured it: its scenes/ (the demos'),
/// its grading/ and stage 3's cases (`raystep grade`, `raystep check`), the project `raystep view`
/// shows. Only source_tree.cpp is compiled with the path, outside the unity build, so that the
/// other files compile to the same objects in every copy of the tree (a student release beside the
/// repository), which ccache then shares (scripts/use-ccache.sh).
std::filesystem::path source_tree();

}  // namespace raystep
