#pragma once

#include <filesystem>
#include <string>

namespace raystep {

/// The folder under which a command writes the files it was not told where to write: out/ in the
/// working folder. Git ignores it, so renders never land among the scenes or in `git status`.
inline const std::filesystem::path kOutputFolder = "out";

/// Where a command writes `file_name` when no -o is given: out/FOLDER/file_name, FOLDER naming
/// what it was made from: a scene's folder (scenes/stage6/cornell-box.test, view full:
/// out/stage6/cornell-box.full.png; scene_output_folder), or "demos". The folders are created.
std::filesystem::path default_output(const std::string& folder, const std::string& file_name);

/// The FOLDER of default_output for a scene: the name of the folder the scene file is in.
std::string scene_output_folder(const std::filesystem::path& scene);

}  // namespace raystep
