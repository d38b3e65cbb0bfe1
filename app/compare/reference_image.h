#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace raystep {

/// Where the student release keeps the reference's render of a scene's view: a reference/ folder
/// beside the scene, `<scene name>.<view>.png` (scenes/stage2/reference/orthographic.rays.png).
std::filesystem::path reference_image_path(const std::filesystem::path& scene,
                                           std::string_view view);

/// Where the student release keeps the reference's per-pixel trace of a scene, the values `raystep
/// trace --compare` holds a pixel against (app/compare/reference_trace.h): `<scene name>.trace.exr`
/// in the same reference/ folder (scenes/stage2/reference/orthographic.trace.exr).
std::filesystem::path reference_trace_path(const std::filesystem::path& scene);

/// The views of a scene the release renders by the reference: those its `# views:` line lists,
/// or `full` when it has none. An unreadable scene has none. Throws InputError naming the line
/// when it lists a word that is no view.
std::vector<std::string> reference_views(const std::filesystem::path& scene);

/// The reference image for a render: `<name>.png` with the image's own name
/// (orthographic.rays.png), or `<name>.<view>.png` when `view` is given and the name does not end
/// in it. Looked for in a reference/ folder beside the image, then in scenes/*/reference/ under
/// the current folder. Throws InputError naming the image, the name looked for and the
/// references of that scene there are, when there is none.
std::filesystem::path find_reference_image(const std::filesystem::path& image,
                                           const std::string& view);

}  // namespace raystep
