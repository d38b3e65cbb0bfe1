#pragma once

// Stage 10 calls: the frame, the densities, the BRDF and the heuristics one value at a time; the
// samplers, the light samples and the roulette many at a time, for the grader's histograms and
// means; and path_radiance over a scene the probe plays from the question. The random numbers
// of every sampler are the grader's (each call takes its u); only path_radiance draws its own,
// from RandomStream(seed, stream) for each of the streams asked, and answers one colour per
// stream: the grader judges their mean against a closed form, never a value.

#include <array>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "app/probe/probe_call.h"
#include "grading/10_path_tracing/path_tracing_json.h"
#include "stages/10_path_tracing/path_tracing.h"

namespace raystep::probe {

// --- many directions from one sampler, and its density at many directions

/// The samplers of the stage, each with the density it promises.
enum class Sampler { uniform_hemisphere, cosine_hemisphere, phong_lobe, ggx_half_vector, brdf };

inline constexpr std::array<std::pair<Sampler, const char*>, 5> kSamplerWords{
    {{Sampler::uniform_hemisphere, "uniform_hemisphere"},
     {Sampler::cosine_hemisphere, "cosine_hemisphere"},
     {Sampler::phong_lobe, "phong_lobe"},
     {Sampler::ggx_half_vector, "ggx_half_vector"},
     {Sampler::brdf, "brdf"}}};

template <>
struct JsonCodec<Sampler> : WordCodec<Sampler, kSamplerWords> {};

/// A sampler and what it samples around: `parameter` is phong_lobe's exponent or
/// ggx_half_vector's roughness; sample_brdf takes `brdf`, `normal` and `to_eye`.
struct SamplerSetting {
    Sampler sampler = Sampler::uniform_hemisphere;
    double parameter = 0;
    SurfaceBrdf brdf;
    Vec3 normal{0, 0, 1};
    Vec3 to_eye{0, 0, 1};
};

/// The sampler's direction for each u (sample_brdf's lobe chosen by choices[k]).
struct DirectionsQuestion {
    SamplerSetting setting;
    std::vector<Vec2> us;
    std::vector<double> choices;
};

/// The sampler's density at each direction.
struct DensitiesQuestion {
    SamplerSetting setting;
    std::vector<Vec3> directions;
};

/// sample_light_direction of one light from one point, for each u.
struct LightDirectionsQuestion {
    QuadLight light;
    Vec3 point;
    std::vector<Vec2> us;
};

/// russian_roulette of one throughput, for each u.
struct RouletteQuestion {
    Color throughput{0.0};
    std::vector<double> us;
};

// --- paths through a scene the probe plays

/// The inside of a sphere: every point of it emits `emission` towards the centre's side and
/// reflects by `brdf`.
struct Enclosure {
    Vec3 centre;
    double radius = 1;
    SurfaceBrdf brdf;
    Color emission{0.0};
};

/// The plane through `point` with unit normal `normal`, reflecting by `brdf`, seen from its
/// normal's side.
struct Floor {
    Vec3 point;
    Vec3 normal{0, 1, 0};
    SurfaceBrdf brdf;
};

/// A scene of an enclosure or a floor (or neither) and quad lights, drawn as emitters on their
/// emitting side (ac x ab). Shadow rays are blocked by the enclosure and the floor, never by a
/// light; with `shadows_blocked`, every shadow ray is.
struct PathSceneQuestion {
    std::optional<Enclosure> enclosure;
    std::optional<Floor> floor;
    std::vector<QuadLight> lights;
    bool shadows_blocked = false;
    RayOffset offset;
};

/// path_radiance of `ray` once per stream: `count` streams from `first_stream`, each its own
/// RandomStream(seed, stream).
struct PathsQuestion {
    PathSceneQuestion scene;
    Ray ray;
    PathSettings settings;
    std::uint64_t seed = 0;
    std::uint64_t first_stream = 0;
    int count = 0;
};

template <>
struct JsonFields<SamplerSetting> {
    using S = SamplerSetting;
    static constexpr auto list =
        std::make_tuple(json_field("sampler", &S::sampler), json_field("parameter", &S::parameter),
                        json_field("brdf", &S::brdf), json_field("normal", &S::normal),
                        json_field("to_eye", &S::to_eye));
};

template <>
struct JsonFields<DirectionsQuestion> {
    using Q = DirectionsQuestion;
    static constexpr auto list =
        std::make_tuple(json_field("setting", &Q::setting), json_field("us", &Q::us),
                        json_field("choices", &Q::choices));
};

template <>
struct JsonFields<DensitiesQuestion> {
    using Q = DensitiesQuestion;
    static constexpr auto list = std::make_tuple(json_field("setting", &Q::setting),
                                                 json_field("directions", &Q::directions));
};

template <>
struct JsonFields<LightDirectionsQuestion> {
    using Q = LightDirectionsQuestion;
    static constexpr auto list = std::make_tuple(
        json_field("light", &Q::light), json_field("point", &Q::point), json_field("us", &Q::us));
};

template <>
struct JsonFields<RouletteQuestion> {
    using Q = RouletteQuestion;
    static constexpr auto list =
        std::make_tuple(json_field("throughput", &Q::throughput), json_field("us", &Q::us));
};

template <>
struct JsonFields<Enclosure> {
    static constexpr auto list = std::make_tuple(
        json_field("centre", &Enclosure::centre), json_field("radius", &Enclosure::radius),
        json_field("brdf", &Enclosure::brdf), json_field("emission", &Enclosure::emission));
};

template <>
struct JsonFields<Floor> {
    static constexpr auto list =
        std::make_tuple(json_field("point", &Floor::point), json_field("normal", &Floor::normal),
                        json_field("brdf", &Floor::brdf));
};

template <>
struct JsonFields<PathSceneQuestion> {
    using Q = PathSceneQuestion;
    static constexpr auto list = std::make_tuple(
        json_field("enclosure", &Q::enclosure), json_field("floor", &Q::floor),
        json_field("lights", &Q::lights), json_field("shadows_blocked", &Q::shadows_blocked),
        json_field("offset", &Q::offset));
};

template <>
struct JsonFields<PathsQuestion> {
    using Q = PathsQuestion;
    static constexpr auto list = std::make_tuple(
        json_field("scene", &Q::scene), json_field("ray", &Q::ray),
        json_field("settings", &Q::settings), json_field("seed", &Q::seed),
        json_field("first_stream", &Q::first_stream), json_field("count", &Q::count));
};

std::vector<Vec3> directions_of(const DirectionsQuestion& q);
std::vector<double> densities_of(const DensitiesQuestion& q);
std::vector<LightDirectionSample> light_directions_of(const LightDirectionsQuestion& q);
std::vector<std::optional<Color>> roulette_of(const RouletteQuestion& q);
std::vector<Color> paths_of(const PathsQuestion& q);

/// The scene the question describes, as path_radiance sees it.
PathScene path_scene(const PathSceneQuestion& q);

// --- the calls

inline constexpr auto frame_around_call =
    function_call<Frame(const Vec3&), &frame_around>("frame_around");
inline constexpr auto to_world_call =
    function_call<Vec3(const Frame&, const Vec3&), &to_world>("to_world");
inline constexpr auto to_local_call =
    function_call<Vec3(const Frame&, const Vec3&), &to_local>("to_local");
inline constexpr auto uniform_hemisphere_call =
    function_call<Vec3(const Vec2&), &uniform_hemisphere>("uniform_hemisphere");
inline constexpr auto uniform_hemisphere_pdf_call =
    function_call<double(const Vec3&), &uniform_hemisphere_pdf>("uniform_hemisphere_pdf");
inline constexpr auto cosine_hemisphere_call =
    function_call<Vec3(const Vec2&), &cosine_hemisphere>("cosine_hemisphere");
inline constexpr auto cosine_hemisphere_pdf_call =
    function_call<double(const Vec3&), &cosine_hemisphere_pdf>("cosine_hemisphere_pdf");
inline constexpr auto phong_lobe_call =
    function_call<Vec3(const Vec2&, double), &phong_lobe>("phong_lobe");
inline constexpr auto phong_lobe_pdf_call =
    function_call<double(const Vec3&, double), &phong_lobe_pdf>("phong_lobe_pdf");
inline constexpr auto ggx_distribution_call =
    function_call<double(const Vec3&, double), &ggx_distribution>("ggx_distribution");
inline constexpr auto ggx_half_vector_call =
    function_call<Vec3(const Vec2&, double), &ggx_half_vector>("ggx_half_vector");
inline constexpr auto ggx_half_vector_pdf_call =
    function_call<double(const Vec3&, double), &ggx_half_vector_pdf>("ggx_half_vector_pdf");
inline constexpr auto evaluate_brdf_call =
    function_call<Color(const SurfaceBrdf&, const Vec3&, const Vec3&, const Vec3&), &evaluate_brdf>(
        "evaluate_brdf");
inline constexpr auto specular_probability_call =
    function_call<double(const SurfaceBrdf&), &specular_probability>("specular_probability");
inline constexpr auto sample_brdf_call =
    function_call<Vec3(const SurfaceBrdf&, const Vec3&, const Vec3&, const Vec2&, double),
                  &sample_brdf>("sample_brdf");
inline constexpr auto brdf_pdf_call =
    function_call<double(const SurfaceBrdf&, const Vec3&, const Vec3&, const Vec3&), &brdf_pdf>(
        "brdf_pdf");
inline constexpr auto sample_light_direction_call =
    function_call<LightDirectionSample(const QuadLight&, const Vec3&, const Vec2&),
                  &sample_light_direction>("sample_light_direction");
inline constexpr auto light_direction_pdf_call =
    function_call<double(const QuadLight&, const Vec3&, const Vec3&), &light_direction_pdf>(
        "light_direction_pdf");
inline constexpr auto balance_heuristic_call =
    function_call<double(double, double), &balance_heuristic>("balance_heuristic");
inline constexpr auto power_heuristic_call =
    function_call<double(double, double), &power_heuristic>("power_heuristic");
inline constexpr auto russian_roulette_call =
    function_call<std::optional<Color>(const Color&, double), &russian_roulette>(
        "russian_roulette");

inline constexpr ProbeCall<DirectionsQuestion, std::vector<Vec3>> directions_call{
    "sampled_directions", &directions_of};
inline constexpr ProbeCall<DensitiesQuestion, std::vector<double>> densities_call{
    "sampled_densities", &densities_of};
inline constexpr ProbeCall<LightDirectionsQuestion, std::vector<LightDirectionSample>>
    light_directions_call{"sampled_light_directions", &light_directions_of};
inline constexpr ProbeCall<RouletteQuestion, std::vector<std::optional<Color>>> roulette_call{
    "played_roulettes", &roulette_of};
inline constexpr ProbeCall<PathsQuestion, std::vector<Color>> path_radiance_call{"path_radiance",
                                                                                 &paths_of};

inline constexpr auto path_tracing_calls = std::make_tuple(
    frame_around_call, to_world_call, to_local_call, uniform_hemisphere_call,
    uniform_hemisphere_pdf_call, cosine_hemisphere_call, cosine_hemisphere_pdf_call,
    phong_lobe_call, phong_lobe_pdf_call, ggx_distribution_call, ggx_half_vector_call,
    ggx_half_vector_pdf_call, evaluate_brdf_call, specular_probability_call, sample_brdf_call,
    brdf_pdf_call, sample_light_direction_call, light_direction_pdf_call, balance_heuristic_call,
    power_heuristic_call, russian_roulette_call, directions_call, densities_call,
    light_directions_call, roulette_call, path_radiance_call);

}  // namespace raystep::probe
