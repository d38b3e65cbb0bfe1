#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace raystep {

/// What a render shows. Each view is what one stage produces, so that a stage can be checked
/// (and graded) on its own image before the later stages exist. Views up to cost show one ray
/// through each pixel's centre whatever the scene's `spp` (a mean of depths or normals belongs
/// to no surface); shaded and full average the pixel's samples by stage 8 when spp > 1
/// (averages_samples below).
enum class View {
    rays,         ///< stage 2: the camera ray's direction as a colour, 0.5 (d + 1)
    depth,        ///< stage 3: distance to the nearest hit, near bright, far dark, misses black
    normal,       ///< stage 3: the geometric normal at the nearest hit as a colour, 0.5 (n + 1)
    barycentric,  ///< stage 3: (1 - beta - gamma, beta, gamma) on triangles, grey elsewhere
    cost,         ///< stage 4: BVH nodes visited plus primitives tested, as a heat map
    uv,           ///< stage 11: the hit's texture coordinates as (u, v, 0), each less its floor
    tangent,      ///< stage 11: the tangent frame's tangent as 0.5 (t + 1); black without one
    shaded,  ///< stage 6: the local model with shadows, no reflection; quad lights' soft shadows
             ///< (stage 8); misses show the background
    full,    ///< the finished image: stage 6, stage 7's reflections where the scene has mirrors,
             ///< stage 9's refraction where something transmits; misses show the background
    /// stage 10: under `integrator pathtracer`, the light that reaches what the eye sees after
    /// bouncing off another surface: each path's colour less the same path cut after its direct
    /// light (max_depth 1, the same random numbers). Black for a scene not path-traced.
    indirect,
};

/// The view's name on the command line.
std::string_view view_name(View view);

/// The view with this name; nullopt when no view has it.
std::optional<View> parse_view(std::string_view name);

/// Every view's name, in the order above.
std::vector<std::string> view_names();

/// True for the views that average a pixel's samples when the scene has more than one
/// (`spp`): shaded, full and indirect, the views of the finished colour. The others show one ray
/// through the pixel's centre whatever the scene's spp: a mean of depths, normals or barycentrics
/// blends values that belong to different surfaces (a depth halfway between a sphere and the wall
/// behind it is a depth of nothing), and those views are there to check stages 2 to 4 one ray
/// at a time.
bool averages_samples(View view);

}  // namespace raystep
