// Stage 8's statistical checks: a student may place a pattern's samples in any order and consume
// the RandomStream in any way, so their random answers are judged by their distributions, never
// by their values. Each check asks for hundreds of streams of the grader's seed
// (statistics_seed()) in one query per case and runs a few tests on what comes back:
//
// - what holds for every stream (one point per stratum, the radiance asked `count` times, no film
//   point outside the pixel, a dark side that adds nothing): deterministic, no false fails;
// - a chi-square test of pooled points against the exact uniform distribution, or a z-test of a
//   mean over streams against the exact value the grader integrates, or a one-sided test of a
//   variance against the exact variance of stratified sampling.
//
// A check's false-fail rate is kCheckAlpha: it runs m tests, each at kCheckAlpha / m
// (Bonferroni), so that a right submission loses a check's points on at most that share of
// seeds. The measured rates, on the reference and on every stage-8 alternative over many seeds,
// and the command that measures them: docs/measurements/stage8-checks.md.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "app/grade/value_text.h"
#include "grader/grade/checks/judging.h"
#include "grader/grade/checks/sample_statistics.h"
#include "grader/grade/checks/stage8_queries.h"
#include "grader/grade/checks/stage8_statistics.h"
#include "grader/grade/checks/stage_checks.h"
#include "grader/grade/checks/statistics_seed.h"

namespace raystep::grade {

namespace {

using probe::Json;

std::string p_text(double p, double alpha) {
    return "p = " + full_text(p) + " (fails below " + full_text(alpha) + ")";
}

// --- jittered_samples

// Where a point lies among n x n strata and its offset in its stratum, exactly: a double times
// an n below 2^11 is exact in long double's 64-bit significand.
struct StratumPlace {
    int a = 0;
    int b = 0;
    Vec2 offset;
};

StratumPlace place_of(const Vec2& p, int n) {
    const long double x = static_cast<long double>(p.x) * n;
    const long double y = static_cast<long double>(p.y) * n;
    const long double a = std::floor(x);
    const long double b = std::floor(y);
    // An offset within half an ulp of 1 rounds to 1 as a double: keep it below.
    const double below_one = std::nextafter(1.0, 0.0);
    return {static_cast<int>(a),
            static_cast<int>(b),
            {std::min(static_cast<double>(x - a), below_one),
             std::min(static_cast<double>(y - b), below_one)}};
}

// Every stream's n^2 points in [0, 1)^2, one in each stratum.
std::string stratification_problem(const std::vector<Vec2>& points, int n) {
    if (points.size() != static_cast<std::size_t>(n) * n) {
        return std::to_string(points.size()) + " points";
    }
    std::vector<int> seen(points.size(), 0);
    for (const Vec2& p : points) {
        if (!(p.x >= 0 && p.x < 1 && p.y >= 0 && p.y < 1)) {
            return "the point " + point_text(p) + " outside [0, 1)^2";
        }
        const StratumPlace place = place_of(p, n);
        if (++seen[static_cast<std::size_t>(place.b) * n + place.a] > 1) {
            return "two points in stratum (" + std::to_string(place.a) + ", " +
                   std::to_string(place.b) + "), one of them " + point_text(p);
        }
    }
    return "";
}

Json jittered_query(int n, std::uint64_t seed, const Json& streams) {
    return {{"strata", n}, {"seed", seed}, {"streams", streams}};
}

ProbeCase stratified_case(int n, std::uint64_t seed, StreamCounter& streams) {
    const std::string want = "n^2 = " + std::to_string(n * n) + " points, one in each stratum";
    return {"jittered_samples(" + std::to_string(n) + "): one point per stratum, 64 streams",
            {"jittered_samples", jittered_query(n, seed, streams.next(64))},
            [n, want](const ProbeAnswer& answer) {
                if (answer.kind != ProbeAnswer::Kind::result) return wrong(want, "");
                for (const Json& stream : answer.value) {
                    const std::string problem = stratification_problem(points_from(stream), n);
                    if (!problem.empty()) return wrong(want, problem);
                }
                return right();
            },
            ""};
}

// The offsets within their strata, pooled over every stream, binned in 10 x 10 against the
// uniform: a pattern biased inside its strata (offsets in half a stratum, the centres) fails,
// and so do x and y drawn alike.
ProbeCase offsets_uniform_case(int n, int stream_count, std::uint64_t seed, StreamCounter& streams,
                               double alpha) {
    return {"jittered_samples(" + std::to_string(n) + "): offsets in their strata uniform, " +
                std::to_string(stream_count) + " streams pooled",
            {"jittered_samples", jittered_query(n, seed, streams.next(stream_count))},
            [n, alpha](const ProbeAnswer& answer) {
                const std::string want =
                    "offsets uniform over the stratum, chi-square p >= " + full_text(alpha);
                if (answer.kind != ProbeAnswer::Kind::result) return wrong(want, "");
                std::vector<Vec2> offsets;
                for (const Json& stream : answer.value) {
                    for (const Vec2& p : points_from(stream))
                        offsets.push_back(place_of(p, n).offset);
                }
                const double p = chi_square_p_value(uniform_square_chi_square(offsets, kBins),
                                                    kBins * kBins - 1);
                return p >= alpha ? right() : wrong(want, p_text(p, alpha));
            },
            ""};
}

// Offsets of different strata of one stream independent: the x offsets of strata paired in
// stratum order, (0, 1), (2, 3), ..., binned as points. One random offset reused for every
// stratum puts them all on the diagonal.
ProbeCase strata_independent_case(int n, int stream_count, std::uint64_t seed,
                                  StreamCounter& streams, double alpha) {
    return {"jittered_samples(" + std::to_string(n) + "): strata of one stream independent, " +
                std::to_string(stream_count) + " streams",
            {"jittered_samples", jittered_query(n, seed, streams.next(stream_count))},
            [n, alpha](const ProbeAnswer& answer) {
                const std::string want =
                    "the offsets of two strata independent, chi-square p >= " + full_text(alpha);
                if (answer.kind != ProbeAnswer::Kind::result) return wrong(want, "");
                std::vector<Vec2> pairs;
                for (const Json& stream : answer.value) {
                    std::vector<double> by_stratum(static_cast<std::size_t>(n) * n, 0.5);
                    for (const Vec2& p : points_from(stream)) {
                        const StratumPlace place = place_of(p, n);
                        if (place.a < 0 || place.a >= n || place.b < 0 || place.b >= n) continue;
                        by_stratum[static_cast<std::size_t>(place.b) * n + place.a] =
                            place.offset.x;
                    }
                    for (std::size_t k = 0; k + 1 < by_stratum.size(); k += 2)
                        pairs.push_back({by_stratum[k], by_stratum[k + 1]});
                }
                const double p =
                    chi_square_p_value(uniform_square_chi_square(pairs, kBins), kBins * kBins - 1);
                return p >= alpha ? right() : wrong(want, p_text(p, alpha));
            },
            ""};
}

// The same stream twice gives the same points, and the next stream others: the samples come from
// the RandomStream handed in, not from a generator of the student's own, nor from constants.
ProbeCase streams_case(const std::string& call, const Json& args_without_streams,
                       std::uint64_t seed, StreamCounter& streams) {
    Json args = args_without_streams;
    const Json two = streams.next(2);
    args["seed"] = seed;
    args["streams"] = Json::array({two.at(0), two.at(0), two.at(1)});
    return {call + ": one stream twice gives the same points, another stream others",
            {call, args},
            [](const ProbeAnswer& answer) {
                const std::string want =
                    "the same points from the same stream, others from the next";
                if (answer.kind != ProbeAnswer::Kind::result) return wrong(want, "");
                const std::vector<Vec2> first = points_from(answer.value.at(0));
                const std::vector<Vec2> again = points_from(answer.value.at(1));
                const std::vector<Vec2> other = points_from(answer.value.at(2));
                if (first != again) return wrong(want, "different points from the same stream");
                if (first == other) return wrong(want, "the same points from another stream");
                return right();
            },
            ""};
}

std::vector<ProbeCase> jittered_cases() {
    const std::uint64_t seed = statistics_seed();
    StreamCounter streams;
    constexpr int tests = 3;
    const double alpha = kCheckAlpha / tests;
    std::vector<ProbeCase> cases;
    for (int n : {1, 2, 3, 4, 7})
        cases.push_back(stratified_case(n, seed, streams));
    cases.push_back(offsets_uniform_case(4, 500, seed, streams, alpha));
    cases.push_back(offsets_uniform_case(2, 2000, seed, streams, alpha));
    cases.push_back(strata_independent_case(4, 500, seed, streams, alpha));
    cases.push_back(streams_case("jittered_samples", Json{{"strata", 3}}, seed, streams));
    return cases;
}

// --- random_samples

ProbeCase random_points_case(int count, std::uint64_t seed, StreamCounter& streams) {
    return {
        "random_samples(" + std::to_string(count) + "): the count, in [0, 1)^2, 30 streams",
        {"random_samples", Json{{"count", count}, {"seed", seed}, {"streams", streams.next(30)}}},
        [count](const ProbeAnswer& answer) {
            const std::string want = std::to_string(count) + " points in [0, 1)^2";
            if (answer.kind != ProbeAnswer::Kind::result) return wrong(want, "");
            for (const Json& stream : answer.value) {
                const std::vector<Vec2> points = points_from(stream);
                if (points.size() != static_cast<std::size_t>(count)) {
                    return wrong(want, std::to_string(points.size()) + " points");
                }
                for (const Vec2& p : points) {
                    if (!(p.x >= 0 && p.x < 1 && p.y >= 0 && p.y < 1)) {
                        return wrong(want, point_text(p));
                    }
                }
            }
            return right();
        },
        ""};
}

// All points pooled (`pairs` false), or the x of successive points paired, (p0.x, p1.x),
// (p2.x, p3.x), ... (`pairs` true): uniform, and points of one stream independent. One point
// repeated `count` times passes the first and fails the second.
ProbeCase random_uniform_case(bool pairs, std::uint64_t seed, StreamCounter& streams,
                              double alpha) {
    constexpr int count = 8;
    constexpr int stream_count = 1000;
    return {std::string("random_samples(8): ") +
                (pairs ? "the x of successive points independent" : "points uniform") + ", " +
                std::to_string(stream_count) + " streams pooled",
            {"random_samples",
             Json{{"count", count}, {"seed", seed}, {"streams", streams.next(stream_count)}}},
            [pairs, alpha](const ProbeAnswer& answer) {
                const std::string want = "uniform, chi-square p >= " + full_text(alpha);
                if (answer.kind != ProbeAnswer::Kind::result) return wrong(want, "");
                std::vector<Vec2> binned;
                for (const Json& stream : answer.value) {
                    const std::vector<Vec2> points = points_from(stream);
                    if (!pairs) {
                        binned.insert(binned.end(), points.begin(), points.end());
                        continue;
                    }
                    for (std::size_t k = 0; k + 1 < points.size(); k += 2)
                        binned.push_back({points[k].x, points[k + 1].x});
                }
                const double p =
                    chi_square_p_value(uniform_square_chi_square(binned, kBins), kBins * kBins - 1);
                return p >= alpha ? right() : wrong(want, p_text(p, alpha));
            },
            ""};
}

std::vector<ProbeCase> random_cases() {
    const std::uint64_t seed = statistics_seed();
    StreamCounter streams;
    constexpr int tests = 2;
    const double alpha = kCheckAlpha / tests;
    return {random_points_case(7, seed, streams), random_points_case(1, seed, streams),
            random_uniform_case(false, seed, streams, alpha),
            random_uniform_case(true, seed, streams, alpha),
            streams_case("random_samples", Json{{"count", 5}}, seed, streams)};
}

}  // namespace

std::vector<CheckDefinition> stage8_statistical_checks() {
    const std::string rate = " (false-fail rate 1e-4)";
    return {
        case_check("stage8.statistics.jittered", 8, "oracle",
                   "jittered samples: one per stratum, uniform and independent offsets, from the "
                   "stream handed in" +
                       rate,
                   jittered_cases),
        case_check("stage8.statistics.random", 8, "oracle",
                   "random samples: uniform, independent, from the stream handed in" + rate,
                   random_cases),
        case_check("stage8.statistics.pixel_colour", 8, "oracle",
                   "a pixel's mean over an edge and a ramp against the exact coverage, and the "
                   "variance of stratified samples" +
                       rate,
                   pixel_cases),
        case_check("stage8.statistics.quad_light_shading", 8, "oracle",
                   "soft shadows: the mean over seeds against the light's integral, a blocker "
                   "over half of it, a light half behind the surface, its dark side" +
                       rate,
                   shading_cases),
    };
}

}  // namespace raystep::grade
