// Stage 3 reference solution: the closest hit over a list.

#include "solutions/3_intersect/hit_building.h"

namespace raystep {

std::optional<PrimitiveHit> closest_hit(const Ray& ray, const PrimitiveList& primitives) {
    // Every test sees t_max shrunk to the best t so far, so it rejects farther hits itself. A hit
    // at exactly the best t is still returned by the test (the range is closed), and the strict
    // < keeps the earlier primitive: ties go to spheres, then triangles, then planes, each in
    // list order, the order the contract promises.
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
