// Stage 3 reference solution: the triangle test the renderer uses.

#include "solutions/3_intersect/intersect_methods.h"

namespace raystep {

// The watertight test: the lecture methods can let a ray slip between two triangles that share
// an edge (docs/stage3.md measures how often), and a reference image must not have such holes.
std::optional<Hit> intersect_triangle(const Ray& ray, const Triangle& triangle) {
    return intersect_triangle_watertight(ray, triangle);
}

}  // namespace raystep
