// Stage 8's judges of the jittered pattern, of the shadow rays a probe hands back, and of a pixel's
// film and light samples together, on answers made in process: the reference's, through the
// probe's own call table, and the same calls with one of the corpus's bugs each, made here from
// the reference's pieces.

#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "app/probe/call_table.h"
#include "app/probe/tests/probe_answers.h"
#include "base/testing/catch.h"
#include "grading/8_sampling/sampling_calls.h"
#include "grading/8_sampling/stage8_shadow_rays.h"
#include "grading/8_sampling/stage8_statistics.h"
#include "stages/6_shading/shading.h"
#include "stages/8_sampling/sampling.h"

using namespace raystep;
using namespace raystep::grade;
using raystep::testing::result_answer;

namespace {

// The answer the probe's call table gives in process: the reference stages'.
ProbeAnswer reference_answer(const ProbeQuery& query) {
    static const probe::CallTable calls = probe::stage_calls();
    return result_answer(calls.at(query.call)(query.args));
}

// The input of every case of `cases` that `answer` fails.
std::vector<std::string> failed(const std::vector<ProbeCase>& cases,
                                const std::function<ProbeAnswer(const ProbeQuery&)>& answer) {
    std::vector<std::string> inputs;
    for (const ProbeCase& c : cases) {
        if (!c.judge(answer(c.query)).passed) inputs.push_back(c.input);
    }
    return inputs;
}

bool has(const std::vector<std::string>& inputs, const std::string& part) {
    for (const std::string& input : inputs) {
        if (input.find(part) != std::string::npos) return true;
    }
    return false;
}

// --- The jittered pattern

using Pattern = std::function<std::vector<Vec2>(int n, RandomStream& random)>;

// A jittered_samples or samples(jittered) query answered by `pattern` on each of its streams.
ProbeAnswer pattern_answer(const ProbeQuery& query, const Pattern& pattern) {
    const auto answer = [&](int n, std::uint64_t seed, const std::vector<std::uint64_t>& streams) {
        probe::StreamPoints points;
        for (const std::uint64_t stream : streams) {
            RandomStream random(seed, stream);
            points.push_back(pattern(n, random));
        }
        return result_answer(probe::JsonCodec<probe::StreamPoints>::write(points));
    };
    if (query.call == probe::samples_call.name) {
        const auto q = probe::JsonCodec<probe::SamplesQuestion>::read(query.args);
        return answer(static_cast<int>(std::lround(std::sqrt(q.count))), q.seed, q.streams);
    }
    const auto q = probe::JsonCodec<probe::JitteredSamplesQuestion>::read(query.args);
    return answer(q.strata, q.seed, q.streams);
}

// Below the far edge (a + 1.0) / n, as the handout clamps.
double clamped(double x, int a, int n) {
    const double edge = (a + 1.0) / n;
    return x < edge ? x : std::nextafter(edge, 0.0);
}

std::vector<Vec2> without_clamp(int n, RandomStream& random) {
    std::vector<Vec2> points;
    for (int b = 0; b < n; ++b) {
        for (int a = 0; a < n; ++a) {
            const Vec2 u = random.next2();
            points.push_back({(a + u.x) / n, (b + u.y) / n});
        }
    }
    return points;
}

std::vector<Vec2> row_shares_y(int n, RandomStream& random) {
    std::vector<Vec2> points;
    for (int b = 0; b < n; ++b) {
        const double y = clamped((b + random.next()) / n, b, n);
        for (int a = 0; a < n; ++a)
            points.push_back({clamped((a + random.next()) / n, a, n), y});
    }
    return points;
}

std::vector<Vec2> column_shares_x(int n, RandomStream& random) {
    std::vector<double> column_x;
    for (int a = 0; a < n; ++a)
        column_x.push_back(clamped((a + random.next()) / n, a, n));
    std::vector<Vec2> points;
    for (int b = 0; b < n; ++b) {
        for (int a = 0; a < n; ++a)
            points.push_back(
                {column_x[static_cast<std::size_t>(a)], clamped((b + random.next()) / n, b, n)});
    }
    return points;
}

// The reference's jittered_samples, except where a query names `call`: there `pattern`.
std::function<ProbeAnswer(const ProbeQuery&)> answering(const std::string& call,
                                                        const Pattern& pattern) {
    return [call, pattern](const ProbeQuery& query) {
        return query.call == call ? pattern_answer(query, pattern) : reference_answer(query);
    };
}

// --- Shadow rays

// A 2 x 2 light 2 above the floor facing down, and a point on a wall x = 0 under its middle:
// the samples with u.y < 0.5 lie behind the wall.
const QuadLight kLight{{-1, 2, -1}, {0, 0, 2}, {2, 0, 0}, {5, 2.5, 1.25}, 0};
const RayOffset kOffset{OffsetRule::along_normal, 1e-9};

QuadLightCall wall_call() {
    QuadLightCall call;
    call.material.diffuse = {0.6, 0.5, 0.4};
    call.material.specular = {0.3, 0.3, 0.3};
    call.material.shininess = 20;
    const Vec3 normal{1, 0, 0};
    call.point = {{0, 1, 0.1}, Vec3(0.0), normal, normal, glm::normalize(Vec3{1, 0.2, 0.3})};
    call.light = kLight;
    call.sample_count = 16;
    call.offset = kOffset;
    return call;
}

// The reference quad_light_shading's colour and the shadow rays it traced, none blocked.
Color traced_by_reference(const QuadLightCall& call, std::vector<TracedShadowRay>& traced) {
    RandomStream random(8, 1);
    const OccludedFunction occluded = [&](const Ray& ray) {
        traced.push_back({ray, false});
        return false;
    };
    return quad_light_shading(call.material, call.point, call.light, SamplePattern::jittered,
                              call.sample_count, random, occluded, call.offset);
}

// The shadow ray stage 6 makes to the light's point at u.
TracedShadowRay shadow_ray_to(const QuadLightCall& call, const Vec2& u) {
    const LightSample sample =
        sample_quad_light(call.light, call.point.position, u, call.sample_count);
    return {shadow_ray(call.point, sample, call.offset), false};
}

// --- A pixel's film and light samples

// The answer of "pixel_colour_with_quad_light" made as the probe makes it, from the reference's
// samples and quad_light_shading, but with the pixel's stream copied for the film points
// (`copy_for_film`, 8-pixel-colour-stream-copied) or for each film sample's light samples
// (`copy_for_light`, 8-quad-light-stream-copied).
ProbeAnswer lit_pixel_answer(const ProbeQuery& query, bool copy_for_film, bool copy_for_light) {
    const auto q = probe::JsonCodec<probe::LitPixelQuestion>::read(query.args);
    std::vector<probe::LitPixelAnswer> answers;
    for (const std::uint64_t stream : q.streams) {
        RandomStream random(q.seed, stream);
        RandomStream film_copy = random;
        const std::vector<Vec2> offsets =
            samples(q.pattern, q.count, copy_for_film ? film_copy : random);
        probe::LitPixelAnswer answer;
        Color sum(0.0);
        for (const Vec2& u : offsets) {
            probe::LitFilmSample sample{Vec2(q.i, q.j) + u, {}};
            const OccludedFunction occluded = [&](const Ray& ray) {
                sample.shadow_rays.push_back({ray, false});
                return false;
            };
            RandomStream light_copy = random;
            sum += quad_light_shading(q.material, probe::floor_point_under(q, sample.film), q.light,
                                      q.light_pattern, q.light_count,
                                      copy_for_light ? light_copy : random, occluded, q.offset);
            answer.films.push_back(std::move(sample));
        }
        answer.colour = sum / static_cast<double>(q.count);
        answers.push_back(std::move(answer));
    }
    return result_answer(probe::JsonCodec<std::vector<probe::LitPixelAnswer>>::write(answers));
}

}  // namespace

TEST_CASE("stage8 jittered check: the reference's pattern passes every case", "[grader]") {
    CHECK(failed(jittered_cases(), reference_answer).empty());
}

TEST_CASE("stage8 jittered check: without the clamp, 1 - 2^-53 lands on a stratum's far edge",
          "[grader]") {
    const std::vector<std::string> failures =
        failed(jittered_cases(), answering(probe::jittered_samples_call.name, without_clamp));
    CAPTURE(failures);
    CHECK(failures.size() == 2);
    CHECK(has(failures, "jittered_samples(3): 0 and 1 - 2^-53 at every draw"));
    CHECK(has(failures, "jittered_samples(4): 0 and 1 - 2^-53 at every draw"));
}

TEST_CASE("stage8 jittered check: an offset shared along a row or a column is not independent",
          "[grader]") {
    const std::vector<std::string> rows =
        failed(jittered_cases(), answering(probe::jittered_samples_call.name, row_shares_y));
    CAPTURE(rows);
    CHECK(has(rows, "neighbouring strata along rows"));
    const std::vector<std::string> columns =
        failed(jittered_cases(), answering(probe::jittered_samples_call.name, column_shares_x));
    CAPTURE(columns);
    CHECK(has(columns, "neighbouring strata along columns"));
}

TEST_CASE("stage8 jittered check: samples(jittered) falling through to random is not stratified",
          "[grader]") {
    const Pattern random_points = [](int n, RandomStream& random) {
        return random_samples(n * n, random);
    };
    const std::vector<std::string> failures =
        failed(jittered_cases(), answering(probe::samples_call.name, random_points));
    CAPTURE(failures);
    REQUIRE(failures.size() == 1);
    CHECK(has(failures, "samples(jittered, 16): one point per stratum"));
}

TEST_CASE("read_shadow_rays: the reference's rays explain its colour, none behind the surface",
          "[grader]") {
    const QuadLightCall call = wall_call();
    std::vector<TracedShadowRay> traced;
    const Color colour = traced_by_reference(call, traced);
    const ShadowRayReading reading = read_shadow_rays(call, traced);
    CHECK(reading.problem.empty());
    CHECK(reading.behind == 0);
    // Half the light behind the wall: 8 of the 16 jittered samples traced.
    CHECK(reading.samples.size() == 8);
    CHECK(colour_problem(colour, reading.colour, reading.tolerance).empty());
}

TEST_CASE("read_shadow_rays: a ray to a sample behind the surface is counted, and adds nothing",
          "[grader]") {
    const QuadLightCall call = wall_call();
    std::vector<TracedShadowRay> traced;
    const Color colour = traced_by_reference(call, traced);
    traced.push_back(shadow_ray_to(call, {0.5, 0.1}));
    const ShadowRayReading reading = read_shadow_rays(call, traced);
    CHECK(reading.problem.empty());
    CHECK(reading.behind == 1);
    CHECK(colour_problem(colour, reading.colour, reading.tolerance).empty());
}

TEST_CASE("read_shadow_rays: a colour with a ray left out of the list is not the rays' colour",
          "[grader]") {
    const QuadLightCall call = wall_call();
    std::vector<TracedShadowRay> traced;
    const Color colour = traced_by_reference(call, traced);
    traced.pop_back();
    const ShadowRayReading reading = read_shadow_rays(call, traced);
    CHECK(reading.problem.empty());
    CHECK_FALSE(colour_problem(colour, reading.colour, reading.tolerance).empty());
}

TEST_CASE("read_shadow_rays: a blocker's answer that its parallelogram contradicts is refused",
          "[grader]") {
    QuadLightCall call = wall_call();
    // The whole light, a hundredth of the way towards the point: every ray to it crosses it.
    const Vec3 near = call.point.position + 0.99 * (kLight.corner - call.point.position);
    call.blockers = {{near, 0.99 * kLight.edge1, 0.99 * kLight.edge2}};
    std::vector<TracedShadowRay> traced = {shadow_ray_to(call, {0.5, 0.75})};
    CHECK_FALSE(read_shadow_rays(call, traced).problem.empty());
    traced.front().blocked = true;
    CHECK(read_shadow_rays(call, traced).problem.empty());
}

TEST_CASE("read_shadow_rays: a ray not bounded at its light sample is no shadow ray", "[grader]") {
    const QuadLightCall call = wall_call();
    TracedShadowRay unbounded = shadow_ray_to(call, {0.5, 0.75});
    unbounded.ray.t_max = std::numeric_limits<double>::infinity();
    CHECK_FALSE(read_shadow_rays(call, {unbounded}).problem.empty());
}

TEST_CASE("stage8 film and light check: the reference passes, each copied stream fails its case",
          "[grader]") {
    const std::vector<ProbeCase> cases = film_and_light_cases();
    REQUIRE(cases.size() == 2);
    CHECK(failed(cases, reference_answer).empty());
    const std::vector<std::string> light_copied =
        failed(cases, [](const ProbeQuery& query) { return lit_pixel_answer(query, false, true); });
    CAPTURE(light_copied);
    CHECK(has(light_copied, "each film sample's light samples its own"));
    const std::vector<std::string> film_copied =
        failed(cases, [](const ProbeQuery& query) { return lit_pixel_answer(query, true, false); });
    CAPTURE(film_copied);
    CHECK(film_copied.size() == 1);
    CHECK(has(film_copied, "film and light samples independent"));
    // The answer made here without a copy is the probe's own.
    CHECK(failed(cases, [](const ProbeQuery& query) {
              return lit_pixel_answer(query, false, false);
          }).empty());
}
