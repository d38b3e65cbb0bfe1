#include "studies/structures/threshold.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <memory>

#include "base/errors/not_implemented.h"
#include "studies/common/bench_timing.h"
#include "studies/common/markdown_table.h"
#include "studies/common/number_text.h"
#include "studies/structures/bench_geometry.h"
#include "studies/structures/bench_rays.h"

namespace raystep {

namespace {

constexpr std::uint64_t kThresholdSeed = 512;

// Each timing repeats its work until it takes at least this long: a steady_clock reading costs
// tens of nanoseconds, and a tiny scene's build or pass takes microseconds.
constexpr double kMinimumTiming = 0.02;

// The best over `runs` of the mean time of one call of `work` (which returns its own seconds, so
// that it can leave untimed set-up out), the calls repeated until each run takes kMinimumTiming.
template <class Work>
double seconds_per_call(int runs, Work&& work) {
    const double first = work();
    const int repeats =
        std::max(1, static_cast<int>(std::ceil(kMinimumTiming / std::max(first, 1e-9))));
    double best = std::numeric_limits<double>::infinity();  // the first call only warmed up
    for (int run = 0; run < runs; ++run) {
        double total = 0.0;
        for (int k = 0; k < repeats; ++k)
            total += work();
        best = std::min(best, total / repeats);
    }
    return best;
}

// Seconds per ray of one pass of a built structure over the rays, on one thread.
double seconds_per_ray(const BenchStructure& structure, const std::vector<Ray>& rays, int runs) {
    std::vector<BenchHit> answers(rays.size());
    const double pass = seconds_per_call(runs, [&] {
        return seconds_of(
            [&] { structure.closest_hits(rays.data(), rays.size(), answers.data(), nullptr); });
    });
    return pass / static_cast<double>(rays.size());
}

ThresholdPoint measure_point(const BenchCandidate& brute_force, const BenchCandidate& bvh,
                             const PrimitiveList& primitives, const std::vector<Ray>& rays,
                             const ThresholdOptions& options) {
    ThresholdPoint point;
    point.n = primitives.spheres.size() + primitives.triangles.size();

    std::unique_ptr<BenchStructure> brute = brute_force.make(primitives);
    brute->build();
    point.brute_force_ns = 1e9 * seconds_per_ray(*brute, rays, options.runs);

    // A fresh structure for each build, made outside the timing
    const double build = seconds_per_call(options.runs, [&] {
        std::unique_ptr<BenchStructure> structure = bvh.make(primitives);
        return seconds_of([&] { structure->build(); });
    });
    std::unique_ptr<BenchStructure> structure = bvh.make(primitives);
    structure->build();
    point.bvh_build_us = 1e6 * build;
    point.bvh_query_ns = 1e9 * seconds_per_ray(*structure, rays, options.runs);

    const double image_rays = static_cast<double>(options.image_width) * options.image_height;
    point.bvh_ns = point.bvh_query_ns + 1e9 * build / image_rays;
    return point;
}

}  // namespace

std::vector<ThresholdCurve> measure_threshold(const BenchCandidate& brute_force,
                                              const BenchCandidate& bvh,
                                              const ThresholdOptions& options) {
    std::vector<ThresholdCurve> curves;
    for (const std::string kind : {"triangles", "spheres"}) {
        ThresholdCurve& curve = curves.emplace_back();
        curve.kind = kind;
        try {
            for (const std::size_t n : options.sizes) {
                PrimitiveList primitives;
                if (kind == "triangles") {
                    primitives.triangles = random_triangles(n, kThresholdSeed);
                } else {
                    primitives.spheres = random_spheres(n, kThresholdSeed);
                }
                const std::vector<Ray> rays = primary_rays(
                    bench_bounds(primitives), options.timed_width, options.timed_height);
                curve.points.push_back(measure_point(brute_force, bvh, primitives, rays, options));
            }
        } catch (const NotImplemented& stub) {
            curve.failure = std::string("not implemented: ") + stub.what();
        } catch (const std::exception& error) {
            curve.failure = std::string("failed: ") + error.what();
        }
        if (!curve.failure.empty()) curve.points.clear();
        curve.bvh_pays_from = bvh_pays_from(curve.points);
    }
    return curves;
}

std::optional<std::size_t> bvh_pays_from(const std::vector<ThresholdPoint>& points) {
    std::optional<std::size_t> from;
    for (auto point = points.rbegin(); point != points.rend(); ++point) {
        if (!(point->bvh_ns < point->brute_force_ns)) break;
        from = point->n;
    }
    return from;
}

std::string threshold_report(const std::vector<ThresholdCurve>& curves,
                             const ThresholdOptions& options) {
    const std::string image =
        std::to_string(options.image_width) + " x " + std::to_string(options.image_height);
    std::string text;
    for (const ThresholdCurve& curve : curves) {
        text += "\n" + curve.kind + ":\n\n";
        if (!curve.failure.empty()) {
            text += curve.failure + "\n";
            continue;
        }
        MarkdownTable table({"n", "brute force ns/ray", "BVH query ns/ray", "BVH build us",
                             "BVH ns/ray, build over " + image, "BVH pays"});
        for (const ThresholdPoint& p : curve.points) {
            table.add_row({std::to_string(p.n), three_digits(p.brute_force_ns),
                           three_digits(p.bvh_query_ns), three_digits(p.bvh_build_us),
                           three_digits(p.bvh_ns), p.bvh_ns < p.brute_force_ns ? "yes" : "no"});
        }
        text += table.text() + "\n";
        text += curve.bvh_pays_from
                    ? "The BVH pays from n = " + std::to_string(*curve.bvh_pays_from) + " " +
                          curve.kind + " on (at that n and every larger one measured).\n"
                    : "The BVH does not pay at any n measured, up to " +
                          std::to_string(options.sizes.back()) + ".\n";
    }
    return text;
}

}  // namespace raystep
