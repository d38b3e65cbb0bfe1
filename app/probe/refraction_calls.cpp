// Stage 9 calls: Snell's law, the Fresnel reflectances, the media, the refracted ray, and
// radiance_with_refraction over a fake scene. The fake scene answers a ray by what it is, not by
// when it is asked: each of its hits is keyed by the ray that should reach it (an origin and a
// direction), so that a recursion that follows the refracted ray before the reflected one, or
// walks the tree with a loop and a stack of its own, meets the same scene. The answer is the
// colour and every ray radiance asked about, in the order asked; the grader judges the rays as a
// set.

#include <cmath>
#include <optional>

#include <glm/geometric.hpp>

#include "app/probe/call_table.h"
#include "app/protocol/refraction_json.h"
#include "stages/9_refraction/refraction.h"

namespace raystep::probe {

namespace {

// How near a ray must be to a hit's key to land on it. The grader's scenes keep keys from
// different hits at least 10 apart in origin, and the two rays that leave one hit at least 0.1
// apart in direction (grader/grade/checks/stage9_radiance_cases.cpp), so that a
// right ray finds its own hit and nothing else; a wrong one within these bounds finds it too and
// is judged wrong by its origin or direction, one beyond them misses.
constexpr double kKeyOriginRadius = 1.0;
constexpr double kKeyDirectionRadius = 0.01;

struct KeyedHit {
    Ray key;
    MediumHit hit;
};

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

Json optional_vec3(const std::optional<Vec3>& v) {
    return v ? vec3(*v) : Json(nullptr);
}

}  // namespace

void add_refraction_calls(CallTable& table) {
    table["refract"] = [](const Json& a) {
        return optional_vec3(refract(vec3_from(a.at(0)), vec3_from(a.at(1)), number_from(a.at(2))));
    };
    table["fresnel_exact"] = [](const Json& a) {
        return number(
            fresnel_exact(number_from(a.at(0)), number_from(a.at(1)), number_from(a.at(2))));
    };
    table["fresnel_schlick"] = [](const Json& a) {
        return number(
            fresnel_schlick(number_from(a.at(0)), number_from(a.at(1)), number_from(a.at(2))));
    };
    table["current_index"] = [](const Json& a) {
        return number(current_index(media_from(a.at(0))));
    };
    table["after_crossing"] = [](const Json& a) {
        const Json& entering = a.at(2);
        if (!entering.is_boolean()) throw std::invalid_argument("expected entering true or false");
        return media(
            after_crossing(media_from(a.at(0)), medium_from(a.at(1)), entering.get<bool>()));
    };
    table["refracted_ray"] = [](const Json& a) {
        const std::optional<Ray> r =
            refracted_ray(surface_point_from(a.at(0)), number_from(a.at(1)), number_from(a.at(2)),
                          ray_offset_from(a.at(3)));
        return r ? ray(*r) : Json(nullptr);
    };
    table["radiance_with_refraction"] = [](const Json& a) {
        std::vector<KeyedHit> scene;
        for (const Json& entry : a.at("scene"))
            scene.push_back({ray_from(entry.at("key")), medium_hit_from(entry.at("hit"))});
        const Json& schlick = a.at("schlick");
        if (!schlick.is_boolean()) throw std::invalid_argument("expected schlick true or false");
        Json asked = Json::array();
        const MediumShadeFunction shade = [&](const Ray& r) {
            asked.push_back(ray(r));
            return hit_for(scene, r);
        };
        const Color colour = radiance_with_refraction(
            shade, ray_from(a.at("ray")), a.at("bounces").get<int>(), media_from(a.at("inside")),
            schlick.get<bool>(), ray_offset_from(a.at("offset")));
        return Json{{"colour", vec3(colour)}, {"rays", asked}};
    };
}

}  // namespace raystep::probe
