#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "studies/structures/bench_structure.h"

namespace raystep {

/// The cost of one ray through a scene of n primitives, by brute force and by a BVH.
struct ThresholdPoint {
    std::size_t n = 0;
    double brute_force_ns = 0.0;  ///< per ray
    double bvh_query_ns = 0.0;    ///< per ray, the build not counted
    double bvh_build_us = 0.0;    ///< one build
    /// Per ray with the build spread over the image's rays: what a render pays.
    double bvh_ns = 0.0;
};

/// Brute force against a BVH over one kind of primitive, for growing n.
struct ThresholdCurve {
    std::string kind;  ///< "triangles" or "spheres"
    std::vector<ThresholdPoint> points;
    /// The smallest n from which the BVH costs less at that n and every larger n measured;
    /// nullopt when it never does.
    std::optional<std::size_t> bvh_pays_from;
    std::string failure;  ///< why there are no points ("not implemented: ..."); empty if measured
};

/// What the threshold measurement runs on.
struct ThresholdOptions {
    std::vector<std::size_t> sizes{1, 2, 4, 8, 16, 32, 64, 128, 256, 512};
    int image_width = 640;  ///< the image whose rays pay for the build
    int image_height = 480;
    /// The rays timed: a coarser image of the same view (a quarter of the side), since the cost
    /// per ray does not depend on how finely the view is sampled.
    int timed_width = 160;
    int timed_height = 120;
    int runs = 3;
};

/// For each size n and each kind (random triangles, then random spheres, bench_geometry.h): the
/// time per primary ray of `brute_force` and of `bvh`, each on one thread, best of the runs, and
/// the BVH's build time. A stub or an error in either ends that kind's curve, in `failure`.
std::vector<ThresholdCurve> measure_threshold(const BenchCandidate& brute_force,
                                              const BenchCandidate& bvh,
                                              const ThresholdOptions& options);

/// The smallest n from which the BVH costs less per ray (its build spread over the image) at
/// that n and every larger n among the points; nullopt when it does not at the largest.
std::optional<std::size_t> bvh_pays_from(const std::vector<ThresholdPoint>& points);

/// The tables (one per kind), and for each kind the line "the BVH pays from n = ...".
std::string threshold_report(const std::vector<ThresholdCurve>& curves,
                             const ThresholdOptions& options);

}  // namespace raystep
