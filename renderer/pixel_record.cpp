#include "renderer/pixel_record.h"

#include "renderer/local_model.h"

namespace raystep {

void PixelRecorder::camera_ray(const Ray& ray) {
    record_.camera_ray = ray;
}

void PixelRecorder::closest_hit(const Ray& /*ray*/, const std::optional<PrimitiveHit>& hit,
                                const TraversalStats& /*cost*/) {
    record_.hit_searched = true;
    record_.hit = hit;
}

// The eye ray's hit is shaded first: once its local colour is kept, later hits are the
// recursion's.
void PixelRecorder::surface(const SurfacePoint& point, const Material& material) {
    if (record_.local) return;
    point_ = point;
    material_ = material;
}

// Point and directional lights only: the lights a reference trace stores.
void PixelRecorder::light(const LightStep& step) {
    if (record_.local || step.kind == LightKind::spot) return;
    const bool reaches = step.reach == LightReach::reaches;
    record_.lights.push_back(
        {step.reach,
         reaches ? light_term(dialect_, *material_, *point_, step.sample) : Color(0.0)});
}

void PixelRecorder::local_colour(const std::vector<LightSample>& /*reaching*/,
                                 const Color& colour) {
    if (!record_.local) record_.local = colour;
}

void PixelRecorder::finished_colour(const Color& colour) {
    record_.full = colour;
}

}  // namespace raystep
