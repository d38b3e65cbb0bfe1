// Stage 3: the closest hit over a list. Handout: docs/stage3.md, "The closest hit".

#include "stages/3_intersect/intersect.h"

namespace raystep {

std::optional<PrimitiveHit> closest_hit(const Ray& ray, const PrimitiveList& primitives) {
    // Every test sees t_max cut to the best t so far, so it rejects farther hits itself. The
    // range is closed, so a hit at exactly the best t still comes back, and the strict < keeps
    // the primitive listed first: spheres, then triangles, then planes, each in list order.
    Ray nearer = ray;
    std::optional<PrimitiveHit> best;
    const auto keep = [&](const std::optional<Hit>& hit, PrimitiveKind kind, std::size_t index) {
        if (hit && (!best || hit->t < best->hit.t)) {
            best = PrimitiveHit{*hit, kind, index};
            nearer.t_max = hit->t;
        }
    };
    for (std::size_t k = 0; k < primitives.spheres.size(); ++k) {
        keep(intersect_sphere(nearer, primitives.spheres[k]), PrimitiveKind::sphere, k);
    }
    for (std::size_t k = 0; k < primitives.triangles.size(); ++k) {
        keep(intersect_triangle(nearer, primitives.triangles[k]), PrimitiveKind::triangle, k);
    }
    for (std::size_t k = 0; k < primitives.planes.size(); ++k) {
        keep(intersect_plane(nearer, primitives.planes[k]), PrimitiveKind::plane, k);
    }
    return best;
}

}  // namespace raystep
