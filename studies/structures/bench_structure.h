#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>

#include "stages/3_intersect/intersect.h"
#include "stages/4_accel/traversal.h"

namespace raystep {

/// A closest hit in the one form every benchmarked structure can give, so that two structures'
/// answers compare with ==: the primitive's number in closest_hit's order (spheres first, then
/// triangles, then planes) and the hit's t.
struct BenchHit {
    static constexpr std::uint32_t kMiss = std::numeric_limits<std::uint32_t>::max();
    std::uint32_t primitive = kMiss;  ///< kMiss when the ray hit nothing
    double t = std::numeric_limits<double>::infinity();

    bool operator==(const BenchHit& other) const {
        return primitive == other.primitive && t == other.t;
    }
    bool operator!=(const BenchHit& other) const { return !(*this == other); }
};

/// The BenchHit of closest_hit's answer over a list with these sphere and triangle counts.
BenchHit bench_hit(const std::optional<PrimitiveHit>& hit, std::size_t sphere_count,
                   std::size_t triangle_count);

/// Which counters of TraversalStats a structure fills; the others read "-" in the report.
struct StatsCoverage {
    bool nodes = false;
    bool primitive_tests = false;
};

/// One acceleration structure (or brute force) under measurement. Its factory prepares the input
/// in the structure's own format, untimed; `build` is the construction the bench times.
class BenchStructure {
  public:
    virtual ~BenchStructure() = default;

    /// Builds over the primitives the factory was given. Called once; timed.
    virtual void build() = 0;

    /// answers[k] = the closest hit of rays[k] for k < count, each ray queried on its own. Adds
    /// what the queries cost to `stats` when it is not null. Safe to call from several threads at
    /// once after build. Throws what the structure throws (NotImplemented for a stub).
    virtual void closest_hits(const Ray* rays, std::size_t count, BenchHit* answers,
                              TraversalStats* stats) const = 0;

    /// The counters closest_hits fills.
    virtual StatsCoverage coverage() const = 0;
};

/// Makes an unbuilt structure over a scene's spheres and triangles. The list outlives the
/// structure, which may keep a reference to it.
using BenchFactory = std::function<std::unique_ptr<BenchStructure>(const PrimitiveList&)>;

/// A structure the bench measures, as a row of its tables.
struct BenchCandidate {
    std::string name;  ///< the row's label: "BVH SAH", "grid", "Embree 3.13.5", ...
    BenchFactory make;
    /// Runs only on an evenly spaced subsample of a workload's rays, sized by the bench's budget of
    /// primitive tests: brute force, whose cost per ray grows with the scene.
    bool subsampled = false;
    /// The largest scene it is run on at all; larger scenes skip it.
    std::size_t max_primitives = std::numeric_limits<std::size_t>::max();
    /// The structure the others are compared with (its ratios are 1).
    bool baseline = false;
    /// False for brute force, which has nothing to build: its build columns read "-".
    bool builds = true;
    /// The same structure built on one thread, for a like-for-like build time beside our
    /// single-threaded builders; empty when the structure has no such setting.
    BenchFactory make_single_threaded;
    /// The instruction set it is held to, below the best the processor has; empty: not held.
    std::string isa;
    /// For a baseline that can be held to an instruction set (Embree's device option max_isa):
    /// the same baseline held to `isa`. Empty when it cannot be.
    std::function<BenchCandidate(const std::string& isa)> held_to;
};

}  // namespace raystep
