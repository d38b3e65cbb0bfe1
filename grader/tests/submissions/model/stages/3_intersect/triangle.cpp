// Stage 3: the triangle test the renderer uses. Handout: docs/stage3.md, "Which test to use".

#include "stages/3_intersect/intersect.h"

namespace raystep {

std::optional<Hit> intersect_triangle(const Ray& ray, const Triangle& triangle) {
    // Cramer's rule: no plane to intersect first, so it is right on slivers too.
    return intersect_triangle_cramer(ray, triangle);
}

}  // namespace raystep
