// Stage 8's statistical checks of means (stage8_statistics.cpp says how the checks judge): a
// pixel's colour over film radiances whose exact mean the grader knows (an edge's coverage, a
// ramp), with the variance that stratification must bring, and a quad light's soft shadow over a
// point against the light's integral, with a blocker over a known part of it. Each answer hands
// back what the student's code asked (the film points, the shadow rays), and the grader takes the
// colour those make itself before any statistic: a colour they do not explain, a film point
// outside the pixel or a shadow ray to a sample behind the surface fails the case outright.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "app/grade/value_text.h"
#include "grader/grade/checks/judging.h"
#include "grader/grade/checks/statistics_seed.h"
#include "grading/8_sampling/sample_statistics.h"
#include "grading/8_sampling/sampling_calls.h"
#include "grading/8_sampling/sampling_oracle.h"
#include "grading/8_sampling/stage8_light_scene.h"
#include "grading/8_sampling/stage8_shadow_rays.h"
#include "grading/8_sampling/stage8_statistics.h"

namespace raystep::grade {

namespace {

// --- pixel_colour

constexpr int kPixelI = 3;
constexpr int kPixelJ = 5;

// What the probe's radiance may answer at a film point: one value, or either side of an edge
// that the point lies on within rounding.
struct FilmValues {
    double low = 0.0;
    double high = 0.0;
};

// A film radiance of the probe's (grading/8_sampling/sampling_calls.h) and what the grader knows of
// it.
struct FilmCase {
    std::string text;
    probe::FilmRadianceModel radiance;
    std::function<FilmValues(const Vec2&)> at;  ///< its value at a film point
    double mean = 0.0;                          ///< its exact mean over the pixel
    /// The exact variance of the jittered estimate with n x n strata.
    std::function<double(int n)> jittered_variance;
};

// The probe computes a film radiance in double: within 1e-12 of an edge it may fall on either
// side, and a ramp's value is the grader's within 1e-12 of its size.
constexpr double kFilmRounding = 1e-12;

FilmCase constant_film(double value) {
    probe::FilmRadianceModel model;
    model.kind = "constant";
    model.value = value;
    return {"constant " + full_text(value), model,
            [value](const Vec2&) {
                return FilmValues{value, value};
            },
            value, [](int) { return 0.0; }};
}

// An edge through `through` at `angle` (radians) to the x axis of the film: bright on the side
// its normal points to.
FilmCase edge_film(const Vec2& through, double angle, double bright, double dark) {
    const Vec2 normal{-std::sin(angle), std::cos(angle)};
    const Vec2 low{kPixelI, kPixelJ};
    const Vec2 high{kPixelI + 1, kPixelJ + 1};
    const double share = half_plane_share(low, high, through, normal);
    const auto variance = [=](int n) {
        // Each stratum's sample is bright with the share q of the stratum the edge leaves bright:
        // the strata are independent, so the variance is (bright - dark)^2 sum q (1 - q) / n^4.
        double sum = 0.0;
        for (int b = 0; b < n; ++b) {
            for (int a = 0; a < n; ++a) {
                const Vec2 s_low = low + Vec2(a, b) / static_cast<double>(n);
                const Vec2 s_high = low + Vec2(a + 1, b + 1) / static_cast<double>(n);
                const double q = half_plane_share(s_low, s_high, through, normal);
                sum += q * (1 - q);
            }
        }
        const double n2 = static_cast<double>(n) * n;
        return (bright - dark) * (bright - dark) * sum / (n2 * n2);
    };
    probe::FilmRadianceModel model;
    model.kind = "edge";
    model.through = through;
    model.normal = normal;
    model.bright = bright;
    model.dark = dark;
    return {"an edge through " + full_text(through) + " at " + full_text(angle) +
                " radians, bright " + full_text(bright) + ", dark " + full_text(dark),
            model,
            [=](const Vec2& film) {
                const Vec2 d = film - through;
                const double side = d.x * normal.x + d.y * normal.y;
                if (std::abs(side) <= kFilmRounding) return FilmValues{dark, bright};
                const double value = side >= 0.0 ? bright : dark;
                return FilmValues{value, value};
            },
            dark + (bright - dark) * share, variance};
}

FilmCase ramp_film(double value, const Vec2& gradient) {
    const double mean = value + gradient.x * (kPixelI + 0.5) + gradient.y * (kPixelJ + 0.5);
    // A stratum of side 1/n adds the variance of a uniform offset, (g.x^2 + g.y^2) / (12 n^2),
    // over n^2 independent strata averaged: divided by n^2 again.
    const auto variance = [=](int n) {
        const double n2 = static_cast<double>(n) * n;
        return (gradient.x * gradient.x + gradient.y * gradient.y) / (12.0 * n2 * n2);
    };
    probe::FilmRadianceModel model;
    model.kind = "ramp";
    model.value = value;
    model.gradient = gradient;
    return {"a ramp " + full_text(value) + " + " + full_text(gradient) + " . film", model,
            [=](const Vec2& film) {
                const double at = value + gradient.x * film.x + gradient.y * film.y;
                const double rounding = kFilmRounding * (1 + std::abs(at));
                return FilmValues{at - rounding, at + rounding};
            },
            mean, variance};
}

ProbeQuery pixel_query(const FilmCase& film, SamplePattern pattern, int count, std::uint64_t seed,
                       const std::vector<std::uint64_t>& streams) {
    return probe::query(probe::pixel_colour_call,
                        {film.radiance, kPixelI, kPixelJ, pattern, count, seed, streams});
}

std::string pixel_call(const FilmCase& film, SamplePattern pattern, int count) {
    return "pixel_colour(" + film.text + ", pixel (" + std::to_string(kPixelI) + ", " +
           std::to_string(kPixelJ) + "), " + std::string(sample_pattern_name(pattern)) + ", " +
           std::to_string(count) + ")";
}

// Per stream: the radiance asked at `count` film points, each inside the pixel, and the colour
// their mean, the three channels alike (the probe's radiance is grey). The grader reads the film
// points the probe hands back and takes the radiance's values there itself, so the count and the
// colour come from data it checks, not from the probe's word. Returns the red channel of each
// stream, or the problem.
std::string read_pixel_answers(const ProbeAnswer& answer, const FilmCase& film, int count,
                               std::vector<double>& colours) {
    for (const probe::PixelColourAnswer& stream :
         probe::read_answer(probe::pixel_colour_call, answer.value)) {
        const std::vector<Vec2>& films = stream.films;
        if (films.size() != static_cast<std::size_t>(count)) {
            return "the radiance asked at " + std::to_string(films.size()) + " film points, not " +
                   std::to_string(count);
        }
        double low = 0.0;
        double high = 0.0;
        for (const Vec2& f : films) {
            // Closed: i + u with u just below 1 may round to i + 1.
            if (!(f.x >= kPixelI && f.x <= kPixelI + 1 && f.y >= kPixelJ && f.y <= kPixelJ + 1)) {
                return "the film point " + full_text(f) + " outside the pixel [" +
                       std::to_string(kPixelI) + ", " + std::to_string(kPixelI + 1) + "] x [" +
                       std::to_string(kPixelJ) + ", " + std::to_string(kPixelJ + 1) + "]";
            }
            const FilmValues values = film.at(f);
            low += values.low;
            high += values.high;
        }
        const Color& colour = stream.colour;
        if (!(colour.x == colour.y && colour.y == colour.z)) {
            return "the channels of a grey radiance apart: " + full_text(colour);
        }
        // The mean of `count` values in double: within `count` roundings of its size.
        const double rounding = 1e-12 * (1 + std::abs(high / count));
        if (!(colour.x >= low / count - rounding && colour.x <= high / count + rounding)) {
            return "the colour " + full_text(colour.x) + ", where the film points asked make " +
                   full_text(low / count) +
                   (high > low ? " to " + full_text(high / count) : std::string());
        }
        colours.push_back(colour.x);
    }
    return "";
}

// Every stream's answer the exact value, within rounding: a constant's mean, or the regular
// pattern's sum, which has no randomness.
ProbeCase pixel_exact_case(const FilmCase& film, SamplePattern pattern, int count, double exact,
                           std::uint64_t seed, StreamCounter& streams) {
    return {pixel_call(film, pattern, count) + ": " + full_text(exact) + " from every stream",
            pixel_query(film, pattern, count, seed, streams.next(20)),
            [film, count, exact](const ProbeAnswer& answer) {
                const std::string want = full_text(exact) + " from every stream";
                if (answer.kind != ProbeAnswer::Kind::result) return wrong(want, "");
                std::vector<double> colours;
                const std::string problem = read_pixel_answers(answer, film, count, colours);
                if (!problem.empty()) return wrong(want, problem);
                for (double c : colours) {
                    if (!(std::abs(c - exact) <= 1e-12 * std::max(1.0, std::abs(exact)))) {
                        return wrong(want, full_text(c));
                    }
                }
                return right();
            },
            ""};
}

// The mean over kMeanStreams streams within the bound of standard errors of the exact mean; with
// `variance_test`, also the streams' variance not above the exact jittered variance (one-sided),
// which random sampling's exceeds many times over.
ProbeCase pixel_mean_case(const FilmCase& film, SamplePattern pattern, int count,
                          bool variance_test, std::uint64_t seed, StreamCounter& streams,
                          double alpha) {
    const int n = static_cast<int>(std::lround(std::sqrt(count)));
    const double jittered_variance = film.jittered_variance(n);
    return {pixel_call(film, pattern, count) + ": the mean over " + std::to_string(kMeanStreams) +
                " streams" + (variance_test ? ", and its variance that of stratified samples" : ""),
            pixel_query(film, pattern, count, seed, streams.next(kMeanStreams)),
            [film, count, exact = film.mean, variance_test, jittered_variance,
             alpha](const ProbeAnswer& answer) {
                const std::string want =
                    "a mean within " + full_text(two_sided_normal_bound(alpha)) +
                    " standard errors of " + full_text(exact) +
                    (variance_test ? ", a variance near " + full_text(jittered_variance) : "");
                if (answer.kind != ProbeAnswer::Kind::result) return wrong(want, "");
                std::vector<double> colours;
                const std::string problem = read_pixel_answers(answer, film, count, colours);
                if (!problem.empty()) return wrong(want, problem);
                const MeanEstimate estimate = estimate_mean(colours, kDeviationFloor);
                const std::string got = "the mean " + full_text(estimate.mean) +
                                        ", standard error " + full_text(estimate.standard_error) +
                                        ", variance " +
                                        full_text(estimate.deviation * estimate.deviation);
                if (!mean_consistent(estimate, exact, two_sided_normal_bound(alpha))) {
                    return wrong(want, got);
                }
                if (variance_test && !variance_not_above(colours, jittered_variance,
                                                         one_sided_normal_bound(alpha))) {
                    return wrong(want, got);
                }
                return right();
            },
            ""};
}

std::vector<ProbeCase> make_pixel_cases() {
    const std::uint64_t seed = statistics_seed();
    StreamCounter streams;
    // Four means and one variance.
    constexpr int tests = 5;
    const double alpha = kCheckAlpha / tests;
    const FilmCase constant = constant_film(0.7);
    const FilmCase edge = edge_film({kPixelI + 0.37, kPixelJ + 0.61}, 0.3, 1.0, 0.2);
    const FilmCase ramp = ramp_film(0.3, {0.05, -0.03});
    // The regular pattern's exact answer: the mean at the 3 x 3 centres.
    double regular_sum = 0.0;
    for (int b = 0; b < 3; ++b) {
        for (int a = 0; a < 3; ++a) {
            const FilmValues at = ramp.at({kPixelI + (a + 0.5) / 3, kPixelJ + (b + 0.5) / 3});
            regular_sum += (at.low + at.high) / 2;
        }
    }
    return {
        pixel_exact_case(constant, SamplePattern::jittered, 16, 0.7, seed, streams),
        pixel_exact_case(constant, SamplePattern::random, 10, 0.7, seed, streams),
        pixel_exact_case(ramp, SamplePattern::regular, 9, regular_sum / 9, seed, streams),
        pixel_mean_case(edge, SamplePattern::jittered, 16, false, seed, streams, alpha),
        pixel_mean_case(edge, SamplePattern::jittered, 64, true, seed, streams, alpha),
        pixel_mean_case(edge, SamplePattern::random, 16, false, seed, streams, alpha),
        pixel_mean_case(ramp, SamplePattern::jittered, 16, false, seed, streams, alpha),
    };
}

// --- quad_light_shading

SurfacePoint surface_at(const Vec3& position, const Vec3& normal, const Vec3& to_eye) {
    const Vec3 n = glm::normalize(normal);
    return {position, Vec3(0.0), n, n, glm::normalize(to_eye)};
}

// A point on the floor seen from above, under the light of stage8_light_scene.h.
const SurfacePoint kFloorPoint = surface_at({0.3, 0, -0.2}, {0, 1, 0}, {1, 1, 0.5});
// On a wall x = 0 under the light's middle: half the light lies behind the wall's plane.
const SurfacePoint kWallPoint = surface_at({0, 1, 0.1}, {1, 0, 0}, {1, 0.2, 0.3});
// Above the light, facing it: the light's dark side.
const SurfacePoint kAbovePoint = surface_at({0.2, 3, 0.1}, {0, -1, 0}, {0.1, -1, 0});
// Under the floor, facing down: the whole light behind the surface.
const SurfacePoint kBelowPoint = surface_at({0.3, 0, -0.2}, {0, -1, 0}, {1, -1, 0.5});

const RayOffset kOffset{OffsetRule::along_normal, 1e-9};

// What blocks the shadow rays: the part u.x < blocked_below of the light, moved 1% of the way
// towards the point (from the point it covers exactly that part, and a shadow ray meets it just
// before the light), and two traps that no right shadow ray meets. The surface's own tangent
// plane around the point catches a shadow ray that starts on the surface with nothing to keep
// it from hitting the surface at t = 0 (shadow acne); a ceiling half a unit beyond the light
// catches one that is not bounded at the light sample's distance.
std::vector<Parallelogram> blockers(const SurfacePoint& point, double blocked_below) {
    std::vector<Parallelogram> parts;
    if (blocked_below > 0.0) {
        const Vec3 corner = point.position + 0.99 * (kShadingCheckLight.corner - point.position);
        parts.push_back({corner, 0.99 * blocked_below * kShadingCheckLight.edge1,
                         0.99 * kShadingCheckLight.edge2});
    }
    const Vec3 tangent = glm::normalize(glm::cross(point.normal, {0.6, 0.0, 0.8}));
    const Vec3 bitangent = glm::cross(point.normal, tangent);
    parts.push_back(
        {point.position - 10.0 * tangent - 10.0 * bitangent, 20.0 * tangent, 20.0 * bitangent});
    parts.push_back({{-10, kShadingCheckLight.corner.y + 0.5, -10}, {0, 0, 20}, {20, 0, 0}});
    return parts;
}

// The call a case makes: the shaded material, kShadingCheckLight, kOffset and the blockers above.
QuadLightCall shading_call_of(const SurfacePoint& point, double blocked_below, int count) {
    return {shading_check_material(),      point, kShadingCheckLight, count, kOffset,
            blockers(point, blocked_below)};
}

ProbeQuery shading_query(const QuadLightCall& call, SamplePattern pattern, std::uint64_t seed,
                         const std::vector<std::uint64_t>& streams) {
    return probe::query(probe::quad_light_shading_call,
                        {call.material, call.point, call.light, pattern, call.sample_count,
                         call.blockers, call.offset, seed, streams});
}

std::string shading_call(const SurfacePoint& point, double blocked_below, SamplePattern pattern,
                         int count) {
    return "quad_light_shading(light at " + full_text(kShadingCheckLight.corner) + " + u " +
           full_text(kShadingCheckLight.edge1) + " + v " + full_text(kShadingCheckLight.edge2) +
           ", point " + full_text(point.position) + " normal " + full_text(point.normal) + ", " +
           std::string(sample_pattern_name(pattern)) + ", " + std::to_string(count) + ", " +
           (blocked_below > 0 ? "blocked for u < " + full_text(blocked_below) : "nothing blocks") +
           ")";
}

// Per stream: the rays the probe hands back are shadow rays of the call, none of them to a sample
// behind the surface (it adds nothing, so a right quad_light_shading traces no ray for it), and
// the colour is what the samples that got through make. Each stream's colour goes into
// `colours`; returns the first problem, or empty.
std::string read_shading_answers(const ProbeAnswer& answer, const QuadLightCall& call,
                                 std::vector<Vec3>& colours) {
    for (const probe::QuadLightShadingAnswer& stream :
         probe::read_answer(probe::quad_light_shading_call, answer.value)) {
        const ShadowRayReading reading = read_shadow_rays(call, stream.shadow_rays);
        if (!reading.problem.empty()) return reading.problem;
        if (reading.behind > 0) {
            return std::to_string(reading.behind) + " of " +
                   std::to_string(reading.samples.size()) +
                   " shadow rays traced to light samples behind the surface (N . L <= 0), which "
                   "add nothing";
        }
        const Color& colour = stream.colour;
        const std::string problem = colour_problem(colour, reading.colour, reading.tolerance);
        if (!problem.empty()) return problem;
        colours.push_back(colour);
    }
    return "";
}

// The light's integral over its part not blocked, seen from `point`, by the midpoint rule on
// 128 x 128 and 256 x 256 cells with Richardson extrapolation (quad_light_integral: an error
// near 1e-9 of the value or below, far below the checks' standard errors). It depends on no seed:
// each is computed once per run, however many seeds a sweep grades at (seed_sweep.h).
Color light_integral(const SurfacePoint& point, double blocked_below) {
    static std::mutex mutex;
    static std::map<std::array<double, 4>, Color> known;
    const std::array<double, 4> key = {point.position.x, point.position.y, point.position.z,
                                       blocked_below};
    const std::lock_guard<std::mutex> lock(mutex);
    const auto found = known.find(key);
    if (found != known.end()) return found->second;
    const Color integral = quad_light_integral(shading_check_material(), point, kShadingCheckLight,
                                               blocked_below, 128);
    known.emplace(key, integral);
    return integral;
}

// The mean over kMeanStreams streams, channel by channel, within the bound of standard errors of
// the exact integral.
ProbeCase shading_mean_case(const SurfacePoint& point, double blocked_below, SamplePattern pattern,
                            int count, std::uint64_t seed, StreamCounter& streams, double alpha) {
    const Color exact = light_integral(point, blocked_below);
    const QuadLightCall call = shading_call_of(point, blocked_below, count);
    return {shading_call(point, blocked_below, pattern, count) + ": the mean over " +
                std::to_string(kMeanStreams) + " streams",
            shading_query(call, pattern, seed, streams.next(kMeanStreams)),
            [call, exact, alpha](const ProbeAnswer& answer) {
                const double bound = two_sided_normal_bound(alpha);
                const std::string want =
                    "a mean within " + full_text(bound) + " standard errors of " + full_text(exact);
                if (answer.kind != ProbeAnswer::Kind::result) return wrong(want, "");
                std::vector<Vec3> colours;
                const std::string problem = read_shading_answers(answer, call, colours);
                if (!problem.empty()) return wrong(want, problem);
                Vec3 mean;
                Vec3 error;
                bool consistent = true;
                for (int c = 0; c < 3; ++c) {
                    std::vector<double> channel;
                    for (const Vec3& colour : colours)
                        channel.push_back(colour[c]);
                    const MeanEstimate estimate = estimate_mean(channel, kDeviationFloor);
                    mean[c] = estimate.mean;
                    error[c] = estimate.standard_error;
                    consistent = consistent && mean_consistent(estimate, exact[c], bound);
                }
                return consistent ? right()
                                  : wrong(want, "the mean " + full_text(mean) +
                                                    ", standard errors " + full_text(error));
            },
            ""};
}

// Every stream's answer `exact` within rounding: the regular pattern's sum, or nothing at all.
ProbeCase shading_exact_case(const SurfacePoint& point, double blocked_below, SamplePattern pattern,
                             int count, const Color& exact, std::uint64_t seed,
                             StreamCounter& streams) {
    const QuadLightCall call = shading_call_of(point, blocked_below, count);
    return {shading_call(point, blocked_below, pattern, count) + ": " + full_text(exact) +
                " from every stream",
            shading_query(call, pattern, seed, streams.next(20)),
            [call, exact](const ProbeAnswer& answer) {
                const std::string want = full_text(exact) + " from every stream";
                if (answer.kind != ProbeAnswer::Kind::result) return wrong(want, "");
                std::vector<Vec3> colours;
                const std::string problem = read_shading_answers(answer, call, colours);
                if (!problem.empty()) return wrong(want, problem);
                const double scale = std::max({exact.x, exact.y, exact.z, 1e-300});
                for (const Vec3& colour : colours) {
                    if (!(glm::length(colour - exact) <= 1e-10 * scale)) {
                        return wrong(want, full_text(colour));
                    }
                }
                return right();
            },
            ""};
}

std::vector<ProbeCase> make_shading_cases() {
    const std::uint64_t seed = statistics_seed();
    StreamCounter streams;
    // Four means of three channels each.
    constexpr int tests = 12;
    const double alpha = kCheckAlpha / tests;
    const Material material = shading_check_material();
    return {
        shading_mean_case(kFloorPoint, 0.0, SamplePattern::jittered, 16, seed, streams, alpha),
        shading_mean_case(kFloorPoint, 0.5, SamplePattern::jittered, 16, seed, streams, alpha),
        shading_mean_case(kFloorPoint, 0.5, SamplePattern::random, 9, seed, streams, alpha),
        shading_mean_case(kWallPoint, 0.0, SamplePattern::jittered, 16, seed, streams, alpha),
        // Blocked below 0.4, not 0.5: the middle column of centres lies at u.x = 0.5 exactly.
        shading_exact_case(
            kFloorPoint, 0.4, SamplePattern::regular, 9,
            regular_quad_light_sum(material, kFloorPoint, kShadingCheckLight, 3, 0.4), seed,
            streams),
        shading_exact_case(kAbovePoint, 0.0, SamplePattern::jittered, 16, Color(0.0), seed,
                           streams),
        // The whole light behind the surface: nothing, and no shadow ray.
        shading_exact_case(kBelowPoint, 0.0, SamplePattern::jittered, 16, Color(0.0), seed,
                           streams),
    };
}

}  // namespace

std::vector<ProbeCase> pixel_cases() {
    return make_pixel_cases();
}

std::vector<ProbeCase> shading_cases() {
    return make_shading_cases();
}

}  // namespace raystep::grade
