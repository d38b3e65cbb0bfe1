#pragma once

// A yes/no decision under the rounding budget: which answers a correct double-precision test
// could give. A decision that could go both ways puts a case near a boundary.

#include <cmath>

#include "stages/2_rays/ray.h"

namespace raystep {

struct PossibleAnswers {
    bool yes = false;
    bool no = false;

    bool ambiguous() const { return yes && no; }
};

/// The exact answer, and the other one too when `near` (within rounding of the boundary).
inline PossibleAnswers possible(bool exact, bool near) {
    return {exact || near, !exact || near};
}

/// Both decisions must say yes.
inline PossibleAnswers both(PossibleAnswers a, PossibleAnswers b) {
    return {a.yes && b.yes, a.no || b.no};
}

/// t within `tolerance` of t_min or of a finite t_max: rounding may put it on either side.
inline bool near_range_end(const Ray& ray, double t, double tolerance) {
    return std::abs(t - ray.t_min) <= tolerance ||
           (std::isfinite(ray.t_max) && std::abs(t - ray.t_max) <= tolerance);
}

}  // namespace raystep
