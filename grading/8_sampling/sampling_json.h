#pragma once

#include <optional>
#include <string>
#include <vector>

#include "app/protocol/json_codec.h"
#include "base/scene/sample_pattern.h"
#include "base/scene/scene.h"
#include "stages/2_rays/camera.h"
#include "stages/8_sampling/sampling.h"

namespace raystep::probe {

// Stage 8's values as its calls (grading/8_sampling/sampling_calls.h) take and give them, and the
// probe's own pieces of scene they name: the blockers in front of a light and the film radiances
// whose exact means the grader knows. Shared by the probe, which answers with them, and the grader,
// which asks with them and checks the answers against them; none of it is stage code.

/// A pattern by its name in the handout ("jittered", "regular", "random").
template <>
struct JsonCodec<SamplePattern> {
    static Json write(SamplePattern pattern);
    static SamplePattern read(const Json& j);
};

template <>
struct JsonFields<QuadLight> {
    static constexpr auto list = std::make_tuple(
        json_field("corner", &QuadLight::corner), json_field("edge1", &QuadLight::edge1),
        json_field("edge2", &QuadLight::edge2), json_field("radiance", &QuadLight::radiance));
};

/// A camera's fields, its frame's u, v and w among them.
Json perspective_camera(const PerspectiveCamera& camera);
PerspectiveCamera perspective_camera_from(const Json& j);
Json orthographic_camera(const OrthographicCamera& camera);
OrthographicCamera orthographic_camera_from(const Json& j);

template <>
struct JsonCodec<PerspectiveCamera>
    : FunctionCodec<PerspectiveCamera, perspective_camera, perspective_camera_from> {};
template <>
struct JsonCodec<OrthographicCamera>
    : FunctionCodec<OrthographicCamera, orthographic_camera, orthographic_camera_from> {};

/// The parallelogram corner + s edge1 + r edge2, s and r in [0, 1]: a blocker in front of a
/// light, or the floor a pixel sees.
struct Parallelogram {
    Vec3 corner;
    Vec3 edge1;
    Vec3 edge2;
};

template <>
struct JsonFields<Parallelogram> {
    static constexpr auto list = std::make_tuple(json_field("corner", &Parallelogram::corner),
                                                 json_field("edge1", &Parallelogram::edge1),
                                                 json_field("edge2", &Parallelogram::edge2));
};

/// Whether `ray` crosses one of `blockers` within its [t_min, t_max], in double.
bool crosses_any(const std::vector<Parallelogram>& blockers, const Ray& ray);

/// A film radiance the grader can integrate, all three channels alike, by its kind:
/// - "constant": `value` everywhere;
/// - "edge": `bright` where (film - through) . normal >= 0, `dark` elsewhere;
/// - "ramp": value + gradient . film.
struct FilmRadianceModel {
    std::string kind;
    std::optional<double> value;
    std::optional<Vec2> through;
    std::optional<Vec2> normal;
    std::optional<double> bright;
    std::optional<double> dark;
    std::optional<Vec2> gradient;
};

template <>
struct JsonFields<FilmRadianceModel> {
    static constexpr auto list =
        std::make_tuple(json_field("kind", &FilmRadianceModel::kind),
                        json_field("value", &FilmRadianceModel::value),
                        json_field("through", &FilmRadianceModel::through),
                        json_field("normal", &FilmRadianceModel::normal),
                        json_field("bright", &FilmRadianceModel::bright),
                        json_field("dark", &FilmRadianceModel::dark),
                        json_field("gradient", &FilmRadianceModel::gradient));
};

/// The model as a FilmRadiance; throws std::invalid_argument for an unknown kind or a field its
/// kind needs left out.
FilmRadiance film_radiance(const FilmRadianceModel& model);

/// A shadow ray as quad_light_shading traced it, and what the blockers answered.
struct TracedShadowRay {
    Ray ray;
    bool blocked = false;
};

template <>
struct JsonFields<TracedShadowRay> {
    static constexpr auto list = std::make_tuple(json_field("ray", &TracedShadowRay::ray),
                                                 json_field("blocked", &TracedShadowRay::blocked));
};

}  // namespace raystep::probe
