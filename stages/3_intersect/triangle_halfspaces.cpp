// Stage 3: ray-triangle by 3D half-spaces. Handout: docs/stage3.md.

#include "base/errors/not_implemented.h"
#include "stages/1_vectors/vectors.h"
#include "stages/3_intersect/intersect.h"

namespace raystep {

std::optional<Hit> intersect_triangle_halfspaces(const Ray& ray, const Triangle& triangle) {
    // 1. Intersect the triangle's plane, as in method 1, to get the point P.
    // 2. For each edge, its inward normal is the part of (opposite vertex - edge start)
    //    perpendicular to the edge: your perpendicular_to from stage 1. For the edge p2 -> p1:
    //      n = (p0 - p2) - ((p0 - p2) . e^) e^,   e^ = (p1 - p2) / |p1 - p2|.
    // 3. P is inside when (P - edge start) . n >= 0 for all three edges.
    // 4. The barycentric weight of the opposite vertex is (P - edge start) . n divided by
    //    (opposite vertex - edge start) . n: how far P is from the edge, as a fraction.
    RAYSTEP_TODO(3, "intersect_triangle_halfspaces", "Method 2: 3D half-spaces");
}

}  // namespace raystep
