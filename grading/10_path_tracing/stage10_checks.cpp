// Stage 10 checks, one value at a time: the frame around a normal, the samplers' directions and
// densities, the BRDFs, the choice and density of BRDF sampling, a quad light's samples and
// density, the heuristics and the roulette. Each is decided in long double from the contract's
// formulas (grading/10_path_tracing/path_tracing_oracle.h): on hand-worked cases (public), on
// the contract's edges (hidden: a direction below the surface, a Phong exponent of 0 and of
// 1e17, a GGX roughness of 1e-9, both densities 0, a point on the light's plane) and on seeded
// random ones. sample_brdf turns its lobe into the world by the student's frame_around, which
// any orthonormal frame may be, so its directions are judged by their distribution alone
// (stage10_statistics.cpp); so is path_radiance, by its means.

#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "app/grade/value_judges.h"
#include "app/grade/value_text.h"
#include "base/math/portable_random.h"
#include "grader/grade/checks/data_judged.h"
#include "grader/grade/checks/judging.h"
#include "grader/grade/checks/stage_checks.h"
#include "grading/10_path_tracing/path_tracing_calls.h"
#include "grading/10_path_tracing/path_tracing_judges.h"
#include "grading/10_path_tracing/path_tracing_oracle.h"

namespace raystep::grade {

namespace {

constexpr const char* kPublicName =
    "the frame, the samplers and their densities, the BRDFs, the light's samples, the "
    "heuristics and the roulette on hand-worked cases";

// A unit vector the samplers answer is within this of the contract's, per component: sin and
// cos of 2 pi u round to a few ulps.
constexpr double kDirectionTolerance = 1e-12;

std::string number_text(double x) {
    return full_text(x);
}

std::string brdf_text(const SurfaceBrdf& b) {
    return std::string(b.model == BrdfModel::phong ? "phong" : "ggx") + " Kd " +
           full_text(b.diffuse) + " Ks " + full_text(b.specular) +
           (b.model == BrdfModel::phong ? " s " + full_text(b.shininess)
                                        : " alpha " + full_text(b.roughness));
}

std::string light_text(const QuadLight& light) {
    return "light " + full_text(light.corner) + " + u " + full_text(light.edge1) + " + v " +
           full_text(light.edge2) + ", radiance " + full_text(light.radiance);
}

PublicCase number_case(std::string call, ProbeQuery query, double expected) {
    return {call, std::move(query), near_number_judge(expected, path_tolerance(expected)), call};
}

PublicCase direction_case(std::string call, ProbeQuery query, const Vec3& expected,
                          double tolerance = kDirectionTolerance) {
    return {call, std::move(query), near_vec3_judge(expected, tolerance), call};
}

// --- one call, one case

PublicCase frame_around_case(const Vec3& normal) {
    const std::string call = "frame_around(" + full_text(normal) + ")";
    return {call, probe::query(probe::frame_around_call, {normal}),
            frame_around_judge(normal, 1e-13), call};
}

// to_world or to_local in the orthonormal frame of w and u (made orthonormal here).
PublicCase frame_map_case(const Vec3& u, const Vec3& w, const Vec3& vector, bool into_world) {
    const Vec3 ww = glm::normalize(w);
    const Vec3 uu = glm::normalize(u - glm::dot(u, ww) * ww);
    const Frame frame{uu, glm::cross(ww, uu), ww};
    using Wide = long double;
    Vec3 expected;
    for (int k = 0; k < 3; ++k) {
        const Vec3& axis = k == 0 ? frame.u : k == 1 ? frame.v : frame.w;
        expected[k] =
            into_world
                ? static_cast<double>(Wide(vector.x) * frame.u[k] + Wide(vector.y) * frame.v[k] +
                                      Wide(vector.z) * frame.w[k])
                : static_cast<double>(Wide(vector.x) * axis.x + Wide(vector.y) * axis.y +
                                      Wide(vector.z) * axis.z);
    }
    const std::string call = std::string(into_world ? "to_world" : "to_local") + "(frame u " +
                             full_text(frame.u) + " v " + full_text(frame.v) + " w " +
                             full_text(frame.w) + ", " + full_text(vector) + ")";
    const auto& descriptor = into_world ? probe::to_world_call : probe::to_local_call;
    const double size = std::max({std::abs(vector.x), std::abs(vector.y), std::abs(vector.z)});
    return {call, probe::query(descriptor, {frame, vector}),
            near_vec3_judge(expected, 1e-14 * size), call};
}

PublicCase uniform_case(const Vec2& u) {
    return direction_case("uniform_hemisphere(" + full_text(u) + ")",
                          probe::query(probe::uniform_hemisphere_call, {u}),
                          expected_uniform_hemisphere(u));
}

PublicCase cosine_case(const Vec2& u) {
    return direction_case("cosine_hemisphere(" + full_text(u) + ")",
                          probe::query(probe::cosine_hemisphere_call, {u}),
                          expected_cosine_hemisphere(u));
}

PublicCase phong_lobe_case(const Vec2& u, double s) {
    return direction_case("phong_lobe(" + full_text(u) + ", s " + number_text(s) + ")",
                          probe::query(probe::phong_lobe_call, {u, s}), expected_phong_lobe(u, s));
}

// A roughness near 0 puts the half vector within alpha of the normal, where a sine taken from
// 1 - cos^2 rounds to 0: any direction within 1e-8 of the contract's is right there.
PublicCase ggx_half_vector_case(const Vec2& u, double alpha) {
    return direction_case("ggx_half_vector(" + full_text(u) + ", alpha " + number_text(alpha) + ")",
                          probe::query(probe::ggx_half_vector_call, {u, alpha}),
                          expected_ggx_half_vector(u, alpha),
                          alpha < 1e-3 ? 1e-8 : kDirectionTolerance);
}

PublicCase uniform_pdf_case(const Vec3& d) {
    return number_case("uniform_hemisphere_pdf(" + full_text(d) + ")",
                       probe::query(probe::uniform_hemisphere_pdf_call, {d}),
                       expected_uniform_hemisphere_pdf(d));
}

PublicCase cosine_pdf_case(const Vec3& d) {
    return number_case("cosine_hemisphere_pdf(" + full_text(d) + ")",
                       probe::query(probe::cosine_hemisphere_pdf_call, {d}),
                       expected_cosine_hemisphere_pdf(d));
}

PublicCase phong_pdf_case(const Vec3& d, double s) {
    return number_case("phong_lobe_pdf(" + full_text(d) + ", s " + number_text(s) + ")",
                       probe::query(probe::phong_lobe_pdf_call, {d, s}),
                       expected_phong_lobe_pdf(d, s));
}

PublicCase ggx_d_case(const Vec3& h, double alpha) {
    return number_case("ggx_distribution(" + full_text(h) + ", alpha " + number_text(alpha) + ")",
                       probe::query(probe::ggx_distribution_call, {h, alpha}),
                       expected_ggx_distribution(h, alpha));
}

// D at alpha^2 far below sin^2(theta_h): D ~ alpha^2 / (pi sin^4), and sin^2 taken as 1 - z^2
// (tan^2 as the header writes it) rather than x^2 + y^2 differs by the rounding of h's length,
// some 1e-10 of D: within 1e-9 is right there.
PublicCase ggx_d_steep_case(const Vec3& h, double alpha) {
    PublicCase c = ggx_d_case(h, alpha);
    const double expected = expected_ggx_distribution(h, alpha);
    c.judge = near_number_judge(expected, 1e-9 * expected);
    return c;
}

PublicCase ggx_pdf_case(const Vec3& h, double alpha) {
    return number_case(
        "ggx_half_vector_pdf(" + full_text(h) + ", alpha " + number_text(alpha) + ")",
        probe::query(probe::ggx_half_vector_pdf_call, {h, alpha}),
        expected_ggx_half_vector_pdf(h, alpha));
}

// wi and wo normalized here.
PublicCase brdf_case(const SurfaceBrdf& brdf, const Vec3& n, const Vec3& wi, const Vec3& wo) {
    const Vec3 to_light = glm::normalize(wi);
    const Vec3 to_eye = glm::normalize(wo);
    const Color e = expected_brdf(brdf, n, to_light, to_eye);
    const double size = std::max({e.x, e.y, e.z});
    const std::string call = "evaluate_brdf(" + brdf_text(brdf) + ", n " + full_text(n) + ", wi " +
                             full_text(to_light) + ", wo " + full_text(to_eye) + ")";
    return {call, probe::query(probe::evaluate_brdf_call, {brdf, n, to_light, to_eye}),
            near_vec3_judge(e, path_tolerance(size)), call};
}

PublicCase specular_probability_case(const SurfaceBrdf& brdf) {
    return number_case("specular_probability(" + brdf_text(brdf) + ")",
                       probe::query(probe::specular_probability_call, {brdf}),
                       expected_specular_probability(brdf));
}

PublicCase brdf_pdf_case(const SurfaceBrdf& brdf, const Vec3& n, const Vec3& wo, const Vec3& wi) {
    const Vec3 to_eye = glm::normalize(wo);
    const Vec3 to_light = glm::normalize(wi);
    return number_case("brdf_pdf(" + brdf_text(brdf) + ", n " + full_text(n) + ", wo " +
                           full_text(to_eye) + ", wi " + full_text(to_light) + ")",
                       probe::query(probe::brdf_pdf_call, {brdf, n, to_eye, to_light}),
                       expected_brdf_pdf(brdf, n, to_eye, to_light));
}

PublicCase light_sample_case(const QuadLight& light, const Vec3& point, const Vec2& u) {
    const std::string call = "sample_light_direction(" + light_text(light) + ", point " +
                             full_text(point) + ", u " + full_text(u) + ")";
    return {call, probe::query(probe::sample_light_direction_call, {light, point, u}),
            light_direction_sample_judge(expected_light_direction(light, point, u),
                                         kDirectionTolerance, kPathRelativeTolerance),
            call};
}

// The direction normalized here.
PublicCase light_pdf_case(const QuadLight& light, const Vec3& point, const Vec3& direction) {
    const Vec3 d = glm::normalize(direction);
    return number_case("light_direction_pdf(" + light_text(light) + ", point " + full_text(point) +
                           ", direction " + full_text(d) + ")",
                       probe::query(probe::light_direction_pdf_call, {light, point, d}),
                       expected_light_direction_pdf(light, point, d));
}

PublicCase balance_case(double pdf, double other) {
    return number_case("balance_heuristic(" + number_text(pdf) + ", " + number_text(other) + ")",
                       probe::query(probe::balance_heuristic_call, {pdf, other}),
                       expected_balance_heuristic(pdf, other));
}

PublicCase power_case(double pdf, double other) {
    return number_case("power_heuristic(" + number_text(pdf) + ", " + number_text(other) + ")",
                       probe::query(probe::power_heuristic_call, {pdf, other}),
                       expected_power_heuristic(pdf, other));
}

PublicCase roulette_case(const Color& throughput, double u) {
    const std::optional<Color> e = expected_russian_roulette(throughput, u);
    const double size = e ? std::max({e->x, e->y, e->z}) : 0.0;
    const std::string call =
        "russian_roulette(" + full_text(throughput) + ", u " + number_text(u) + ")";
    return {call, probe::query(probe::russian_roulette_call, {throughput, u}),
            roulette_judge(e, path_tolerance(size)), call};
}

// evaluate_brdf along the mirror direction at a huge Phong exponent: r . wi is 1 within
// rounding, and which side of 1 the student's rounding lands on decides between the peak
// Ks (s + 2) / (2 pi) and far less; any value from 0 to the peak is right, Inf and NaN are not.
PublicCase mirror_lobe_peak_case(double s) {
    const SurfaceBrdf brdf{BrdfModel::phong, Color(0.0), Color(0.5), s, 0.0};
    const Vec3 n{0, 0, 1};
    const Vec3 wi = glm::normalize(Vec3{1, 0, 1});
    const Vec3 wo = glm::normalize(Vec3{-1, 0, 1});
    const double half_peak = 0.5 * 0.5 * (s + 2) / (2 * 3.14159265358979323846);
    const std::string call = "evaluate_brdf(" + brdf_text(brdf) + ", n " + full_text(n) + ", wi " +
                             full_text(wi) + ", wo " + full_text(wo) + "): the mirror direction";
    return {call, probe::query(probe::evaluate_brdf_call, {brdf, n, wi, wo}),
            near_vec3_judge(Color(half_peak), half_peak), call};
}

SurfaceBrdf phong(const Color& kd, const Color& ks, double s) {
    return {BrdfModel::phong, kd, ks, s, 0.0};
}

SurfaceBrdf ggx(const Color& kd, const Color& ks, double alpha) {
    return {BrdfModel::ggx, kd, ks, 0.0, alpha};
}

const Vec3 kUp{0, 0, 1};
// A light 2 x 2 at height 2 over the origin, facing down.
const QuadLight kCeiling{{-1, -1, 2}, {2, 0, 0}, {0, 2, 0}, {4, 2, 1}, 0};

std::vector<PublicCase> public_cases() {
    const Vec3 tilted = glm::normalize(Vec3{1, 2, 2});
    return {
        frame_around_case(kUp),
        frame_around_case(tilted),
        frame_map_case({1, 0, 0}, kUp, {0.6, 0, 0.8}, true),
        frame_map_case({0, 1, 0}, tilted, {0.5, -0.5, 0.7}, false),
        uniform_case({0.5, 0.25}),
        uniform_pdf_case({0, 0.6, 0.8}),
        cosine_case({0.36, 0.5}),
        cosine_pdf_case({0, 0.6, 0.8}),
        phong_lobe_case({0.5, 0.125}, 10),
        phong_pdf_case({0, 0.6, 0.8}, 10),
        ggx_half_vector_case({0.5, 0.75}, 0.5),
        ggx_d_case({0, 0.6, 0.8}, 0.5),
        ggx_pdf_case({0, 0.6, 0.8}, 0.5),
        brdf_case(phong({0.5, 0.5, 0.5}, {0, 0, 0}, 0), kUp, {1, 0, 1}, {-1, 0, 2}),
        brdf_case(phong({0.2, 0.2, 0.2}, {0.6, 0.6, 0.6}, 20), kUp, {1, 0, 1}, {-1, 0, 1}),
        brdf_case(ggx({0.2, 0.2, 0.2}, {0.5, 0.5, 0.5}, 0.3), kUp, {1, 0, 1}, {-1, 0.2, 1}),
        specular_probability_case(phong({0.3, 0.3, 0.3}, {0.1, 0.1, 0.1}, 10)),
        specular_probability_case(ggx({0.8, 0.8, 0.8}, {0.1, 0.1, 0.1}, 0.3)),
        brdf_pdf_case(phong({0.5, 0.5, 0.5}, {0.5, 0.5, 0.5}, 10), kUp, {-1, 0, 1}, {1, 0, 1.2}),
        brdf_pdf_case(ggx({0.5, 0.5, 0.5}, {0.5, 0.5, 0.5}, 0.4), kUp, {-1, 0, 1}, {1, 0.1, 1}),
        light_sample_case(kCeiling, {0, 0, 0}, {0.5, 0.5}),
        light_sample_case(kCeiling, {0.5, 0, 0}, {0.25, 0.75}),
        light_pdf_case(kCeiling, {0, 0, 0}, {0.2, 0.1, 1}),
        light_pdf_case(kCeiling, {0, 0, 0}, {1, 0, 0.2}),
        balance_case(1, 3),
        power_case(1, 3),
        roulette_case({0.5, 0.25, 0.1}, 0.3),
        roulette_case({0.5, 0.25, 0.1}, 0.7),
    };
}

// The contract's edges.
std::vector<PublicCase> hidden_cases() {
    const Vec3 below = glm::normalize(Vec3{0.3, 0.4, -0.5});
    const Vec3 horizon{0.6, 0.8, 0};
    const Vec3 steep = glm::normalize(Vec3{1e-3, 0, 1});
    return {
        // frames about the axes and their opposites, and a normal with two equal components
        frame_around_case({0, 0, -1}),
        frame_around_case({1, 0, 0}),
        frame_around_case({0, -1, 0}),
        frame_around_case(glm::normalize(Vec3{1, 1, 1e-9})),
        frame_around_case(glm::normalize(Vec3{-3, 3, 3})),
        // densities below the surface and on its horizon
        uniform_pdf_case(below),
        cosine_pdf_case(below),
        phong_pdf_case(below, 0),
        phong_pdf_case(below, 5),
        phong_pdf_case(horizon, 3),
        ggx_d_case(below, 0.3),
        ggx_pdf_case(below, 0.3),
        // the samplers at the ends of [0, 1)
        uniform_case({0, 0}),
        cosine_case({0, 0.999}),
        cosine_case({0.999999, 0.3}),
        phong_lobe_case({0, 0.5}, 1),
        phong_lobe_case({0.3, 0.7}, 0),
        phong_lobe_case({0.5, 0.1}, 1e6),
        ggx_half_vector_case({0, 0.2}, 0.1),
        ggx_half_vector_case({0.999999, 0.2}, 0.9),
        ggx_half_vector_case({0.5, 0.2}, 1e-9),
        // GGX's roughness far from 1: D along the normal is 1 / (pi alpha^2)
        ggx_d_case(kUp, 1e-9),
        ggx_d_steep_case(steep, 1e-9),
        ggx_d_case({0, 0, 1}, 1),
        ggx_d_case(glm::normalize(Vec3{0, 1, 1e-6}), 0.5),
        // the BRDFs below the surface, at Phong exponents 0 and 1e17, at grazing
        brdf_case(phong({0.5, 0.5, 0.5}, {0.5, 0.5, 0.5}, 10), kUp, {1, 0, -0.1}, {-1, 0, 1}),
        brdf_case(phong({0.5, 0.5, 0.5}, {0.5, 0.5, 0.5}, 10), kUp, {1, 0, 1}, {-1, 0, -0.1}),
        brdf_case(phong({0, 0, 0}, {0.5, 0.5, 0.5}, 0), kUp, {-1, 0, 0.5}, {-1, 0, 1}),
        brdf_case(phong({0, 0, 0}, {0.5, 0.5, 0.5}, 0), kUp, {1, 0, 1}, {-1, 0, 1}),
        mirror_lobe_peak_case(1e17),
        brdf_case(ggx({0, 0, 0}, {1, 0.5, 0.2}, 0.2), kUp, {1, 0, 0.01}, {-1, 0, 0.02}),
        brdf_case(ggx({0.1, 0.2, 0.3}, {0.04, 0.04, 0.04}, 1), kUp, {0.3, 0.4, 1}, {0, -1, 1}),
        // BRDF sampling's lobe share: black surfaces, GGX's floor of 0.25
        specular_probability_case(phong({0, 0, 0}, {0, 0, 0}, 10)),
        specular_probability_case(ggx({0, 0, 0}, {0, 0, 0}, 0.5)),
        specular_probability_case(phong({0, 0, 0}, {0.2, 0.4, 0.6}, 10)),
        specular_probability_case(ggx({0.9, 0.1, 0.5}, {0.9, 0.1, 0.05}, 0.5)),
        // brdf_pdf below the surface, GGX's half vector turned to the normal's side
        brdf_pdf_case(phong({0.5, 0.5, 0.5}, {0.5, 0.5, 0.5}, 3), kUp, {-1, 0, 1}, {1, 0, -0.05}),
        brdf_pdf_case(ggx({0.5, 0.5, 0.5}, {0.5, 0.5, 0.5}, 0.5), kUp, {-1, 0, 0.2}, {0.5, 0, -1}),
        brdf_pdf_case(phong({0, 0, 0}, {0, 0, 0}, 3), kUp, {-1, 0, 1}, {1, 0, 1}),
        // a light seen edge-on and from behind, a point on its plane
        light_sample_case(kCeiling, {0, 0, 4}, {0.5, 0.5}),
        light_sample_case(kCeiling, {5, 0, 2}, {0.5, 0.5}),
        light_sample_case(kCeiling, {0, 0, 0}, {0, 0}),
        light_pdf_case(kCeiling, {0, 0, 4}, {0, 0, -1}),
        light_pdf_case(kCeiling, {0, 0, 0}, {0, 0, -1}),
        light_pdf_case(kCeiling, {0, 0, 0}, {0.9, -0.9, 2}),
        light_pdf_case(kCeiling, {0, 0, 0}, {1.0001, 0, 2}),
        // heuristics: both densities 0, one 0, one infinite-ish
        balance_case(0, 0),
        power_case(0, 0),
        balance_case(0, 2),
        power_case(5, 0),
        balance_case(1e-200, 3e-200),
        // the roulette: a bright path always goes on unscaled, a black one stops, u at q
        roulette_case({2, 0.5, 0.1}, 0.999),
        roulette_case({0, 0, 0}, 0),
        roulette_case({0.5, 0.25, 0.1}, 0.5),
        roulette_case({0.5, 0.25, 0.1}, 0.4999),
    };
}

// --- generated cases

constexpr std::uint64_t kOracleSeed = 10199;

Vec2 random_u(PortableRandom& random) {
    return {random.unit(), random.unit()};
}

Vec3 random_above(PortableRandom& random, const Vec3& n, double min_cos) {
    for (;;) {
        const Vec3 d = random.unit_vector();
        if (glm::dot(d, n) >= min_cos) return d;
        if (-glm::dot(d, n) >= min_cos) return -d;
    }
}

Color random_colour(PortableRandom& random, double most) {
    return {random.uniform(0, most), random.uniform(0, most), random.uniform(0, most)};
}

SurfaceBrdf random_brdf(PortableRandom& random, int k) {
    if (k % 2 == 0)
        return phong(random_colour(random, 0.5), random_colour(random, 0.5), random.decade(0, 2.4));
    return ggx(random_colour(random, 0.5), random_colour(random, 0.5), random.uniform(0.05, 1));
}

PublicCase random_sampler_case(PortableRandom& random, int k) {
    const Vec2 u = random_u(random);
    switch (k % 4) {
        case 0:
            return uniform_case(u);
        case 1:
            return cosine_case(u);
        case 2:
            return phong_lobe_case(u, random.decade(-1, 2.4));
        default:
            return ggx_half_vector_case(u, random.uniform(0.02, 1));
    }
}

PublicCase random_density_case(PortableRandom& random, int k) {
    const Vec3 d = random.unit_vector();
    // Keep z away from 0, where a density's value jumps.
    const Vec3 direction = std::abs(d.z) < 1e-3 ? Vec3{d.x, d.y, 0.5} : d;
    const Vec3 unit = glm::normalize(direction);
    switch (k % 5) {
        case 0:
            return uniform_pdf_case(unit);
        case 1:
            return cosine_pdf_case(unit);
        case 2:
            return phong_pdf_case(unit, random.decade(-1, 2.4));
        case 3:
            return ggx_d_case(unit, random.uniform(0.02, 1));
        default:
            return ggx_pdf_case(unit, random.uniform(0.02, 1));
    }
}

// A surface anywhere, wi and wo at least 0.05 from its plane and r . wi at least 0.05 from 0,
// where the lobe's edge would let rounding decide.
PublicCase random_brdf_case(PortableRandom& random, int k) {
    const Vec3 n = random.unit_vector();
    const SurfaceBrdf brdf = random_brdf(random, k);
    const Vec3 wo = random_above(random, n, 0.05);
    const Vec3 r = 2 * glm::dot(n, wo) * n - wo;
    for (;;) {
        const Vec3 wi = random.unit_vector();
        if (std::abs(glm::dot(n, wi)) < 0.05 || std::abs(glm::dot(r, wi)) < 0.05) continue;
        if (k % 4 < 2) return brdf_case(brdf, n, wi, wo);
        return brdf_pdf_case(brdf, n, wo, wi);
    }
}

PublicCase random_light_case(PortableRandom& random, int k) {
    QuadLight light;
    light.corner = random.unit_vector() * random.uniform(0, 3);
    light.edge1 = random.unit_vector() * random.uniform(0.2, 2);
    light.edge2 =
        glm::normalize(glm::cross(random.unit_vector(), light.edge1)) * random.uniform(0.2, 2);
    light.radiance = random_colour(random, 10);
    const Vec3 normal = glm::normalize(glm::cross(light.edge1, light.edge2));
    const Vec3 centre = light.corner + 0.5 * light.edge1 + 0.5 * light.edge2;
    const double side = random.unit() < 0.5 ? -1.0 : 1.0;
    const Vec3 point = centre + side * random.uniform(0.1, 4) * normal +
                       random.uniform(-2, 2) * glm::normalize(light.edge1);
    if (k % 2 == 0) return light_sample_case(light, point, random_u(random));
    // A target on the light or beside it: the density jumps at the light's edges, which a target
    // drawn at random meets within rounding with probability near 0 (and the seeds are fixed).
    const Vec3 target = light.corner + random.uniform(-0.2, 1.2) * light.edge1 +
                        random.uniform(-0.2, 1.2) * light.edge2;
    return light_pdf_case(light, point, target - point);
}

PublicCase random_estimator_case(PortableRandom& random, int k) {
    switch (k % 3) {
        case 0:
            return balance_case(random.decade(-3, 3), random.decade(-3, 3));
        case 1:
            return power_case(random.decade(-3, 3), random.decade(-3, 3));
        default: {
            const Color throughput = random_colour(random, 1.5);
            const double q = std::min(1.0, std::max({throughput.x, throughput.y, throughput.z}));
            double u = random.unit();
            if (std::abs(u - q) < 1e-9) u = q / 2;
            return roulette_case(throughput, u);
        }
    }
}

std::vector<PublicCase> generated_cases(std::uint64_t seed, int count) {
    std::vector<PublicCase> cases;
    const auto family = [&](std::uint64_t offset, int n, auto make) {
        for (int k = 0; k < n; ++k) {
            PortableRandom random(seed + offset, static_cast<std::uint64_t>(k));
            cases.push_back(make(random, k));
        }
    };
    family(0, count, random_sampler_case);
    family(1, count, random_density_case);
    family(2, 2 * count, random_brdf_case);
    family(3, count, random_light_case);
    family(4, count, random_estimator_case);
    return cases;
}

constexpr const char* kOracleName =
    "random directions, densities, BRDFs, light samples, heuristics and roulettes, against long "
    "double";

}  // namespace

PublicCheck stage10_public_check() {
    return {"stage10.unit", 10, "unit", kPublicName, public_cases()};
}

PublicCheck stage10_sample_check() {
    return sample_check(10, kOracleName, generated_cases(kOracleSeed + kSampleSeedOffset, 4));
}

std::vector<CheckDefinition> stage10_checks() {
    std::vector<CheckDefinition> checks = stage_case_checks(
        {10, kPublicName, [] { return data_judged_cases(public_cases()); },
         "below the surface and on its horizon, Phong exponents 0 and 1e17, GGX roughness 1e-9, "
         "lights edge-on and from behind, both densities 0, the roulette at q",
         [] { return data_judged_cases(hidden_cases()); }, kOracleName,
         [] { return data_judged_cases(generated_cases(kOracleSeed, 60)); }});
    for (CheckDefinition& check : stage10_statistical_checks())
        checks.push_back(std::move(check));
    return checks;
}

}  // namespace raystep::grade
