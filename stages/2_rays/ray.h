#pragma once

#include <limits>

#include "base/math/types.h"

namespace raystep {

// Stage 2: rays. Handout: docs/stage2.md, "Rays".

/// The ray R(t) = A + t D for t in [t_min, t_max]. D need not be unit length; when it is, t is
/// the distance from A.
struct Ray {
    Vec3 origin;     ///< A
    Vec3 direction;  ///< D
    double t_min = 0.0;
    double t_max = std::numeric_limits<double>::infinity();

    /// The point R(t) = A + t D.
    Vec3 at(double t) const;
};

}  // namespace raystep
