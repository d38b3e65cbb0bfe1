#pragma once

// Stage 8 calls: sample patterns, rays through film points, a pixel's mean and a quad light's
// soft shadow. The random calls take the render's seed and a list of stream numbers and answer
// one result per stream, each from its own RandomStream(seed, stream): the grader asks for
// hundreds of streams in one query and judges the distribution of what comes back, never the
// values, since a student may consume a stream in any order. The film radiance and the blockers
// are the probe's own, made from the question, so that the grader knows the exact integral each
// mean estimates. Where the student's code asks them something, the answer hands back what it
// asked (the film points, the shadow rays) as data, never a count: the grader checks that data
// against its own scene and derives every figure from it, since a count kept in this process is
// only what the student's code, which runs here too, lets it be.

#include <cstdint>
#include <vector>

#include <glm/geometric.hpp>

#include "app/probe/probe_call.h"
#include "grading/8_sampling/sampling_json.h"
#include "stages/8_sampling/sampling.h"

namespace raystep::probe {

// --- the questions and answers; a random call's answer is a list, one entry per stream

struct RegularSamplesQuestion {
    int strata = 0;
};

struct JitteredSamplesQuestion {
    int strata = 0;
    std::uint64_t seed = 0;
    std::vector<std::uint64_t> streams;
};

struct RandomSamplesQuestion {
    int count = 0;
    std::uint64_t seed = 0;
    std::vector<std::uint64_t> streams;
};

struct SamplesQuestion {
    SamplePattern pattern = SamplePattern::jittered;
    int count = 0;
    std::uint64_t seed = 0;
    std::vector<std::uint64_t> streams;
};

/// Rays through film points, one per point, in order.
template <class Camera>
struct RaysThroughQuestion {
    Camera camera;
    std::vector<Vec2> films;
};

/// pixel_colour of pixel (i, j) over the model's radiance.
struct PixelColourQuestion {
    FilmRadianceModel radiance;
    int i = 0;
    int j = 0;
    SamplePattern pattern = SamplePattern::jittered;
    int count = 0;
    std::uint64_t seed = 0;
    std::vector<std::uint64_t> streams;
};

/// A stream's pixel colour, and the film points the radiance was asked about, in order.
struct PixelColourAnswer {
    Color colour;
    std::vector<Vec2> films;
};

struct SampleQuadLightQuestion {
    QuadLight light;
    Vec3 point;
    Vec2 u;
    int sample_count = 0;
};

/// quad_light_shading, a shadow ray blocked where it crosses one of `blockers`.
struct QuadLightShadingQuestion {
    Material material;
    SurfacePoint point;
    QuadLight light;
    SamplePattern pattern = SamplePattern::jittered;
    int count = 0;
    std::vector<Parallelogram> blockers;
    RayOffset offset;
    std::uint64_t seed = 0;
    std::vector<std::uint64_t> streams;
};

/// A stream's colour, and the shadow rays traced, in order.
struct QuadLightShadingAnswer {
    Color colour;
    std::vector<TracedShadowRay> shadow_rays;
};

/// A pixel of a floor under a quad light: pixel_colour over a film radiance that shades the
/// floor point under each film point (floor_point_under) with quad_light_shading, nothing
/// blocking. Each stream is the pixel's one stream, handed to pixel_colour and then to every
/// quad_light_shading in turn, as a RandomStream& parameter promises a caller may: right code
/// draws new numbers for every film sample's light samples.
struct LitPixelQuestion {
    int i = 0;
    int j = 0;
    SamplePattern pattern = SamplePattern::jittered;
    int count = 0;
    Parallelogram floor;
    Vec3 to_eye;
    Material material;
    QuadLight light;
    SamplePattern light_pattern = SamplePattern::jittered;
    int light_count = 0;
    RayOffset offset;
    std::uint64_t seed = 0;
    std::vector<std::uint64_t> streams;
};

/// The floor point the film point (i + x, j + y) sees: corner + x edge1 + y edge2, its normal
/// edge1 x edge2 normalized, seen from `to_eye`.
inline SurfacePoint floor_point_under(const LitPixelQuestion& q, const Vec2& film) {
    const Vec3 normal = glm::normalize(glm::cross(q.floor.edge1, q.floor.edge2));
    return {q.floor.corner + (film.x - q.i) * q.floor.edge1 + (film.y - q.j) * q.floor.edge2,
            Vec3(0.0), normal, normal, q.to_eye};
}

/// A film sample of a lit pixel: its film point and the shadow rays its shading traced.
struct LitFilmSample {
    Vec2 film;
    std::vector<TracedShadowRay> shadow_rays;
};

/// A stream's pixel colour and its film samples, in order.
struct LitPixelAnswer {
    Color colour;
    std::vector<LitFilmSample> films;
};

template <>
struct JsonFields<RegularSamplesQuestion> {
    static constexpr auto list =
        std::make_tuple(json_field("strata", &RegularSamplesQuestion::strata));
};

template <>
struct JsonFields<JitteredSamplesQuestion> {
    static constexpr auto list =
        std::make_tuple(json_field("strata", &JitteredSamplesQuestion::strata),
                        json_field("seed", &JitteredSamplesQuestion::seed),
                        json_field("streams", &JitteredSamplesQuestion::streams));
};

template <>
struct JsonFields<RandomSamplesQuestion> {
    static constexpr auto list =
        std::make_tuple(json_field("count", &RandomSamplesQuestion::count),
                        json_field("seed", &RandomSamplesQuestion::seed),
                        json_field("streams", &RandomSamplesQuestion::streams));
};

template <>
struct JsonFields<SamplesQuestion> {
    static constexpr auto list = std::make_tuple(json_field("pattern", &SamplesQuestion::pattern),
                                                 json_field("count", &SamplesQuestion::count),
                                                 json_field("seed", &SamplesQuestion::seed),
                                                 json_field("streams", &SamplesQuestion::streams));
};

template <class Camera>
struct JsonFields<RaysThroughQuestion<Camera>> {
    static constexpr auto list =
        std::make_tuple(json_field("camera", &RaysThroughQuestion<Camera>::camera),
                        json_field("films", &RaysThroughQuestion<Camera>::films));
};

template <>
struct JsonFields<PixelColourQuestion> {
    static constexpr auto list = std::make_tuple(
        json_field("radiance", &PixelColourQuestion::radiance),
        json_field("i", &PixelColourQuestion::i), json_field("j", &PixelColourQuestion::j),
        json_field("pattern", &PixelColourQuestion::pattern),
        json_field("count", &PixelColourQuestion::count),
        json_field("seed", &PixelColourQuestion::seed),
        json_field("streams", &PixelColourQuestion::streams));
};

template <>
struct JsonFields<PixelColourAnswer> {
    static constexpr auto list = std::make_tuple(json_field("colour", &PixelColourAnswer::colour),
                                                 json_field("films", &PixelColourAnswer::films));
};

template <>
struct JsonFields<SampleQuadLightQuestion> {
    static constexpr auto list =
        std::make_tuple(json_field("light", &SampleQuadLightQuestion::light),
                        json_field("point", &SampleQuadLightQuestion::point),
                        json_field("u", &SampleQuadLightQuestion::u),
                        json_field("sample_count", &SampleQuadLightQuestion::sample_count));
};

template <>
struct JsonFields<QuadLightShadingQuestion> {
    static constexpr auto list =
        std::make_tuple(json_field("material", &QuadLightShadingQuestion::material),
                        json_field("point", &QuadLightShadingQuestion::point),
                        json_field("light", &QuadLightShadingQuestion::light),
                        json_field("pattern", &QuadLightShadingQuestion::pattern),
                        json_field("count", &QuadLightShadingQuestion::count),
                        json_field("blockers", &QuadLightShadingQuestion::blockers),
                        json_field("offset", &QuadLightShadingQuestion::offset),
                        json_field("seed", &QuadLightShadingQuestion::seed),
                        json_field("streams", &QuadLightShadingQuestion::streams));
};

template <>
struct JsonFields<QuadLightShadingAnswer> {
    static constexpr auto list =
        std::make_tuple(json_field("colour", &QuadLightShadingAnswer::colour),
                        json_field("shadow_rays", &QuadLightShadingAnswer::shadow_rays));
};

template <>
struct JsonFields<LitPixelQuestion> {
    static constexpr auto list = std::make_tuple(
        json_field("i", &LitPixelQuestion::i), json_field("j", &LitPixelQuestion::j),
        json_field("pattern", &LitPixelQuestion::pattern),
        json_field("count", &LitPixelQuestion::count),
        json_field("floor", &LitPixelQuestion::floor),
        json_field("to_eye", &LitPixelQuestion::to_eye),
        json_field("material", &LitPixelQuestion::material),
        json_field("light", &LitPixelQuestion::light),
        json_field("light_pattern", &LitPixelQuestion::light_pattern),
        json_field("light_count", &LitPixelQuestion::light_count),
        json_field("offset", &LitPixelQuestion::offset),
        json_field("seed", &LitPixelQuestion::seed),
        json_field("streams", &LitPixelQuestion::streams));
};

template <>
struct JsonFields<LitFilmSample> {
    static constexpr auto list =
        std::make_tuple(json_field("film", &LitFilmSample::film),
                        json_field("shadow_rays", &LitFilmSample::shadow_rays));
};

template <>
struct JsonFields<LitPixelAnswer> {
    static constexpr auto list = std::make_tuple(json_field("colour", &LitPixelAnswer::colour),
                                                 json_field("films", &LitPixelAnswer::films));
};

// --- the calls

using StreamPoints = std::vector<std::vector<Vec2>>;  ///< a random pattern's points per stream

std::vector<Vec2> regular_samples_of(const RegularSamplesQuestion& q);
StreamPoints jittered_samples_of(const JitteredSamplesQuestion& q);
StreamPoints random_samples_of(const RandomSamplesQuestion& q);
StreamPoints samples_of(const SamplesQuestion& q);
std::vector<Ray> perspective_rays_through(const RaysThroughQuestion<PerspectiveCamera>& q);
std::vector<Ray> orthographic_rays_through(const RaysThroughQuestion<OrthographicCamera>& q);
std::vector<PixelColourAnswer> pixel_colour_of(const PixelColourQuestion& q);
LightSample sample_quad_light_of(const SampleQuadLightQuestion& q);
std::vector<QuadLightShadingAnswer> quad_light_shading_of(const QuadLightShadingQuestion& q);
std::vector<LitPixelAnswer> lit_pixel_of(const LitPixelQuestion& q);

inline constexpr ProbeCall<RegularSamplesQuestion, std::vector<Vec2>> regular_samples_call{
    "regular_samples", &regular_samples_of};
inline constexpr ProbeCall<JitteredSamplesQuestion, StreamPoints> jittered_samples_call{
    "jittered_samples", &jittered_samples_of};
inline constexpr ProbeCall<RandomSamplesQuestion, StreamPoints> random_samples_call{
    "random_samples", &random_samples_of};
inline constexpr ProbeCall<SamplesQuestion, StreamPoints> samples_call{"samples", &samples_of};
inline constexpr ProbeCall<RaysThroughQuestion<PerspectiveCamera>, std::vector<Ray>>
    perspective_ray_through_call{"perspective_ray_through", &perspective_rays_through};
inline constexpr ProbeCall<RaysThroughQuestion<OrthographicCamera>, std::vector<Ray>>
    orthographic_ray_through_call{"orthographic_ray_through", &orthographic_rays_through};
inline constexpr ProbeCall<PixelColourQuestion, std::vector<PixelColourAnswer>> pixel_colour_call{
    "pixel_colour", &pixel_colour_of};
inline constexpr ProbeCall<SampleQuadLightQuestion, LightSample> sample_quad_light_call{
    "sample_quad_light", &sample_quad_light_of};
inline constexpr ProbeCall<QuadLightShadingQuestion, std::vector<QuadLightShadingAnswer>>
    quad_light_shading_call{"quad_light_shading", &quad_light_shading_of};
inline constexpr ProbeCall<LitPixelQuestion, std::vector<LitPixelAnswer>>
    pixel_colour_with_quad_light_call{"pixel_colour_with_quad_light", &lit_pixel_of};

inline constexpr auto sampling_calls = std::make_tuple(
    regular_samples_call, jittered_samples_call, random_samples_call, samples_call,
    perspective_ray_through_call, orthographic_ray_through_call, pixel_colour_call,
    sample_quad_light_call, quad_light_shading_call, pixel_colour_with_quad_light_call);

}  // namespace raystep::probe
