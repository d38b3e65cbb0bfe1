#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "base/scene/scene.h"

namespace raystep {

/// Reads a scene file: the CSE167 ray tracer format, the CSE168 path tracer's commands for area
/// lights and sampling, and raystep's extensions (docs/scene-format.md). Mesh paths are relative
/// to the scene file's folder. CSE168 settings that raystep does not render, and a non-square
/// `spp` sampled at random, are kept in Scene::notes for the caller to show as warnings.
///
/// Throws InputError `file:line: problem` for anything wrong: an unknown command, a wrong
/// argument count, a number that is malformed or not finite, a value out of its range (a
/// negative radius, a field of view of 180 degrees, spp 0), a word that is not one of its
/// command's (`lightstratify yes`), a vertex index out of range, popTransform on an empty stack,
/// a missing or malformed mesh file, a camera whose up vector is parallel to its view direction,
/// a quad light with no area, a non-square sample count where n x n strata need one, or no
/// camera at all.
Scene load_scene(const std::filesystem::path& path);

/// The same for scene text in memory: `name` is what messages call the file, and mesh paths are
/// resolved against `folder`.
Scene parse_scene(std::string_view text, const std::string& name,
                  const std::filesystem::path& folder);

}  // namespace raystep
