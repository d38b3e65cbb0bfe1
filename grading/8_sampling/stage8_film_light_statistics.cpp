// Stage 8's check of film and light samples together (stage8_statistics.cpp says how the checks
// judge): a pixel of a floor under a quad light, pixel_colour over a film radiance that shades
// the floor point under each film point with quad_light_shading, one stream per pixel handed to
// both in turn (grading/8_sampling/sampling_calls.h, "pixel_colour_with_quad_light"). Each film
// sample must get light samples of its own, drawn independently of the film points. A stream copied
// instead of drawn from gives every film sample the same light samples (copied in
// quad_light_shading), or the light samples the numbers the film points took (copied in
// pixel_colour): both unbiased, so no mean sees them, but each pixel's soft shadow is then one
// shadow seen 16 times, or moves with the film points.

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "app/grade/value_text.h"
#include "grader/grade/checks/judging.h"
#include "grader/grade/checks/statistics_seed.h"
#include "grader/oracle/wide_vec.h"
#include "grading/8_sampling/sample_statistics.h"
#include "grading/8_sampling/sampling_calls.h"
#include "grading/8_sampling/stage8_light_scene.h"
#include "grading/8_sampling/stage8_shadow_rays.h"
#include "grading/8_sampling/stage8_statistics.h"

namespace raystep::grade {

namespace {

constexpr int kPixelI = 2;
constexpr int kPixelJ = 7;
// 4 x 4 jittered film samples, each with 2 x 2 jittered light samples: the renderer's default
// pattern, and 16 pairs of a film point and a light sample a pixel.
constexpr int kFilmSide = 4;
constexpr int kLightSide = 2;

// The film point (i + x, j + y) shades the floor point corner + x edge1 + y edge2, whose normal,
// edge1 x edge2, points up at the light: every light sample is above the surface and nothing
// blocks, so every film sample traces all its light samples.
const probe::Parallelogram kFloor{{-0.5, 0, -0.5}, {0, 0, 1}, {1, 0, 0}};
const Vec3 kToEye = glm::normalize(Vec3{2, 2, 1});
// Along the ray: the origin is the point itself, so the grader's point is the ray's.
const RayOffset kOffset{OffsetRule::along_ray, 1e-9};

// Two samples drawn independently coincide within 1e-9 in both coordinates with probability
// 4e-18; a number reused comes back within rounding, 1e-15 of the unit square.
constexpr double kSameSample = 1e-9;

// The question of every case but its streams: 4 x 4 jittered film samples of the pixel, each
// with 2 x 2 jittered light samples.
probe::LitPixelQuestion lit_pixel_question(std::uint64_t seed,
                                           const std::vector<std::uint64_t>& streams) {
    return {kPixelI,
            kPixelJ,
            SamplePattern::jittered,
            kFilmSide * kFilmSide,
            kFloor,
            kToEye,
            shading_check_material(),
            kShadingCheckLight,
            SamplePattern::jittered,
            kLightSide * kLightSide,
            kOffset,
            seed,
            streams};
}

// One pixel's film samples: each film point, in the order the radiance was asked, and the light
// samples its shading traced shadow rays to.
struct LitPixel {
    std::vector<Vec2> films;
    std::vector<std::vector<Vec2>> lights;
};

// Reads one stream's answer: 16 film points inside the pixel, each with 4 shadow rays of its
// floor point to the light (all above the surface, none blocked), and the colour the mean of
// what those samples make. Returns the problem, or empty.
std::string read_lit_pixel(const probe::LitPixelQuestion& question,
                           const probe::LitPixelAnswer& stream, LitPixel& pixel) {
    const std::vector<probe::LitFilmSample>& films = stream.films;
    const int count = question.count;
    const int light_count = question.light_count;
    if (films.size() != static_cast<std::size_t>(count)) {
        return "the radiance asked at " + std::to_string(films.size()) + " film points, not " +
               std::to_string(count);
    }
    WideVec sum(0);
    WideVec tolerance(0);
    for (const probe::LitFilmSample& film : films) {
        const Vec2& f = film.film;
        if (!(f.x >= kPixelI && f.x <= kPixelI + 1 && f.y >= kPixelJ && f.y <= kPixelJ + 1)) {
            return "the film point " + full_text(f) + " outside the pixel";
        }
        const QuadLightCall call{question.material, probe::floor_point_under(question, f),
                                 question.light,    light_count,
                                 question.offset,   {}};
        const ShadowRayReading reading = read_shadow_rays(call, film.shadow_rays);
        if (!reading.problem.empty()) return reading.problem;
        if (reading.samples.size() != static_cast<std::size_t>(light_count)) {
            return "the film point " + full_text(f) + " shaded with " +
                   std::to_string(reading.samples.size()) + " shadow rays, not " +
                   std::to_string(light_count) + ": every light sample is above the floor";
        }
        pixel.films.push_back(f);
        pixel.lights.push_back(reading.samples);
        sum += widen(reading.colour);
        tolerance += widen(reading.tolerance);
    }
    return colour_problem(stream.colour, narrow(sum / Wide(count)),
                          narrow(tolerance / Wide(count)));
}

// Every stream read, or the first problem.
std::string read_lit_pixels(const probe::LitPixelQuestion& question, const ProbeAnswer& answer,
                            std::vector<LitPixel>& pixels) {
    for (const probe::LitPixelAnswer& stream :
         probe::read_answer(probe::pixel_colour_with_quad_light_call, answer.value)) {
        LitPixel pixel;
        const std::string problem = read_lit_pixel(question, stream, pixel);
        if (!problem.empty()) return problem;
        pixels.push_back(std::move(pixel));
    }
    return "";
}

bool same_sample(const Vec2& a, const Vec2& b) {
    return std::abs(a.x - b.x) <= kSameSample && std::abs(a.y - b.y) <= kSameSample;
}

// A point's offset within its stratum of n x n over the unit square.
Vec2 offset_in_stratum(const Vec2& p, int n) {
    return {p.x * n - std::floor(p.x * n), p.y * n - std::floor(p.y * n)};
}

std::string lit_pixel_call(int streams) {
    return "pixel_colour_with_quad_light(pixel (" + std::to_string(kPixelI) + ", " +
           std::to_string(kPixelJ) + "), jittered, 16 film samples, each shaded by " +
           "quad_light_shading(jittered, 4) from the pixel's one stream), " +
           std::to_string(streams) + " streams";
}

// No two film samples of a pixel share a light sample.
ProbeCase own_light_samples_case(std::uint64_t seed, StreamCounter& streams) {
    constexpr int stream_count = 100;
    const probe::LitPixelQuestion question = lit_pixel_question(seed, streams.next(stream_count));
    return {lit_pixel_call(stream_count) + ": each film sample's light samples its own",
            probe::query(probe::pixel_colour_with_quad_light_call, question),
            [question](const ProbeAnswer& answer) {
                const std::string want = "new light samples for every film sample";
                if (answer.kind != ProbeAnswer::Kind::result) return wrong(want, "");
                std::vector<LitPixel> pixels;
                const std::string problem = read_lit_pixels(question, answer, pixels);
                if (!problem.empty()) return wrong(want, problem);
                for (const LitPixel& pixel : pixels) {
                    for (std::size_t k = 0; k < pixel.lights.size(); ++k) {
                        for (std::size_t other = k + 1; other < pixel.lights.size(); ++other) {
                            for (const Vec2& u : pixel.lights[k]) {
                                for (const Vec2& v : pixel.lights[other]) {
                                    if (!same_sample(u, v)) continue;
                                    return wrong(want,
                                                 "the film points " + full_text(pixel.films[k]) +
                                                     " and " + full_text(pixel.films[other]) +
                                                     " share the light sample " + full_text(u));
                                }
                            }
                        }
                    }
                }
                return right();
            },
            ""};
}

// Film and light samples independent within a pixel: no light sample's offset in its stratum is
// a film point's offset in its own (the same random numbers used twice), and the offsets of each
// film point and of the first light sample its shading traced, pooled over the streams, are
// independent by a chi-square test in x and one in y.
ProbeCase independent_samples_case(std::uint64_t seed, StreamCounter& streams, double alpha) {
    constexpr int stream_count = 400;
    const probe::LitPixelQuestion question = lit_pixel_question(seed, streams.next(stream_count));
    return {lit_pixel_call(stream_count) + ": film and light samples independent",
            probe::query(probe::pixel_colour_with_quad_light_call, question),
            [question, alpha](const ProbeAnswer& answer) {
                const std::string want =
                    "light samples that reuse no film point's numbers, and the offsets of film "
                    "points and their first light samples independent, chi-square p >= " +
                    full_text(alpha) + " for x and for y";
                if (answer.kind != ProbeAnswer::Kind::result) return wrong(want, "");
                std::vector<LitPixel> pixels;
                const std::string problem = read_lit_pixels(question, answer, pixels);
                if (!problem.empty()) return wrong(want, problem);
                std::vector<Vec2> x_pairs;
                std::vector<Vec2> y_pairs;
                for (const LitPixel& pixel : pixels) {
                    std::vector<Vec2> film_offsets;
                    for (const Vec2& f : pixel.films)
                        film_offsets.push_back(
                            offset_in_stratum(f - Vec2(kPixelI, kPixelJ), kFilmSide));
                    for (std::size_t k = 0; k < pixel.films.size(); ++k) {
                        for (const Vec2& u : pixel.lights[k]) {
                            const Vec2 light = offset_in_stratum(u, kLightSide);
                            for (const Vec2& film : film_offsets) {
                                if (!same_sample(light, film)) continue;
                                return wrong(want,
                                             "the light sample " + full_text(u) +
                                                 " of the film point " + full_text(pixel.films[k]) +
                                                 " sits in its stratum at " + full_text(light) +
                                                 ", where a film point of the pixel sits "
                                                 "in its own: the same random numbers");
                            }
                        }
                        const Vec2 first = offset_in_stratum(pixel.lights[k].front(), kLightSide);
                        x_pairs.push_back({film_offsets[k].x, first.x});
                        y_pairs.push_back({film_offsets[k].y, first.y});
                    }
                }
                const double p_x = chi_square_p_value(uniform_square_chi_square(x_pairs, kBins),
                                                      kBins * kBins - 1);
                const double p_y = chi_square_p_value(uniform_square_chi_square(y_pairs, kBins),
                                                      kBins * kBins - 1);
                if (p_x >= alpha && p_y >= alpha) return right();
                return wrong(want, "x: p = " + full_text(p_x) + ", y: p = " + full_text(p_y) +
                                       " (fail below " + full_text(alpha) + ")");
            },
            ""};
}

}  // namespace

std::vector<ProbeCase> film_and_light_cases() {
    const std::uint64_t seed = statistics_seed();
    StreamCounter streams;
    // x and y of the film and light offsets.
    constexpr int tests = 2;
    return {own_light_samples_case(seed, streams),
            independent_samples_case(seed, streams, kCheckAlpha / tests)};
}

}  // namespace raystep::grade
