#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "app/check/ray_case.h"
#include "app/check/stage3_methods.h"

namespace raystep {

// The speed-against-error study of docs/stage3.md, "Speed against error": every intersection
// test, in double and in float, on the same decided ray cases, scored against the exact answers
// and timed on the same rays. One point per method and family: how fast, how often wrong, how
// far off in t.

/// A test under study: the function, and how the charts name it.
struct ParetoMethod {
    Stage3Method method;    ///< a sphere, triangle or plane test
    std::string label;      ///< "Möller-Trumbore", "stable sphere"
    std::string precision;  ///< "double" or "float"
};

/// One method over one family.
struct ParetoPoint {
    std::string label;
    std::string precision;
    std::string function;   ///< the C++ function's name, to find its code
    std::size_t cases = 0;  ///< the family's cases with a primitive this method tests
    std::size_t false_hits = 0;
    std::size_t false_misses = 0;  ///< leaks on watertight cases included: a hit nobody reported
    /// |t - exact t| in double ulps over the hits both the method and the exact answer report:
    /// float's own rounding is 2^29 of them.
    double t_ulps_median = 0.0;
    double t_ulps_p99 = 0.0;
    double t_ulps_max = 0.0;
    /// Ray-primitive tests, in millions per second on one thread, timed on the family's first
    /// 2,048 pairs the method tests (scored on all of them).
    double mrays_per_second = 0.0;

    /// False hits and false misses, as a share of the cases: 0 to 1.
    double wrong_share() const {
        if (cases == 0) return 0.0;
        return static_cast<double>(false_hits + false_misses) / static_cast<double>(cases);
    }
};

struct ParetoFamily {
    std::string name;
    std::string description;
    std::size_t cases = 0;
    std::vector<ParetoPoint> points;  ///< the methods that apply, in the order given
};

/// How long each timing sample runs, and how many are taken (the best counts).
struct ParetoTiming {
    double sample_seconds = 0.02;
    int samples = 5;
};

/// Scores and times each method that applies to the family; methods that apply to none of its
/// cases are left out. Throws std::runtime_error naming a method that is a stub.
ParetoFamily measure_pareto_family(const CaseFamily& family,
                                   const std::vector<ParetoMethod>& methods,
                                   const ParetoTiming& timing = {});

/// Every family's points as one Markdown table.
std::string pareto_table(const std::vector<ParetoFamily>& families);

}  // namespace raystep
