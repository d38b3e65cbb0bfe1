// Stage 10: sampling a quad light by solid angle, for next event estimation. Handout:
// docs/stage10.md.

#include "base/errors/not_implemented.h"
#include "stages/10_path_tracing/path_tracing.h"

namespace raystep {

LightDirectionSample sample_light_direction(const QuadLight& light, const Vec3& point,
                                            const Vec2& u) {
    // y = a + u.x ab + u.y ac; p(w) = d^2 / (A |cos(theta_l)|); radiance only from the side
    // ac x ab faces.
    RAYSTEP_TODO(10, "sample_light_direction", "Next event estimation");
}

double light_direction_pdf(const QuadLight& light, const Vec3& point, const Vec3& direction) {
    // Where the ray meets the light: d^2 / (A |cos(theta_l)|); 0 where it misses.
    RAYSTEP_TODO(10, "light_direction_pdf", "Next event estimation");
}

}  // namespace raystep
