// Public tests for stage 10, the path. Two scenes with closed forms, played by small functions
// of their own (no scene file):
// - the white furnace: the inside of a sphere of albedo a that emits L_e everywhere. A path
//   gathers L_e at every hit, weighted a^k after k bounces, so L = L_e (1 + a + ... + a^d) for
//   max_depth d and L_e / (1 - a) with no limit. Cosine sampling makes f cos / p = a exactly:
//   every path gives the sum itself.
// - a diffuse plane under a square light: L = Kd L_e F, F the form factor from the point to the
//   light, whatever the sampling and next event estimation (which must count the light once).
// A mean of many paths is held to the closed form within five standard errors: a right path
// tracer is further off with probability 6e-7, and the fixed seeds give the same answer on
// every run.

#include <cmath>
#include <optional>
#include <stdexcept>

#include <glm/gtc/constants.hpp>

#include "base/testing/catch.h"
#include "base/testing/number_matchers.h"
#include "base/testing/uses.h"
#include "stages/10_path_tracing/path_tracing.h"

using namespace raystep;
using raystep::testing::IsNear;
using raystep::testing::uses;

namespace {

constexpr double kPi = glm::pi<double>();
const RayOffset kOffset{OffsetRule::along_normal, 1e-9};

SurfacePoint point_at(const Vec3& position, const Vec3& normal, const Vec3& direction) {
    return {position, Vec3(0.0), normal, normal, -direction};
}

// The inside of the unit sphere, albedo `albedo`, emitting 1 everywhere.
PathScene furnace(double albedo) {
    PathScene scene;
    scene.intersect = [albedo](const Ray& ray) -> std::optional<PathHit> {
        // |o + t d| = 1 from inside: the larger root.
        const double b = glm::dot(ray.origin, ray.direction);
        const double c = glm::dot(ray.origin, ray.origin) - 1.0;
        const double t = -b + std::sqrt(b * b - c);
        const Vec3 position = ray.origin + t * ray.direction;
        PathHit hit;
        hit.point = point_at(position, -glm::normalize(position), ray.direction);
        hit.brdf = {BrdfModel::phong, Color(albedo), Color(0.0), 0.0, 0.0};
        hit.emission = Color(1.0);
        return hit;
    };
    scene.occluded = [](const Ray&) { return false; };
    scene.offset = kOffset;
    return scene;
}

// The plane z = 0 (albedo 0.5, facing up) under the square of side 2 at height 1, emitting 1
// downwards.
const QuadLight kLight{{-1.0, -1.0, 1.0}, {2.0, 0.0, 0.0}, {0.0, 2.0, 0.0}, Color(1.0), 1};

PathScene plane_under_light() {
    PathScene scene;
    scene.lights = {kLight};
    scene.intersect = [](const Ray& ray) -> std::optional<PathHit> {
        const double d = ray.direction.z;
        if (d == 0.0) return std::nullopt;
        PathHit hit;
        const double to_light = (1.0 - ray.origin.z) / d;
        const Vec3 at_light = ray.origin + to_light * ray.direction;
        if (to_light > 0.0 && std::abs(at_light.x) <= 1.0 && std::abs(at_light.y) <= 1.0) {
            hit.point = point_at(at_light, {0.0, 0.0, d > 0.0 ? -1.0 : 1.0}, ray.direction);
            hit.emission = d > 0.0 ? kLight.radiance : Color(0.0);  // its face is downwards
            hit.light = 0;
            return hit;
        }
        const double to_plane = -ray.origin.z / d;
        if (!(to_plane > 0.0) || ray.origin.z < 0.0) return std::nullopt;
        hit.point = point_at(ray.origin + to_plane * ray.direction, {0.0, 0.0, 1.0}, ray.direction);
        hit.brdf = {BrdfModel::phong, Color(0.5), Color(0.0), 0.0, 0.0};
        return hit;
    };
    scene.occluded = [](const Ray&) { return false; };
    scene.offset = kOffset;
    return scene;
}

// Kd L_e F at the origin: F four times the corner form factor of a 1 x 1 rectangle at height 1.
double plane_radiance() {
    const double corner = (2.0 / std::sqrt(2.0) * std::atan(1.0 / std::sqrt(2.0))) / (2.0 * kPi);
    return 0.5 * 4.0 * corner;
}

struct Estimate {
    double mean;
    double error;  ///< the standard error of the mean
};

Estimate mean_of_paths(const PathScene& scene, const Ray& ray, const PathSettings& settings,
                       std::uint64_t seed, int count) {
    double sum = 0.0;
    double sum2 = 0.0;
    for (int k = 0; k < count; ++k) {
        RandomStream random(seed, static_cast<std::uint64_t>(k));
        const double value = path_radiance(ray, scene, settings, random).x;
        sum += value;
        sum2 += value * value;
    }
    const double mean = sum / count;
    return {mean, std::sqrt(std::max(0.0, sum2 / count - mean * mean) / count)};
}

const Ray kInFurnace{{0.1, -0.2, 0.3},
                     glm::normalize(Vec3(0.3, 0.5, -0.2)),
                     0.0,
                     std::numeric_limits<double>::infinity()};
const Ray kDownToPlane{
    {0.0, 0.0, 0.5}, {0.0, 0.0, -1.0}, 0.0, std::numeric_limits<double>::infinity()};

}  // namespace

TEST_CASE("path_radiance: the furnace with cosine sampling gives 1 + a + ... + a^d exactly",
          "[stage10]") {
    INFO(uses("path_radiance", "frame_around, cosine_hemisphere, evaluate_brdf and spawn_ray"));
    const PathScene scene = furnace(0.5);
    for (int depth : {0, 1, 2, 5}) {
        CAPTURE(depth);
        PathSettings settings;
        settings.max_depth = depth;
        RandomStream random(40, 0);
        CHECK_THAT(path_radiance(kInFurnace, scene, settings, random).x,
                   IsNear(2.0 - std::pow(0.5, depth), 1e-12));
    }
}

TEST_CASE("path_radiance: the furnace with no depth limit and Russian roulette is L_e / (1 - a)",
          "[stage10]") {
    INFO(uses("path_radiance", "russian_roulette"));
    for (double albedo : {0.5, 0.8}) {
        CAPTURE(albedo);
        PathSettings settings;
        settings.max_depth = -1;
        settings.russian_roulette = true;
        const Estimate estimate = mean_of_paths(furnace(albedo), kInFurnace, settings, 41, 20000);
        INFO("mean " << estimate.mean << ", standard error " << estimate.error);
        CHECK(std::abs(estimate.mean - 1.0 / (1.0 - albedo)) < 5.0 * estimate.error);
    }
}

TEST_CASE("path_radiance: the furnace sampled uniformly converges to the same sum", "[stage10]") {
    PathSettings settings;
    settings.max_depth = 3;
    settings.sampling = DirectionSampling::hemisphere;
    const Estimate estimate = mean_of_paths(furnace(0.5), kInFurnace, settings, 42, 20000);
    INFO("mean " << estimate.mean << ", standard error " << estimate.error);
    CHECK(std::abs(estimate.mean - 1.875) < 5.0 * estimate.error);
}

TEST_CASE("path_radiance: no depth limit without Russian roulette is refused", "[stage10]") {
    PathSettings settings;
    settings.max_depth = -1;
    RandomStream random(43, 0);
    CHECK_THROWS_AS(path_radiance(kInFurnace, furnace(0.5), settings, random), std::domain_error);
}

TEST_CASE("path_radiance: a plane under a light is Kd L_e F by every sampling and light rule",
          "[stage10]") {
    INFO(uses("path_radiance",
              "sample_light_direction, light_direction_pdf, power_heuristic and sample_brdf"));
    const PathScene scene = plane_under_light();
    std::uint64_t seed = 50;
    for (NextEvent next_event : {NextEvent::off, NextEvent::on, NextEvent::mis}) {
        for (DirectionSampling sampling :
             {DirectionSampling::hemisphere, DirectionSampling::cosine, DirectionSampling::brdf}) {
            // Three bounces: the plane sees only the light and the sky, so a light counted
            // twice (by its sample and again when a path hits it) shows as a brighter plane.
            PathSettings settings;
            settings.max_depth = 3;
            settings.sampling = sampling;
            settings.next_event = next_event;
            CAPTURE(static_cast<int>(next_event), static_cast<int>(sampling));
            const Estimate estimate = mean_of_paths(scene, kDownToPlane, settings, seed++, 20000);
            INFO("mean " << estimate.mean << ", standard error " << estimate.error);
            CHECK(std::abs(estimate.mean - plane_radiance()) < 5.0 * estimate.error);
        }
    }
}

TEST_CASE("path_radiance: a light sample that a surface blocks adds nothing", "[stage10]") {
    // Every shadow ray blocked: with next event estimation on, the light reaches the plane only
    // through its samples, so the plane is black.
    PathScene scene = plane_under_light();
    scene.occluded = [](const Ray&) { return true; };
    PathSettings settings;
    settings.max_depth = 3;
    settings.next_event = NextEvent::on;
    for (std::uint64_t stream = 0; stream < 100; ++stream) {
        CAPTURE(stream);
        RandomStream random(45, stream);
        REQUIRE(path_radiance(kDownToPlane, scene, settings, random) == Color(0.0));
    }
}

TEST_CASE("path_radiance: a glossy plane comes out alike by every rule", "[stage10]") {
    // No closed form here: each rule is held to light sampling with cosine-weighted directions,
    // which any right BRDF makes unbiased, within five standard errors of their difference. An
    // MIS weight taken from the wrong density, or a lobe whose value and sampler disagree (a
    // Phong lobe of shininess 0 over the whole sky), lands outside.
    INFO(uses("path_radiance", "sample_brdf, brdf_pdf and power_heuristic"));
    for (const double shininess : {0.0, 20.0}) {
        PathScene scene = plane_under_light();
        const auto plane = scene.intersect;
        scene.intersect = [plane, shininess](const Ray& ray) {
            std::optional<PathHit> hit = plane(ray);
            if (hit && !hit->light)
                hit->brdf = {BrdfModel::phong, Color(0.0), Color(0.7), shininess, 0.0};
            return hit;
        };
        // A grazing view: the mirror direction is 17 degrees above the horizon, and the light
        // reaches past the lobe's equator.
        const Ray slanted{{-0.95, 0.0, 0.3},
                          glm::normalize(Vec3(0.95, 0.0, -0.3)),
                          0.0,
                          std::numeric_limits<double>::infinity()};
        PathSettings reference_settings;
        reference_settings.max_depth = 1;
        reference_settings.next_event = NextEvent::on;
        const Estimate reference = mean_of_paths(scene, slanted, reference_settings, 60, 40000);
        std::uint64_t seed = 61;
        for (NextEvent next_event : {NextEvent::off, NextEvent::mis}) {
            for (DirectionSampling sampling :
                 {DirectionSampling::cosine, DirectionSampling::brdf}) {
                PathSettings settings = reference_settings;
                settings.next_event = next_event;
                settings.sampling = sampling;
                CAPTURE(shininess, static_cast<int>(next_event), static_cast<int>(sampling));
                const Estimate estimate = mean_of_paths(scene, slanted, settings, seed++, 40000);
                const double error = std::hypot(estimate.error, reference.error);
                INFO("mean " << estimate.mean << ", light sampling's " << reference.mean
                             << ", standard error of the difference " << error);
                CHECK(std::abs(estimate.mean - reference.mean) < 5.0 * error);
            }
        }
    }
}

TEST_CASE("path_radiance: max_depth 0 is the emission the eye sees", "[stage10]") {
    PathSettings settings;
    settings.max_depth = 0;
    settings.next_event = NextEvent::on;
    RandomStream random(44, 0);
    CHECK(path_radiance(kDownToPlane, plane_under_light(), settings, random) == Color(0.0));
    const Ray up{{0.0, 0.0, 0.5}, {0.0, 0.0, 1.0}, 0.0, std::numeric_limits<double>::infinity()};
    CHECK(path_radiance(up, plane_under_light(), settings, random) == Color(1.0));
}
