// Stage 2: rays. Handout: docs/stage2.md.

#include "stages/2_rays/ray.h"

#include "base/errors/not_implemented.h"

namespace raystep {

Vec3 Ray::at(double t) const {
    // R(t) = A + t D: start at the origin and walk t times the direction.
    RAYSTEP_TODO(2, "Ray::at", "Rays");
}

}  // namespace raystep
