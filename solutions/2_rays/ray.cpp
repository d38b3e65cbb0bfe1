// Stage 2 reference solution: rays.

#include "stages/2_rays/ray.h"

namespace raystep {

Vec3 Ray::at(double t) const {
    return origin + t * direction;
}

}  // namespace raystep
