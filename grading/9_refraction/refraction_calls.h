#pragma once

// Stage 9 calls: Snell's law, the Fresnel reflectances, the media, the refracted ray, and
// radiance_with_refraction over a fake scene. The fake scene answers a ray by what it is, not by
// when it is asked: each of its hits is keyed by the ray that should reach it (an origin and a
// direction), so that a recursion that follows the refracted ray before the reflected one, or
// walks the tree with a loop and a stack of its own, meets the same scene. The answer is the
// colour and every ray radiance asked about, in the order asked; the grader judges the rays as a
// set.

#include <optional>
#include <vector>

#include "app/probe/probe_call.h"
#include "grading/7_recursion/recursion_calls.h"
#include "grading/9_refraction/refraction_json.h"
#include "stages/9_refraction/refraction.h"

namespace raystep::probe {

template <>
struct JsonCodec<Medium> : FunctionCodec<Medium, medium, medium_from> {};
template <>
struct JsonCodec<MediumStack> : FunctionCodec<MediumStack, media, media_from> {};
template <>
struct JsonCodec<MediumHit> : FunctionCodec<MediumHit, medium_hit, medium_hit_from> {};

/// A hit of the fake scene, and the ray that lands on it.
struct KeyedHit {
    Ray key;
    MediumHit hit;
};

struct RefractionRadianceQuestion {
    std::vector<KeyedHit> scene;
    Ray ray;
    int bounces = 0;
    MediumStack inside;
    bool schlick = false;
    RayOffset offset;
};

template <>
struct JsonFields<KeyedHit> {
    static constexpr auto list =
        std::make_tuple(json_field("key", &KeyedHit::key), json_field("hit", &KeyedHit::hit));
};

template <>
struct JsonFields<RefractionRadianceQuestion> {
    using Q = RefractionRadianceQuestion;
    static constexpr auto list =
        std::make_tuple(json_field("scene", &Q::scene), json_field("ray", &Q::ray),
                        json_field("bounces", &Q::bounces), json_field("inside", &Q::inside),
                        json_field("schlick", &Q::schlick), json_field("offset", &Q::offset));
};

/// radiance_with_refraction with shade answering from the question's keyed scene.
RadianceAnswer radiance_over_keyed_scene(const RefractionRadianceQuestion& question);

inline constexpr auto refract_call =
    function_call<std::optional<Vec3>(const Vec3&, const Vec3&, double), &refract>("refract");
inline constexpr auto fresnel_exact_call =
    function_call<double(double, double, double), &fresnel_exact>("fresnel_exact");
inline constexpr auto fresnel_schlick_call =
    function_call<double(double, double, double), &fresnel_schlick>("fresnel_schlick");
inline constexpr auto current_index_call =
    function_call<double(const MediumStack&), &current_index>("current_index");
inline constexpr auto after_crossing_call =
    function_call<MediumStack(const MediumStack&, const Medium&, bool), &after_crossing>(
        "after_crossing");
inline constexpr auto refracted_ray_call =
    function_call<std::optional<Ray>(const SurfacePoint&, double, double, const RayOffset&),
                  &refracted_ray>("refracted_ray");
inline constexpr ProbeCall<RefractionRadianceQuestion, RadianceAnswer>
    radiance_with_refraction_call{"radiance_with_refraction", &radiance_over_keyed_scene};

inline constexpr auto refraction_calls =
    std::make_tuple(refract_call, fresnel_exact_call, fresnel_schlick_call, current_index_call,
                    after_crossing_call, refracted_ray_call, radiance_with_refraction_call);

}  // namespace raystep::probe
