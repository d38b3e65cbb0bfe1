#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "studies/structures/bench_structure.h"

namespace raystep {

/// A set of rays over a scene: one workload, one table of the report.
struct RaySet {
    std::string name;         ///< the workload's name: "bunny-primary"
    std::string description;  ///< "512 x 512 primary rays"
    std::vector<Ray> rays;
};

/// How a candidate is measured.
struct MeasureOptions {
    int threads = 1;          ///< the thread count of the "all threads" measurement
    int runs = 3;             ///< timed runs of each measurement; the best one counts
    bool all_threads = true;  ///< also time on `threads` threads (the growth table does not)
    /// The primitive tests a subsampled candidate may spend on one pass over a ray set: 2^26,
    /// about half a second of brute force on one thread.
    double test_budget = 67108864.0;
    /// Told what is about to be measured ("build", a ray set's name), for a progress line.
    std::function<void(const std::string&)> progress;
};

/// What one candidate did on one ray set.
struct RayMeasurement {
    std::size_t rays = 0;              ///< rays it ran: all the set's, or a subsample
    std::size_t stride = 1;            ///< it ran rays 0, stride, 2 stride, ... of the set
    double seconds_one_thread = 0.0;   ///< for all its rays on one thread, best of the runs
    double seconds_all_threads = 0.0;  ///< the same on MeasureOptions::threads; 0 if not measured
    TraversalStats stats;              ///< summed over its rays
    StatsCoverage coverage;            ///< which counters of `stats` mean something
    std::vector<BenchHit> answers;     ///< answers[k] is its answer for ray k * stride of the set
};

/// What one candidate did on one scene.
struct StructureMeasurement {
    std::string name;
    bool baseline = false;
    bool builds = true;  ///< false for brute force, which has nothing to build
    std::string isa;     ///< the instruction set it was held to (BenchCandidate::isa)
    /// Why there are no numbers ("not implemented: ...", "failed: ...", "skipped: ..."); empty
    /// when the candidate was measured.
    std::string failure;
    double build_seconds = 0.0;  ///< best of the runs
    /// The build on one thread, for a candidate that has make_single_threaded.
    std::optional<double> single_thread_build_seconds;
    std::vector<RayMeasurement> ray_sets;  ///< one per ray set, in their order
};

/// Measures every candidate on a scene, the runs interleaved: each run of a measurement times
/// every candidate in turn, so that a change in the machine's load between runs touches all of
/// them alike and the ratios between them hold. The build: `runs` builds, the best time counts,
/// the last structure is the one queried. Then for each ray set: one untimed pass over its rays
/// on every thread, which warms up and also counts nodes and tests and records the answers;
/// `runs` timed passes on one thread; `runs` timed passes on `threads` threads. Last, the builds
/// of make_single_threaded, once every other structure is gone. A subsampled candidate runs on
/// every stride-th ray, the stride the smallest that keeps a pass within the test budget. A stub
/// (NotImplemented) or any other exception ends that candidate's measurement and is recorded in
/// its `failure`; the others go on, and nothing is thrown. One result per candidate, in order.
std::vector<StructureMeasurement> measure_candidates(const std::vector<BenchCandidate>& candidates,
                                                     const PrimitiveList& primitives,
                                                     const std::vector<RaySet>& ray_sets,
                                                     const MeasureOptions& options);

/// Mrays/s: rays over seconds, in millions; 0 when nothing was timed.
double mrays_per_second(std::size_t rays, double seconds);

}  // namespace raystep
