#include "studies/structures/bench_structure.h"

namespace raystep {

BenchHit bench_hit(const std::optional<PrimitiveHit>& hit, std::size_t sphere_count,
                   std::size_t triangle_count) {
    if (!hit) return {};
    std::size_t number = hit->index;
    if (hit->kind != PrimitiveKind::sphere) number += sphere_count;
    if (hit->kind == PrimitiveKind::plane) number += triangle_count;
    return {static_cast<std::uint32_t>(number), hit->hit.t};
}

}  // namespace raystep
