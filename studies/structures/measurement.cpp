#include "studies/structures/measurement.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <memory>
#include <optional>

#include "base/errors/not_implemented.h"
#include "studies/common/bench_timing.h"
#include "studies/common/number_text.h"
#include "studies/structures/ray_chunks.h"

namespace raystep {

namespace {

// A candidate in the middle of its measurement: its structure while it has one.
struct Contender {
    const BenchCandidate* candidate;
    StructureMeasurement* result;
    std::unique_ptr<BenchStructure> structure;
    std::vector<Ray> rays;  ///< its rays of the ray set being measured
    bool running() const { return result->failure.empty(); }
};

// Runs step(contender) for every contender still running; an exception ends that contender.
template <class Step>
void for_each_running(std::vector<Contender>& contenders, const MeasureOptions& options,
                      const std::string& what, Step&& step) {
    for (Contender& c : contenders) {
        if (!c.running()) continue;
        if (options.progress) options.progress(c.candidate->name + ": " + what);
        try {
            step(c);
        } catch (const NotImplemented& stub) {
            c.result->failure = std::string("not implemented: ") + stub.what();
        } catch (const std::exception& error) {
            c.result->failure = std::string("failed: ") + error.what();
        }
        if (!c.running()) c.structure.reset();
    }
}

// The stride that keeps one pass of a subsampled candidate within the test budget.
std::size_t subsample_stride(std::size_t rays, std::size_t primitives, double test_budget) {
    if (primitives == 0) return 1;
    const double affordable =
        std::max(1.0, std::floor(test_budget / static_cast<double>(primitives)));
    return std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(rays / affordable)));
}

// A candidate's rays of a set: every one, or every stride-th.
std::vector<Ray> rays_run(const RaySet& set, std::size_t stride) {
    std::vector<Ray> rays;
    for (std::size_t k = 0; k < set.rays.size(); k += stride)
        rays.push_back(set.rays[k]);
    return rays;
}

// One pass of a structure over its rays on `threads` threads, answers into `result`, counting
// into stats[worker] when `stats` is given.
void pass(const BenchStructure& structure, const std::vector<Ray>& rays, int threads,
          RayMeasurement& result, std::vector<TraversalStats>* stats) {
    for_each_chunk(rays.size(), chunk_size(rays.size()), threads,
                   [&](std::size_t begin, std::size_t end, int worker) {
                       structure.closest_hits(
                           rays.data() + begin, end - begin, result.answers.data() + begin,
                           stats ? &(*stats)[static_cast<std::size_t>(worker)] : nullptr);
                   });
}

// The best of `runs` builds of each contender by `make`, interleaved; each is left holding its
// last build.
void measure_builds(std::vector<Contender>& contenders, const PrimitiveList& primitives,
                    const MeasureOptions& options, bool single_threaded) {
    for (int run = 0; run < options.runs; ++run) {
        for_each_running(
            contenders, options, single_threaded ? "build on one thread" : "build",
            [&](Contender& c) {
                const BenchFactory& make =
                    single_threaded ? c.candidate->make_single_threaded : c.candidate->make;
                if (!make) return;
                // Let go of the last build first: a baseline may allow one live
                // configuration of its library at a time
                c.structure.reset();
                c.structure = make(primitives);
                const double seconds = seconds_of([&] { c.structure->build(); });
                if (single_threaded) {
                    std::optional<double>& best = c.result->single_thread_build_seconds;
                    best = best ? std::min(*best, seconds) : seconds;
                } else {
                    double& best = c.result->build_seconds;
                    best = run == 0 ? seconds : std::min(best, seconds);
                }
            });
    }
}

void measure_ray_set(std::vector<Contender>& contenders, const RaySet& set,
                     std::size_t primitive_count, const MeasureOptions& options) {
    // Each contender's rays and answers, and the untimed pass that warms up and counts
    for (Contender& c : contenders) {
        if (!c.running()) continue;
        RayMeasurement& r = c.result->ray_sets.emplace_back();
        r.stride = c.candidate->subsampled
                       ? subsample_stride(set.rays.size(), primitive_count, options.test_budget)
                       : 1;
        c.rays = rays_run(set, r.stride);
        r.rays = c.rays.size();
        r.answers.resize(r.rays);
        r.coverage = c.structure->coverage();
    }
    for_each_running(contenders, options, set.name, [&](Contender& c) {
        RayMeasurement& r = c.result->ray_sets.back();
        std::vector<TraversalStats> per_thread(static_cast<std::size_t>(options.threads));
        pass(*c.structure, c.rays, options.threads, r, &per_thread);
        for (const TraversalStats& stats : per_thread) {
            r.stats.nodes += stats.nodes;
            r.stats.primitive_tests += stats.primitive_tests;
        }
    });

    // The timed passes count nothing: counting is work that a render does not do
    const auto time_passes = [&](int threads, double RayMeasurement::*seconds) {
        for (int run = 0; run < options.runs; ++run) {
            for_each_running(contenders, options, set.name, [&](Contender& c) {
                RayMeasurement& r = c.result->ray_sets.back();
                const double time =
                    seconds_of([&] { pass(*c.structure, c.rays, threads, r, nullptr); });
                r.*seconds = run == 0 ? time : std::min(r.*seconds, time);
            });
        }
    };
    time_passes(1, &RayMeasurement::seconds_one_thread);
    if (options.all_threads) time_passes(options.threads, &RayMeasurement::seconds_all_threads);
}

}  // namespace

std::vector<StructureMeasurement> measure_candidates(const std::vector<BenchCandidate>& candidates,
                                                     const PrimitiveList& primitives,
                                                     const std::vector<RaySet>& ray_sets,
                                                     const MeasureOptions& options) {
    std::vector<StructureMeasurement> results(candidates.size());
    std::vector<Contender> contenders;
    const std::size_t primitive_count = primitives.spheres.size() + primitives.triangles.size();
    for (std::size_t k = 0; k < candidates.size(); ++k) {
        StructureMeasurement& result = results[k];
        result.name = candidates[k].name;
        result.baseline = candidates[k].baseline;
        result.builds = candidates[k].builds;
        result.isa = candidates[k].isa;
        if (primitive_count > candidates[k].max_primitives) {
            result.failure = "skipped: " + grouped(primitive_count) +
                             " primitives, over its limit of " +
                             grouped(candidates[k].max_primitives);
        }
        contenders.push_back({&candidates[k], &result, nullptr, {}});
    }

    measure_builds(contenders, primitives, options, false);
    for (const RaySet& set : ray_sets)
        measure_ray_set(contenders, set, primitive_count, options);
    // Every structure let go first, so that a baseline can switch its library to one thread
    for (Contender& c : contenders)
        c.structure.reset();
    measure_builds(contenders, primitives, options, true);
    for (Contender& c : contenders)
        c.structure.reset();

    for (StructureMeasurement& result : results) {
        if (!result.failure.empty()) result.ray_sets.clear();
    }
    return results;
}

double mrays_per_second(std::size_t rays, double seconds) {
    if (!(seconds > 0.0)) return 0.0;  // also a NaN
    return static_cast<double>(rays) / seconds * 1e-6;
}

}  // namespace raystep
