#pragma once

#include <optional>
#include <vector>

#include "renderer/pixel_observer.h"
#include "renderer/render_scene.h"
#include "renderer/view.h"

namespace raystep {

/// One point or directional light at the eye ray's hit: whether it reaches the point and, when
/// it does, its term in the scene's local model (local_model.h's light_term: stage 6's
/// blinn_phong in the CSE167 dialect; diffuse and specular together; 0 otherwise).
struct LightRecord {
    LightReach reach = LightReach::behind;
    Color term{0.0};
};

/// The values of one pixel's steps, in the order the renderer takes them: what `raystep trace
/// --compare` holds against the reference's, and what a student release ships of the reference
/// for each pixel of its scenes. A PixelRecorder fills it as far as the render gets: a step it
/// did not reach (a stub stopped it, or the view does not go that far) stays empty.
struct PixelRecord {
    std::optional<Ray> camera_ray;
    bool hit_searched = false;        ///< closest_hit ran; `hit` is its answer
    std::optional<PrimitiveHit> hit;  ///< the eye ray's closest hit; empty on a miss
    std::vector<LightRecord> lights;  ///< point lights, then directional, in scene order
    std::optional<Color> local;       ///< stage 6's colour at the hit
    std::optional<Color> full;        ///< the finished colour, reflections included
};

/// Watches a pixel's render and keeps its values in a PixelRecord: the eye ray's steps only (the
/// shading of a later ray is not compared), and for a sampled pixel those of the ray through its
/// centre, as at one sample per pixel, so that a student's record can be held against the
/// reference's whatever order the samples come in.
class PixelRecorder final : public PixelObserver {
  public:
    PixelRecorder(PixelRecord& record, SceneDialect dialect) : record_(record), dialect_(dialect) {}

    bool watches_centre_ray() const override { return true; }
    void camera_ray(const Ray& ray) override;
    void closest_hit(const Ray& ray, const std::optional<PrimitiveHit>& hit,
                     const TraversalStats& cost) override;
    void surface(const SurfacePoint& point, const Material& material) override;
    void light(const LightStep& step) override;
    void local_colour(const std::vector<LightSample>& reaching, const Color& colour) override;
    void finished_colour(const Color& colour) override;

  private:
    PixelRecord& record_;
    SceneDialect dialect_;
    std::optional<SurfacePoint> point_;  ///< the eye ray's hit being shaded
    std::optional<Material> material_;   ///< a copy: shading may hand in a mapped one
};

/// How far a view takes a pixel through the pipeline, and so which parts of a record it fills:
/// rays stops at the camera ray; depth, normal, barycentric, cost, uv and tangent at the closest
/// hit; shaded adds the lights and the local colour; full the finished colour.
enum class PipelineReach { camera_ray, closest_hit, shading, full_colour };

/// The reach of a view.
constexpr PipelineReach pipeline_reach(View view) {
    switch (view) {
        case View::rays:
            return PipelineReach::camera_ray;
        case View::shaded:
            return PipelineReach::shading;
        case View::full:
        case View::indirect:
            return PipelineReach::full_colour;
        default:
            return PipelineReach::closest_hit;
    }
}

}  // namespace raystep
