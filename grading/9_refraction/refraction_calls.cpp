// The fake scene of stage 9's radiance_with_refraction call: a ray lands on the hit whose key it
// is nearest, within a radius in origin and in direction.

#include "grading/9_refraction/refraction_calls.h"

#include <glm/geometric.hpp>

namespace raystep::probe {

namespace {

// How near a ray must be to a hit's key to land on it. The grader's scenes keep keys from
// different hits at least 10 apart in origin, and the two rays that leave one hit at least 0.1
// apart in direction (grading/9_refraction/stage9_radiance_cases.cpp), so that a
// right ray finds its own hit and nothing else; a wrong one within these bounds finds it too and
// is judged wrong by its origin or direction, one beyond them misses.
constexpr double kKeyOriginRadius = 1.0;
constexpr double kKeyDirectionRadius = 0.01;

std::optional<MediumHit> hit_for(const std::vector<KeyedHit>& scene, const Ray& ray) {
    const KeyedHit* nearest = nullptr;
    double nearest_turn = kKeyDirectionRadius;
    for (const KeyedHit& entry : scene) {
        // Written so that a NaN ray lands nowhere
        if (!(glm::length(ray.origin - entry.key.origin) <= kKeyOriginRadius)) continue;
        const double turn = glm::length(ray.direction - entry.key.direction);
        if (turn <= nearest_turn) {
            nearest = &entry;
            nearest_turn = turn;
        }
    }
    if (nearest == nullptr) return std::nullopt;
    return nearest->hit;
}

}  // namespace

RadianceAnswer radiance_over_keyed_scene(const RefractionRadianceQuestion& question) {
    RadianceAnswer answer;
    const MediumShadeFunction shade = [&](const Ray& r) {
        answer.rays.push_back(r);
        return hit_for(question.scene, r);
    };
    answer.colour = radiance_with_refraction(shade, question.ray, question.bounces, question.inside,
                                             question.schlick, question.offset);
    return answer;
}

}  // namespace raystep::probe
