#pragma once

#include <filesystem>

namespace raystep {

/// The source tree this program was built from, as CMake configured it: its scenes/ (the demos'),
/// its grading/ and stage 3's cases (`raystep grade`, `raystep check`), the project `raystep view`
/// shows. Only source_tree.cpp is compiled with the path, alone, outside the unity build, so that
/// no other file depends on where the tree is.
std::filesystem::path source_tree();

}  // namespace raystep
