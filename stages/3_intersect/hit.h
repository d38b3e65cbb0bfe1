#pragma once

#include "base/math/types.h"

namespace raystep {

/// Where a ray meets a primitive.
struct Hit {
    double t;     ///< the ray parameter of the hit point: the point is ray.at(t)
    Vec3 normal;  ///< unit geometric normal, never flipped towards the ray: outward for a sphere,
                  ///< (p1 - p0) x (p2 - p0) normalized for a triangle, the plane's normal
    /// Barycentric coordinates of the hit on a triangle, p = (1 - beta - gamma) p0 + beta p1 +
    /// gamma p2; both 0 for spheres and planes.
    double beta = 0.0;
    double gamma = 0.0;
};

}  // namespace raystep
