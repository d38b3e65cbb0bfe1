// Stage 2: rays. Handout: docs/stage2.md.

#include "stages/2_rays/ray.h"

namespace raystep {

Vec3 Ray::at(double t) const {
    return origin + t * direction;
}

}  // namespace raystep
