// Stage 3: ray-triangle by Cramer's rule. Handout: docs/stage3.md.

#include "base/errors/not_implemented.h"
#include "stages/3_intersect/intersect.h"

namespace raystep {

std::optional<Hit> intersect_triangle_cramer(const Ray& ray, const Triangle& triangle) {
    // A + t D = p0 + beta (p1 - p0) + gamma (p2 - p0) is three linear equations in beta, gamma
    // and t:  beta (p0 - p1) + gamma (p0 - p2) + t D = p0 - A.
    // With M the matrix of columns (p0 - p1, p0 - p2, D), Cramer's rule gives each unknown as
    // det(M with that column replaced by p0 - A) / det(M), and det[a b c] = a . (b x c).
    // det(M) = 0: parallel ray or degenerate triangle, a miss. Leave as soon as t is outside
    // [t_min, t_max], gamma outside [0, 1] or beta outside [0, 1 - gamma].
    RAYSTEP_TODO(3, "intersect_triangle_cramer", "Method 3: Cramer's rule");
}

}  // namespace raystep
