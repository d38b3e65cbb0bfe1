#pragma once

// Stage 7 calls: the mirror ray, and radiance over a scripted scene. The script lists what shade
// returns on each call in turn (a shaded hit, or a miss; past its end, misses); the answer is the
// colour and every ray radiance asked about, so that the grader can check the recursion's order,
// depth and rays without a scene.

#include <optional>
#include <vector>

#include "app/probe/probe_call.h"
#include "stages/7_recursion/recursion.h"

namespace raystep::probe {

/// What shade returns on each call in turn: a shaded hit, or nullopt for a miss.
using ShadeScript = std::vector<std::optional<ShadedHit>>;

struct RadianceQuestion {
    ShadeScript script;
    Ray ray;
    int bounces = 0;
    RayOffset offset;
};

/// What radiance saw, here and in stage 9 (radiance_with_refraction).
struct RadianceAnswer {
    Color colour;
    std::vector<Ray> rays;  ///< every ray radiance asked shade about, in order
};

/// A shaded hit {"point", "local", "reflectance"}; a miss in the script is null.
template <>
struct JsonFields<ShadedHit> {
    static constexpr auto list = std::make_tuple(
        json_field("point", &ShadedHit::point), json_field("local", &ShadedHit::local),
        json_field("reflectance", &ShadedHit::reflectance));
};

template <>
struct JsonFields<RadianceQuestion> {
    static constexpr auto list = std::make_tuple(json_field("script", &RadianceQuestion::script),
                                                 json_field("ray", &RadianceQuestion::ray),
                                                 json_field("bounces", &RadianceQuestion::bounces),
                                                 json_field("offset", &RadianceQuestion::offset));
};

template <>
struct JsonFields<RadianceAnswer> {
    static constexpr auto list = std::make_tuple(json_field("colour", &RadianceAnswer::colour),
                                                 json_field("rays", &RadianceAnswer::rays));
};

inline constexpr auto reflected_ray_call =
    function_call<Ray(const SurfacePoint&, const RayOffset&), &reflected_ray>("reflected_ray");

/// radiance with shade answering from the question's script.
inline RadianceAnswer radiance_over_script(const RadianceQuestion& q) {
    RadianceAnswer answer;
    std::size_t next = 0;
    const ShadeFunction shade = [&](const Ray& r) -> std::optional<ShadedHit> {
        answer.rays.push_back(r);
        return next < q.script.size() ? q.script[next++] : std::nullopt;
    };
    answer.colour = radiance(shade, q.ray, q.bounces, q.offset);
    return answer;
}

inline constexpr ProbeCall<RadianceQuestion, RadianceAnswer> radiance_call{"radiance",
                                                                           &radiance_over_script};

inline constexpr auto recursion_calls = std::make_tuple(reflected_ray_call, radiance_call);

}  // namespace raystep::probe
