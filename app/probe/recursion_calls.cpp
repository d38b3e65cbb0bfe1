// Stage 7 calls: the mirror ray, and radiance over a scripted scene. The script lists what shade
// returns on each call in turn (a shaded hit, or null for a miss; past its end, misses); the
// answer is the colour and every ray radiance asked about, so that the grader can check the
// recursion's order, depth and rays without a scene.

#include "app/probe/call_table.h"
#include "stages/7_recursion/recursion.h"

namespace raystep::probe {

namespace {

std::optional<ShadedHit> shaded_hit_from(const Json& j) {
    if (j.is_null()) return std::nullopt;
    return ShadedHit{surface_point_from(j.at("point")), vec3_from(j.at("local")),
                     vec3_from(j.at("reflectance"))};
}

}  // namespace

void add_recursion_calls(CallTable& table) {
    table["reflected_ray"] = [](const Json& a) {
        return ray(reflected_ray(surface_point_from(a.at(0)), ray_offset_from(a.at(1))));
    };
    table["radiance"] = [](const Json& a) {
        std::vector<std::optional<ShadedHit>> script;
        for (const Json& step : a.at("script"))
            script.push_back(shaded_hit_from(step));
        Json asked = Json::array();
        std::size_t next = 0;
        const ShadeFunction shade = [&](const Ray& r) -> std::optional<ShadedHit> {
            asked.push_back(ray(r));
            return next < script.size() ? script[next++] : std::nullopt;
        };
        const Color colour = radiance(shade, ray_from(a.at("ray")), a.at("bounces").get<int>(),
                                      ray_offset_from(a.at("offset")));
        return Json{{"colour", vec3(colour)}, {"rays", asked}};
    };
}

}  // namespace raystep::probe
