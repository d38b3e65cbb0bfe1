#pragma once

#include <cstdint>
#include <cstring>
#include <optional>
#include <vector>

#include "base/math/fnv1a.h"
#include "base/math/portable_random.h"
#include "stages/3_intersect/intersect.h"

namespace raystep::probe {

// A timed stage-4 walk, the same in the probe, which runs the submission's structure, and in the
// grader, which runs the reference's to know the answer the probe must give: pass after pass of
// the base rays, each pass's moved a little by numbers of its own (so that no ray is asked twice),
// each ray asked for its closest hit and, cut short before the scene, whether anything occludes
// it. The answer is a digest of every answer: it cannot be given without finding every hit, and
// it is checked against the reference's, never taken as said.

/// How far each pass moves the base rays: every origin coordinate by up to `origin`, every
/// direction component by up to `direction`, drawn from PortableRandom(seed, pass).
struct Jitter {
    std::uint64_t seed = 0;
    double origin = 0.0;
    double direction = 0.0;
};

/// The base rays as pass `pass` asks them.
inline void move_rays(const std::vector<Ray>& base, const Jitter& jitter, int pass,
                      std::vector<Ray>& moved) {
    PortableRandom random(jitter.seed, static_cast<std::uint64_t>(pass));
    moved = base;
    for (Ray& ray : moved) {
        ray.origin = ray.origin + jitter.origin * random.point(1.0);
        ray.direction = ray.direction + jitter.direction * random.point(1.0);
    }
}

/// Folds one word into a digest (FNV-1a over 64-bit words, base/math/fnv1a.h).
inline std::uint64_t fold(std::uint64_t digest, std::uint64_t word) {
    return fnv1a_fold(digest, word);
}

/// The digest of no answer.
inline constexpr std::uint64_t kEmptyDigest = kFnv1aBasis;

/// Folds a closest hit: its primitive and the bits of its t, or a miss.
inline std::uint64_t fold_hit(std::uint64_t digest, const std::optional<PrimitiveHit>& hit) {
    if (!hit) return fold(digest, ~0ull);
    std::uint64_t t_bits = 0;
    std::memcpy(&t_bits, &hit->hit.t, sizeof t_bits);
    return fold(fold(digest, (std::uint64_t(hit->kind) << 32) ^ hit->index), t_bits);
}

/// `passes` passes of the walk through `structure` (anything with closest_hit(ray) and
/// occluded(ray)): the base rays' closest hits and the shadow rays' occlusion, every ray moved by
/// its pass's numbers. The digest of every answer, in order.
template <class Structure>
std::uint64_t timed_walk(const Structure& structure, const std::vector<Ray>& rays,
                         const std::vector<Ray>& shadow_rays, const Jitter& jitter, int passes) {
    std::uint64_t digest = kEmptyDigest;
    std::vector<Ray> moved;
    std::vector<Ray> moved_shadows;
    for (int pass = 0; pass < passes; ++pass) {
        move_rays(rays, jitter, pass, moved);
        move_rays(shadow_rays, jitter, pass, moved_shadows);
        for (const Ray& ray : moved)
            digest = fold_hit(digest, structure.closest_hit(ray));
        for (const Ray& ray : moved_shadows)
            digest = fold(digest, structure.occluded(ray) ? 1 : 0);
    }
    return digest;
}

}  // namespace raystep::probe
