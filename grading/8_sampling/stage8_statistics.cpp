// Stage 8's statistical checks: a student may place a pattern's samples in any order and consume
// the RandomStream in any way, so their random answers are judged by their distributions, never
// by their values. Each check asks for hundreds of streams of the grader's seed
// (statistics_seed()) in one query per case and runs a few tests on what comes back:
//
// - what holds for every stream (one point per stratum and below its far edge, the film points
//   and shadow rays handed back and the colour they make, no shadow ray behind the surface, no
//   light sample shared by two film samples): deterministic, no false fails;
// - a chi-square test of pooled points against the exact uniform distribution, or a z-test of a
//   mean over streams against the exact value the grader integrates, or a one-sided test of a
//   variance against the exact variance of stratified sampling.
//
// A check's false-fail rate is kCheckAlpha: it runs m tests, each at kCheckAlpha / m
// (Bonferroni), so that a right submission loses a check's points on at most that share of
// seeds. The measured rates, on the reference and on every stage-8 alternative over many seeds,
// each check's power against the bugs it is for, and the commands that measure them:
// docs/measurements/stage8-checks.md.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "app/grade/value_text.h"
#include "grader/grade/checks/judging.h"
#include "grader/grade/checks/stage_checks.h"
#include "grader/grade/checks/statistics_seed.h"
#include "grading/8_sampling/sample_statistics.h"
#include "grading/8_sampling/sampling_calls.h"
#include "grading/8_sampling/stage8_statistics.h"
#include "grading/8_sampling/stream_with_draw.h"

namespace raystep::grade {

namespace {

using probe::StreamPoints;

// Every stream's points, as a sample call answers them; throws where the answer is not that.
StreamPoints stream_points(const ProbeAnswer& answer) {
    return probe::JsonCodec<StreamPoints>::read(answer.value);
}

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
            return "the point " + full_text(p) + " outside [0, 1)^2";
        }
        const StratumPlace place = place_of(p, n);
        if (++seen[static_cast<std::size_t>(place.b) * n + place.a] > 1) {
            return "two points in stratum (" + std::to_string(place.a) + ", " +
                   std::to_string(place.b) + "), one of them " + full_text(p);
        }
    }
    return "";
}

ProbeQuery jittered_query(int n, std::uint64_t seed, const std::vector<std::uint64_t>& streams) {
    return probe::query(probe::jittered_samples_call, {n, seed, streams});
}

// Every stream's points one per stratum of n x n.
std::function<Judgement(const ProbeAnswer&)> stratified_judge(int n, const std::string& want) {
    return [n, want](const ProbeAnswer& answer) {
        if (answer.kind != ProbeAnswer::Kind::result) return wrong(want, "");
        for (const std::vector<Vec2>& points : stream_points(answer)) {
            const std::string problem = stratification_problem(points, n);
            if (!problem.empty()) return wrong(want, problem);
        }
        return right();
    };
}

ProbeCase stratified_case(int n, std::uint64_t seed, StreamCounter& streams) {
    const std::string want = "n^2 = " + std::to_string(n * n) + " points, one in each stratum";
    return {"jittered_samples(" + std::to_string(n) + "): one point per stratum, 64 streams",
            jittered_query(n, seed, streams.next(64)), stratified_judge(n, want), ""};
}

// samples(jittered, n^2) is jittered_samples(n): one point per stratum, not a fall through to
// random points.
ProbeCase samples_stratified_case(int n, std::uint64_t seed, StreamCounter& streams) {
    const std::string want = "n^2 = " + std::to_string(n * n) + " points, one in each stratum";
    return {
        "samples(jittered, " + std::to_string(n * n) + "): one point per stratum, 64 streams",
        probe::query(probe::samples_call, {SamplePattern::jittered, n * n, seed, streams.next(64)}),
        stratified_judge(n, want), ""};
}

// The offsets within their strata, pooled over every stream, binned in 10 x 10 against the
// uniform: a pattern biased inside its strata (offsets in half a stratum, the centres) fails,
// and so do x and y drawn alike.
ProbeCase offsets_uniform_case(int n, int stream_count, std::uint64_t seed, StreamCounter& streams,
                               double alpha) {
    return {"jittered_samples(" + std::to_string(n) + "): offsets in their strata uniform, " +
                std::to_string(stream_count) + " streams pooled",
            jittered_query(n, seed, streams.next(stream_count)),
            [n, alpha](const ProbeAnswer& answer) {
                const std::string want =
                    "offsets uniform over the stratum, chi-square p >= " + full_text(alpha);
                if (answer.kind != ProbeAnswer::Kind::result) return wrong(want, "");
                std::vector<Vec2> offsets;
                for (const std::vector<Vec2>& points : stream_points(answer)) {
                    for (const Vec2& p : points)
                        offsets.push_back(place_of(p, n).offset);
                }
                const double p = chi_square_p_value(uniform_square_chi_square(offsets, kBins),
                                                    kBins * kBins - 1);
                return p >= alpha ? right() : wrong(want, p_text(p, alpha));
            },
            ""};
}

// Offsets of neighbouring strata of one stream independent, along rows (strata (a, b) and
// (a + 1, b), a even) or along columns ((a, b) and (a, b + 1), b even): each coordinate's pairs
// of offsets binned as points, one chi-square test for x and one for y. An offset drawn once for
// a whole row (the same y all along it) or column puts that coordinate's pairs on the diagonal,
// and one offset for every stratum puts both there.
ProbeCase neighbours_independent_case(int n, bool along_rows, int stream_count, std::uint64_t seed,
                                      StreamCounter& streams, double alpha) {
    const std::string along = along_rows ? "rows" : "columns";
    return {"jittered_samples(" + std::to_string(n) + "): neighbouring strata along " + along +
                " independent in x and in y, " + std::to_string(stream_count) + " streams",
            jittered_query(n, seed, streams.next(stream_count)),
            [n, along_rows, alpha](const ProbeAnswer& answer) {
                const std::string want =
                    "the offsets of neighbouring strata independent, chi-square p >= " +
                    full_text(alpha) + " for x and for y";
                if (answer.kind != ProbeAnswer::Kind::result) return wrong(want, "");
                std::vector<Vec2> x_pairs;
                std::vector<Vec2> y_pairs;
                for (const std::vector<Vec2>& points : stream_points(answer)) {
                    std::vector<Vec2> by_stratum(static_cast<std::size_t>(n) * n, Vec2(0.5));
                    for (const Vec2& p : points) {
                        const StratumPlace place = place_of(p, n);
                        if (place.a < 0 || place.a >= n || place.b < 0 || place.b >= n) continue;
                        by_stratum[static_cast<std::size_t>(place.b) * n + place.a] = place.offset;
                    }
                    const auto at = [&](int a, int b) {
                        return by_stratum[static_cast<std::size_t>(b) * n + a];
                    };
                    for (int b = 0; b < n; ++b) {
                        for (int a = 0; a < n; ++a) {
                            const bool first =
                                along_rows ? a % 2 == 0 && a + 1 < n : b % 2 == 0 && b + 1 < n;
                            if (!first) continue;
                            const Vec2 one = at(a, b);
                            const Vec2 other = along_rows ? at(a + 1, b) : at(a, b + 1);
                            x_pairs.push_back({one.x, other.x});
                            y_pairs.push_back({one.y, other.y});
                        }
                    }
                }
                const double p_x = chi_square_p_value(uniform_square_chi_square(x_pairs, kBins),
                                                      kBins * kBins - 1);
                const double p_y = chi_square_p_value(uniform_square_chi_square(y_pairs, kBins),
                                                      kBins * kBins - 1);
                if (p_x >= alpha && p_y >= alpha) return right();
                return wrong(want, "x: " + p_text(p_x, alpha) + "; y: " + p_text(p_y, alpha));
            },
            ""};
}

// The stratum column (or row) of a coordinate as the handout and the public tests decide it:
// the boundaries k / n, k = 1 .. n - 1, computed in double, at or below it.
int stratum_by_double_edges(double x, int n) {
    int stratum = 0;
    for (int k = 1; k < n; ++k)
        stratum += x >= static_cast<double>(k) / n ? 1 : 0;
    return stratum;
}

// The extremes of a stream, 0 and 1 - 2^-53, at every draw up to 3 n^2 (a stream of its own for
// each): whichever stratum and coordinate a right pattern puts them in, the point stays in
// [0, 1)^2 and below its stratum's far edge (a + 1.0) / n, the handout's clamp. Without the
// clamp a + (1 - 2^-53) rounds to a + 1, onto the next stratum's edge, or onto 1.
ProbeCase stratum_edge_case(int n, std::uint64_t seed) {
    std::vector<std::uint64_t> chosen;
    for (const double value : {0.0, 1.0 - 0x1p-53}) {
        for (int draw = 0; draw < 3 * n * n; ++draw)
            chosen.push_back(stream_with_draw(seed, static_cast<std::uint64_t>(draw), value));
    }
    const std::string want =
        "n^2 = " + std::to_string(n * n) + " points in [0, 1)^2, one below each stratum's far edge";
    return {"jittered_samples(" + std::to_string(n) + "): 0 and 1 - 2^-53 at every draw, " +
                std::to_string(chosen.size()) + " streams",
            jittered_query(n, seed, chosen),
            [n, want](const ProbeAnswer& answer) {
                if (answer.kind != ProbeAnswer::Kind::result) return wrong(want, "");
                for (const std::vector<Vec2>& points : stream_points(answer)) {
                    if (points.size() != static_cast<std::size_t>(n) * n) {
                        return wrong(want, std::to_string(points.size()) + " points");
                    }
                    std::vector<int> seen(points.size(), 0);
                    for (const Vec2& p : points) {
                        if (!(p.x >= 0 && p.x < 1 && p.y >= 0 && p.y < 1)) {
                            return wrong(want, "the point " + full_text(p) + " outside [0, 1)^2");
                        }
                        const int a = stratum_by_double_edges(p.x, n);
                        const int b = stratum_by_double_edges(p.y, n);
                        if (++seen[static_cast<std::size_t>(b) * n + a] > 1) {
                            return wrong(want, "two points in stratum (" + std::to_string(a) +
                                                   ", " + std::to_string(b) + "), one of them " +
                                                   full_text(p));
                        }
                    }
                }
                return right();
            },
            ""};
}

// The same stream twice gives the same points, and the next stream others: the samples come from
// the RandomStream handed in, not from a generator of the student's own, nor from constants.
template <class Question>
ProbeCase streams_case(const probe::ProbeCall<Question, StreamPoints>& call, Question question,
                       std::uint64_t seed, StreamCounter& streams) {
    const std::vector<std::uint64_t> two = streams.next(2);
    question.seed = seed;
    question.streams = {two[0], two[0], two[1]};
    return {
        std::string(call.name) + ": one stream twice gives the same points, another stream others",
        probe::query(call, question),
        [](const ProbeAnswer& answer) {
            const std::string want = "the same points from the same stream, others from the next";
            if (answer.kind != ProbeAnswer::Kind::result) return wrong(want, "");
            const StreamPoints points = stream_points(answer);
            if (points.size() != 3) return wrong(want, std::to_string(points.size()) + " streams");
            const std::vector<Vec2>& first = points[0];
            const std::vector<Vec2>& again = points[1];
            const std::vector<Vec2>& other = points[2];
            if (first != again) return wrong(want, "different points from the same stream");
            if (first == other) return wrong(want, "the same points from another stream");
            return right();
        },
        ""};
}

std::vector<ProbeCase> make_jittered_cases() {
    const std::uint64_t seed = statistics_seed();
    StreamCounter streams;
    // Two uniform offsets, and x and y along rows and along columns.
    constexpr int tests = 6;
    const double alpha = kCheckAlpha / tests;
    std::vector<ProbeCase> cases;
    for (int n : {1, 2, 3, 4, 7})
        cases.push_back(stratified_case(n, seed, streams));
    cases.push_back(offsets_uniform_case(4, 500, seed, streams, alpha));
    cases.push_back(offsets_uniform_case(2, 2000, seed, streams, alpha));
    cases.push_back(neighbours_independent_case(4, true, 500, seed, streams, alpha));
    cases.push_back(streams_case(probe::jittered_samples_call, {3, 0, {}}, seed, streams));
    cases.push_back(neighbours_independent_case(4, false, 500, seed, streams, alpha));
    cases.push_back(samples_stratified_case(4, seed, streams));
    for (int n : {3, 4})
        cases.push_back(stratum_edge_case(n, seed));
    return cases;
}

// --- random_samples

ProbeCase random_points_case(int count, std::uint64_t seed, StreamCounter& streams) {
    return {"random_samples(" + std::to_string(count) + "): the count, in [0, 1)^2, 30 streams",
            probe::query(probe::random_samples_call, {count, seed, streams.next(30)}),
            [count](const ProbeAnswer& answer) {
                const std::string want = std::to_string(count) + " points in [0, 1)^2";
                if (answer.kind != ProbeAnswer::Kind::result) return wrong(want, "");
                for (const std::vector<Vec2>& points : stream_points(answer)) {
                    if (points.size() != static_cast<std::size_t>(count)) {
                        return wrong(want, std::to_string(points.size()) + " points");
                    }
                    for (const Vec2& p : points) {
                        if (!(p.x >= 0 && p.x < 1 && p.y >= 0 && p.y < 1)) {
                            return wrong(want, full_text(p));
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
            probe::query(probe::random_samples_call, {count, seed, streams.next(stream_count)}),
            [pairs, alpha](const ProbeAnswer& answer) {
                const std::string want = "uniform, chi-square p >= " + full_text(alpha);
                if (answer.kind != ProbeAnswer::Kind::result) return wrong(want, "");
                std::vector<Vec2> binned;
                for (const std::vector<Vec2>& points : stream_points(answer)) {
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
            streams_case(probe::random_samples_call, {5, 0, {}}, seed, streams)};
}

}  // namespace

std::vector<ProbeCase> jittered_cases() {
    return make_jittered_cases();
}

std::vector<CheckDefinition> stage8_statistical_checks() {
    const std::string rate = " (false-fail rate 1e-4)";
    return {
        case_check("stage8.statistics.jittered", 8, "oracle",
                   "jittered samples: one per stratum and below its far edge, from samples() too, "
                   "uniform offsets, neighbours independent along rows and columns, from the "
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
                   "over half of it, a light half and wholly behind the surface (no shadow ray "
                   "there), its dark side" +
                       rate,
                   shading_cases),
        case_check("stage8.statistics.film_and_light", 8, "oracle",
                   "a pixel under a quad light: light samples of its own for each film sample, "
                   "independent of the film points" +
                       rate,
                   film_and_light_cases),
    };
}

}  // namespace raystep::grade
