#pragma once

#include <filesystem>
#include <string>

namespace raystep {

/// The whole text of a file we are asked to read (a scene, a case file). Throws InputError
/// naming the file when it does not exist, cannot be read, or is not a regular file (a FIFO or a
/// device could block or never end). `what` names the kind of file in messages: "scene file".
std::string read_text_file(const std::filesystem::path& path, const std::string& what);

}  // namespace raystep
