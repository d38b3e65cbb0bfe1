#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "base/image/image_library_table.h"

namespace raystep {

/// The module image_library() loads, in place of the build's own path and the executable's
/// folder: for a program that runs where the build tree is out of its view, a grader's probe,
/// which is told where its copy lies. Call it before the first image is read.
void use_image_library_module(const std::filesystem::path& module);

/// The image library's table, the module loaded on the first call: the module named by
/// use_image_library_module where one was, else from the path the build compiled in, else from
/// beside the running executable. Later calls return the same table.
/// Throws std::runtime_error naming each path tried and the system loader's message when the
/// module cannot be loaded, has no table or was built for another table version; the next call
/// tries again.
const RaystepImageLibraryTable& image_library();

/// The table of the first of `candidates` that loads as the image library module. Throws
/// std::runtime_error naming every candidate and the system loader's reason it did not load. A
/// module loaded stays loaded for the rest of the process.
const RaystepImageLibraryTable& load_image_library(
    const std::vector<std::filesystem::path>& candidates);

/// Throws std::runtime_error(`what` + library's message) when `failure`, the result of one of
/// the table's functions, is not nullptr.
void throw_on_image_failure(const char* failure, const std::string& what);

}  // namespace raystep
