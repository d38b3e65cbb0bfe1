#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "base/math/types.h"
#include "renderer/render_scene.h"
#include "renderer/seen_quad_light.h"
#include "stages/4_accel/traversal.h"
#include "stages/6_shading/shading.h"

namespace raystep {

/// What one light does at a hit, as stage 6 decides it.
enum class LightReach {
    behind,   ///< the light is behind the surface: no shadow ray
    blocked,  ///< the shadow ray meets something before the light
    reaches,  ///< the shadow ray reaches the light; its term counts
};

/// The lights stage 6 samples at a hit, one at a time, in this order.
enum class LightKind { point, directional, spot };

/// One point, directional or spot light at a hit: the sample stage 6 took of it, whether it
/// reaches the point, and the shadow ray that decided it (none for a light behind the surface).
struct LightStep {
    LightKind kind;
    std::uint32_t line;  ///< the light's line in its scene file
    LightSample sample;
    LightReach reach;
    std::optional<Ray> shadow_ray;
};

/// The steps of one pixel, told by the renderer as it takes them to whoever watches: `raystep
/// trace` prints them (app/trace/trace_printer.h), a reference trace keeps their values
/// (pixel_record.h). Rendering and watching run the same code: a render watches with this class
/// itself, whose every step does nothing, so the renderer has no branch of its own for a trace.
///
/// The order is the renderer's: the camera ray, its closest hit, then at a shaded hit its surface
/// point, each light, the quad lights and the local colour; then the recursion's later rays, each
/// with its own shading, and the colour the recursion gives; or, path-traced, each ray of the path
/// and each of its shadow rays. A sampled pixel tells each camera
/// sample's start and colour, and the steps of the samples its observer asks for.
class PixelObserver {
  public:
    virtual ~PixelObserver() = default;

    /// Whether the observer also wants the steps of one more ray, through the pixel's centre with
    /// the light samples of sample 0, before a sampled pixel's samples: the steps are then those
    /// of one sample per pixel, whatever order the samples come in.
    virtual bool watches_centre_ray() const { return false; }
    /// Camera sample `index` of a sampled pixel starts; the observer answers whether it wants the
    /// sample's steps.
    virtual bool sample_starts(int /*index*/, const Vec2& /*film_point*/) { return false; }
    virtual void sample_ends(int /*index*/, const Color& /*colour*/) {}
    virtual void pixel_mean(int /*samples*/, const Color& /*colour*/) {}

    virtual void camera_ray(const Ray& /*ray*/) {}
    /// The search for the eye ray's closest hit starts (a stub may stop it before it ends).
    virtual void hit_search_starts(const Ray& /*ray*/) {}
    /// The eye ray's closest hit (empty on a miss), and what finding it cost.
    virtual void closest_hit(const Ray& /*ray*/, const std::optional<PrimitiveHit>& /*hit*/,
                             const TraversalStats& /*cost*/) {}

    /// In the CSE168 dialect, a quad light that the eye ray meets before its closest hit: the
    /// light's colour is the ray's, and nothing is shaded.
    virtual void quad_light_seen(const SeenQuadLight& /*seen*/) {}

    /// A hit being shaded: its surface point, then its lights in scene order (point,
    /// directional, spot), then its quad lights, then its local colour.
    virtual void surface(const SurfacePoint& /*point*/, const Material& /*material*/) {}
    virtual void light(const LightStep& /*step*/) {}
    virtual void spot_light_outside_cone(std::uint32_t /*line*/) {}
    virtual void quad_light_starts(const QuadLight& /*light*/) {}
    /// Light sample `index` of the current quad light faces the surface and sends `shadow_ray`.
    virtual void quad_light_sample(int /*index*/, const Ray& /*shadow_ray*/, bool /*blocked*/) {}
    virtual void quad_light_ends(const QuadLight& /*light*/, const Color& /*term*/,
                                 int /*shadow_rays*/) {}
    /// The local colour of the hit, with the samples of the lights that reach it, in the order
    /// of their light() steps.
    virtual void local_colour(const std::vector<LightSample>& /*reaching*/,
                              const Color& /*colour*/) {}

    /// Ray `index` (1 for the first) after the eye ray in the recursion, a mirror ray or, in a
    /// scene that refracts, any secondary ray; its closest hit, empty when it leaves the scene.
    virtual void later_ray(int /*index*/, const Ray& /*ray*/,
                           const std::optional<PrimitiveHit>& /*hit*/) {}
    /// What the recursion gives along the eye ray.
    virtual void recursion_colour(const Ray& /*eye_ray*/, const Color& /*colour*/) {}
    /// Under `integrator pathtracer` (renderer/path_traced.h), ray `index` of the eye ray's
    /// path as stage 10's path_radiance asks the scene for it (0: the eye ray itself), and what
    /// it meets: a quad light nearer than any surface (`light`), else the closest hit, empty
    /// when it leaves the scene.
    virtual void path_ray(int /*index*/, const Ray& /*ray*/,
                          const std::optional<PrimitiveHit>& /*hit*/,
                          const SeenQuadLight* /*light*/) {}
    /// A shadow ray of the path's next event estimation, and whether a surface blocks it.
    virtual void path_shadow_ray(const Ray& /*ray*/, bool /*blocked*/) {}
    /// The full view's colour of the eye ray, with or without a recursion.
    virtual void finished_colour(const Color& /*colour*/) {}
};

/// The observer of a plain render: it watches nothing, and holds nothing, so every thread may
/// share it.
inline PixelObserver& unobserved() {
    static PixelObserver nothing;
    return nothing;
}

}  // namespace raystep
