#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "base/scene/scene.h"

namespace raystep {

/// The files a scene is read from: the scene file (Scene::path), every mesh it loads and every
/// image its materials look up.
std::vector<std::filesystem::path> scene_files(const Scene& scene);

/// A digest of the contents of scene_files, 16 hexadecimal digits (64-bit FNV-1a), the same on
/// every platform: a reference trace keeps the digest of the scene it recorded, so that a
/// comparison can tell a student that the scene has been edited since. Carriage returns are left
/// out, so that a checkout that writes line ends as CRLF (git on Windows) changes nothing. Empty
/// when a file cannot be read.
std::string scene_digest(const Scene& scene);

}  // namespace raystep
