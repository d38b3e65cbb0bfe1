#pragma once

#include <filesystem>
#include <string>

namespace raystep {

/// The folder under which a command writes the files it was not told where to write: out/ in the
/// working folder. Git ignores it, so renders never land among the scenes or in `git status`.
inline const std::filesystem::path kOutputFolder = "out";

/// Where a command writes `file_name`, made for the scene `scene`, when no -o is given:
/// out/FOLDER/file_name, FOLDER being the name of the scene's folder
/// (scenes/stage6/cornell-box.test, view full: out/stage6/cornell-box.full.png). The folders are
/// created.
std::filesystem::path default_output(const std::filesystem::path& scene,
                                     const std::string& file_name);

}  // namespace raystep
