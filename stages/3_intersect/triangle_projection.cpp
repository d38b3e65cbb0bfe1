// Stage 3: ray-triangle by projection to 2D. Handout: docs/stage3.md.

#include "base/errors/not_implemented.h"
#include "stages/3_intersect/intersect.h"

namespace raystep {

std::optional<Hit> intersect_triangle_projection(const Ray& ray, const Triangle& triangle) {
    // 1. N = (p1 - p0) x (p2 - p0); a zero N is a degenerate triangle: a miss.
    // 2. Intersect the plane through p0 with normal N (as in intersect_plane).
    // 3. Drop the coordinate in which |N| is largest: the triangle's shadow on that coordinate
    //    plane has the largest area, so the 2D test is best conditioned.
    // 4. In 2D, the point is inside when it is on the inner side of all three edges (the 2D
    //    cross product of edge and point has the same sign as the triangle's own, or is 0).
    // 5. beta and gamma are ratios of 2D areas.
    RAYSTEP_TODO(3, "intersect_triangle_projection", "Method 1: project to 2D");
}

}  // namespace raystep
