#pragma once

#include <filesystem>
#include <vector>

#include "base/scene/ray_offset.h"

namespace raystep {

/// What a ray offset rule costs on a scene: its shadow rays' time, from building each ray to
/// the answer of the occlusion query, averaged over every shadow ray of the image.
struct OffsetRuleCost {
    RayOffset offset;
    double nanoseconds_per_ray = 0.0;
};

/// The cost of each offset in `offsets` on the scene's primary hits and point lights, one
/// thread, best of three, through this program's stages. `surface_nanoseconds` receives what
/// rebuilding each hit's surface point and its error bound costs: every rule starts from it.
/// Throws NotImplemented for a stub, InputError for a bad scene file.
std::vector<OffsetRuleCost> measure_offset_costs(const std::filesystem::path& scene,
                                                 const std::vector<RayOffset>& offsets,
                                                 double& surface_nanoseconds);

}  // namespace raystep
