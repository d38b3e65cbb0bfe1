// Stage 8's deterministic checks: what a seed does not change. The regular pattern exactly; the
// rays through film points against long double at pixel centres, corners and anywhere; a quad
// light's sample against the handout's formula; and the patterns that need a square count
// throwing for any other. The random answers are judged by their distributions in
// stage8_statistics.cpp.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "app/grade/value_judges.h"
#include "app/grade/value_text.h"
#include "base/math/double_double_vec.h"
#include "base/math/portable_random.h"
#include "grader/grade/checks/data_judged.h"
#include "grader/grade/checks/judging.h"
#include "grader/grade/checks/stage_checks.h"
#include "grader/grade/checks/statistics_seed.h"
#include "grading/2_rays/camera_judges.h"
#include "grading/6_shading/shading_judges.h"
#include "grading/8_sampling/sampling_calls.h"
#include "grading/8_sampling/sampling_judges.h"
#include "grading/8_sampling/sampling_oracle.h"

namespace raystep::grade {

namespace {

// A direction's coordinates from two double computations of the same unit vector differ by a
// few ulps of 1 (2.2e-16 each); 1e-12 leaves room for any order of operations and still sees a
// film point moved by 1e-9 of a pixel.
constexpr double kDirectionTolerance = 1e-12;
// The other values (an orthographic origin, a light sample's distance and intensity): relative
// to their size, for the same reason.
constexpr double kRelativeTolerance = 1e-12;

// The public name, shared by the grader's check and the release's case file.
constexpr const char* kPublicName =
    "the regular pattern, rays through film points and a quad light's sample";

// --- regular_samples and samples

// The centres ((a + 1/2)/n, (b + 1/2)/n) in any order, within a few ulps (a student may write
// a/n + 0.5/n).
PublicCase regular_case(int n) {
    std::vector<Vec2> expected;
    for (int b = 0; b < n; ++b) {
        for (int a = 0; a < n; ++a)
            expected.push_back({(a + 0.5) / n, (b + 0.5) / n});
    }
    const std::string call = "regular_samples(" + std::to_string(n) + ")";
    return {call, probe::query(probe::regular_samples_call, {n}), point_set_judge(expected, 1e-15),
            call};
}

// One stream of the default seed: these cases judge what any stream gives.
ProbeQuery samples_query(SamplePattern pattern, int count) {
    return probe::query(probe::samples_call, {pattern, count, kDefaultStatisticsSeed, {0}});
}

std::string samples_call(SamplePattern pattern, int count) {
    return "samples(SamplePattern::" + std::string(sample_pattern_name(pattern)) + ", " +
           std::to_string(count) + ", random)";
}

PublicCase samples_throw_case(SamplePattern pattern, int count) {
    const std::string call = samples_call(pattern, count);
    return {call + ": not a square", samples_query(pattern, count), threw_judge("domain_error"),
            call};
}

PublicCase random_count_throw_case(int count) {
    const std::string call = "random_samples(" + std::to_string(count) + ", random)";
    return {call + ": no samples",
            probe::query(probe::random_samples_call, {count, kDefaultStatisticsSeed, {0}}),
            threw_judge("domain_error"), call};
}

// samples(pattern, count) gives `count` points, each in [0, 1)^2.
PublicCase samples_count_case(SamplePattern pattern, int count) {
    const std::string call = samples_call(pattern, count);
    return {call + ": the count", samples_query(pattern, count), sample_points_judge(count), call};
}

// --- rays through film points

Frame frame_from(const Vec3& backwards, const Vec3& up) {
    const Vec3 w = glm::normalize(backwards);
    const Vec3 u = glm::normalize(glm::cross(up, w));
    return {u, glm::cross(w, u), w};
}

PublicCase perspective_case(const PerspectiveCamera& camera, const Vec2& film) {
    const std::string call =
        "perspective_ray_through(camera, {" + full_text(film.x) + ", " + full_text(film.y) + "})";
    const Ray expected = expected_perspective_ray(camera, film);
    return {call + " with the eye at " + full_text(camera.eye) + ", u " +
                full_text(camera.frame.u) + ", v " + full_text(camera.frame.v) + ", w " +
                full_text(camera.frame.w) + ", " + std::to_string(camera.width) + " x " +
                std::to_string(camera.height) + " pixels, half sizes " +
                full_text(camera.half_width) + " x " + full_text(camera.half_height),
            probe::query(probe::perspective_ray_through_call, {camera, {film}}),
            // The origin is the eye itself: nothing computed.
            camera_ray_judge(expected.origin, 0.0, expected.direction, kDirectionTolerance), call};
}

PublicCase orthographic_case(const OrthographicCamera& camera, const Vec2& film) {
    const std::string call =
        "orthographic_ray_through(camera, {" + full_text(film.x) + ", " + full_text(film.y) + "})";
    const double scale =
        std::max({1.0, glm::length(camera.eye), std::abs(camera.left), std::abs(camera.right),
                  std::abs(camera.bottom), std::abs(camera.top)});
    const Ray expected = expected_orthographic_ray(camera, film);
    return {call + " with the eye at " + full_text(camera.eye) + ", u " +
                full_text(camera.frame.u) + ", v " + full_text(camera.frame.v) + ", w " +
                full_text(camera.frame.w) + ", window [" + full_text(camera.left) + ", " +
                full_text(camera.right) + "] x [" + full_text(camera.bottom) + ", " +
                full_text(camera.top) + "], " + std::to_string(camera.width) + " x " +
                std::to_string(camera.height) + " pixels",
            probe::query(probe::orthographic_ray_through_call, {camera, {film}}),
            camera_ray_judge(expected.origin, kRelativeTolerance * scale, expected.direction,
                             kDirectionTolerance),
            call};
}

PerspectiveCamera perspective_camera(const Vec3& eye, const Frame& frame, double half_height,
                                     int width, int height) {
    return {eye, frame, half_height * width / height, half_height, width, height};
}

// --- a quad light's sample

PublicCase quad_light_sample_case(const QuadLight& light, const Vec3& point, const Vec2& u,
                                  int count) {
    const std::string call =
        "sample_quad_light(light at " + full_text(light.corner) + " + u " + full_text(light.edge1) +
        " + v " + full_text(light.edge2) + ", radiance " + full_text(light.radiance) + ", point " +
        full_text(point) + ", u " + full_text(u) + ", " + std::to_string(count) + ")";
    const LightSample e = expected_quad_light_sample(light, point, u, count);
    const double scale = std::max({e.intensity.x, e.intensity.y, e.intensity.z});
    return {call, probe::query(probe::sample_quad_light_call, {light, point, u, count}),
            light_sample_judge(
                DoubleDoubleVec3(e.direction), kDirectionTolerance, DoubleDouble(e.distance),
                DoubleDouble(kRelativeTolerance * e.distance), DoubleDoubleVec3(e.intensity),
                DoubleDoubleVec3(kRelativeTolerance * scale)),
            call};
}

// A light 2 above the origin facing down: 2 x 2, radiance (1, 0.5, 0.25).
const QuadLight kCeilingLight{{-1, 2, -1}, {0, 0, 2}, {2, 0, 0}, {1, 0.5, 0.25}, 0};

std::vector<PublicCase> public_cases() {
    std::vector<PublicCase> cases;
    for (int n : {1, 2, 3})
        cases.push_back(regular_case(n));
    cases.push_back(samples_throw_case(SamplePattern::jittered, 8));
    cases.push_back(samples_throw_case(SamplePattern::regular, 2));
    cases.push_back(samples_count_case(SamplePattern::random, 7));
    cases.push_back(samples_count_case(SamplePattern::jittered, 9));

    // Film points of a 640 x 480 camera looking down -z: a centre, corners, the middle, and a
    // point off the centres, where a shift by half a pixel or a flipped row shows.
    const PerspectiveCamera camera =
        perspective_camera({0, 0, 0}, {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, 0.5, 640, 480);
    for (const Vec2 film : {Vec2{0.5, 0.5}, Vec2{0, 0}, Vec2{640, 480}, Vec2{10.25, 400.75}})
        cases.push_back(perspective_case(camera, film));
    const OrthographicCamera ortho{
        {1, 2, 3}, {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, -2, 2, -1.5, 1.5, 40, 30};
    for (const Vec2 film : {Vec2{0.5, 0.5}, Vec2{3.25, 20.75}})
        cases.push_back(orthographic_case(ortho, film));

    // Straight below the light's middle with 1 sample, towards its corner with 16.
    cases.push_back(quad_light_sample_case(kCeilingLight, {0, 0, 0}, {0.5, 0.5}, 1));
    cases.push_back(quad_light_sample_case(kCeilingLight, {0, 0, 0}, {0, 0}, 16));
    return cases;
}

// The hidden ones: the contract's edges a student's own tests may not reach.
std::vector<PublicCase> hidden_cases() {
    const PerspectiveCamera tall =
        perspective_camera({1, -2, 3}, frame_from({1, 1, 1}, {0, 0, 1}), 1.2, 3, 700);
    const OrthographicCamera ortho{
        {1, 2, 3}, frame_from({0, 1, 1}, {0, 1, 0}), -2, 2, -1.5, 1.5, 40, 30};
    return {
        regular_case(5),
        samples_throw_case(SamplePattern::jittered, 15),
        samples_throw_case(SamplePattern::regular, 3),
        random_count_throw_case(0),
        samples_count_case(SamplePattern::regular, 16),
        samples_count_case(SamplePattern::random, 1),
        perspective_case(tall, {3, 0}),
        perspective_case(tall, {0.001, 699.999}),
        orthographic_case(ortho, {0, 0}),
        orthographic_case(ortho, {40, 30}),
        // Off to the side with 4 samples; and above the light, which sees its dark side:
        // intensity 0, however bright the light.
        quad_light_sample_case(kCeilingLight, {3, 1, -2}, {0.25, 0.75}, 4),
        quad_light_sample_case(kCeilingLight, {0, 5, 0}, {0.5, 0.5}, 1),
        quad_light_sample_case(kCeilingLight, {0.5, 2.5, 0.5}, {0.1, 0.9}, 9),
    };
}

// --- generated cases: from kOracleSeed, a release's sample from kOracleSeed + kSampleSeedOffset

constexpr std::uint64_t kOracleSeed = 8088;

PublicCase random_perspective_case(PortableRandom& random) {
    const Frame frame = frame_from(random.unit_vector(), random.unit_vector());
    const int width = static_cast<int>(random.integer(1, 1200));
    const int height = static_cast<int>(random.integer(1, 900));
    const PerspectiveCamera camera = perspective_camera(random.unit_vector() * random.decade(-1, 3),
                                                        frame, random.decade(-1, 1), width, height);
    return perspective_case(camera, {random.uniform(0, width), random.uniform(0, height)});
}

PublicCase random_orthographic_case(PortableRandom& random) {
    const Frame frame = frame_from(random.unit_vector(), random.unit_vector());
    const int width = static_cast<int>(random.integer(1, 1200));
    const int height = static_cast<int>(random.integer(1, 900));
    const double left = random.uniform(-10, 0);
    const double bottom = random.uniform(-10, 0);
    const OrthographicCamera camera{random.unit_vector() * random.decade(-1, 3),
                                    frame,
                                    left,
                                    left + random.decade(-1, 1),
                                    bottom,
                                    bottom + random.decade(-1, 1),
                                    width,
                                    height};
    return orthographic_case(camera, {random.uniform(0, width), random.uniform(0, height)});
}

// A light of any size and orientation, a parallelogram sheared by up to 60 degrees (its area is
// |ab x ac|, not |ab| |ac|), and a point at least a tenth of its size off its plane, on either
// side.
PublicCase random_quad_light_case(PortableRandom& random) {
    QuadLight light;
    light.corner = random.point(10);
    light.edge1 = random.unit_vector() * random.decade(-1, 1);
    const Vec3 across = glm::normalize(glm::cross(light.edge1, random.unit_vector()));
    const double shear = std::tan(random.uniform(-1.05, 1.05));
    light.edge2 = (across + shear * glm::normalize(light.edge1)) * random.decade(-1, 1);
    light.radiance = {random.uniform(0, 5), random.uniform(0, 5), random.uniform(0, 5)};
    const Vec3 normal = glm::normalize(glm::cross(light.edge1, light.edge2));
    const double size = std::max(glm::length(light.edge1), glm::length(light.edge2));
    const double off = size * random.uniform(0.1, 5) * (random.unit() < 0.5 ? -1 : 1);
    const Vec3 point =
        light.corner + random.unit() * light.edge1 + random.unit() * light.edge2 + off * normal;
    const int count = static_cast<int>(random.integer(1, 64));
    return quad_light_sample_case(light, point, {random.unit(), random.unit()}, count);
}

// Case k from PortableRandom(seed, k): rays of both cameras and light samples in turn.
std::vector<PublicCase> generated_cases(std::uint64_t seed, int count) {
    std::vector<PublicCase> cases;
    for (int k = 0; k < count; ++k) {
        PortableRandom random(seed, static_cast<std::uint64_t>(k));
        switch (k % 4) {
            case 0:
                cases.push_back(random_perspective_case(random));
                break;
            case 1:
                cases.push_back(random_orthographic_case(random));
                break;
            default:
                cases.push_back(random_quad_light_case(random));
                break;
        }
    }
    return cases;
}

constexpr const char* kOracleName =
    "rays through random film points of random cameras and random quad-light samples, against "
    "long double";

}  // namespace

PublicCheck stage8_public_check() {
    return {"stage8.unit", 8, "unit", kPublicName, public_cases()};
}

PublicCheck stage8_sample_check() {
    return sample_check(8, kOracleName, generated_cases(kOracleSeed + kSampleSeedOffset, 20));
}

std::vector<CheckDefinition> stage8_checks() {
    std::vector<CheckDefinition> checks = stage_case_checks(
        {8, kPublicName, [] { return data_judged_cases(public_cases()); },
         "counts that are not squares, tall cameras, film corners and a light's dark side",
         [] { return data_judged_cases(hidden_cases()); }, kOracleName,
         [] { return data_judged_cases(generated_cases(kOracleSeed, 400)); }});
    for (CheckDefinition& check : stage8_statistical_checks())
        checks.push_back(std::move(check));
    for (CheckDefinition& check : noisy_render_checks())
        checks.push_back(std::move(check));
    return checks;
}

}  // namespace raystep::grade
