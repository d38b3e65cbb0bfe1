#pragma once

#include "base/math/types.h"

namespace raystep {

// The geometric primitives of the scene format, in the coordinates they were written in (their
// object space). Intersection with them is stage 3.

/// All points p with |p - center| = radius.
struct Sphere {
    Vec3 center;
    double radius;
};

/// The triangle p0 p1 p2. Its geometric normal is (p1 - p0) x (p2 - p0): vertices that appear
/// counter-clockwise from a viewpoint make the normal face that viewpoint.
struct Triangle {
    Vec3 p0;
    Vec3 p1;
    Vec3 p2;
};

/// The infinite plane through `point`, perpendicular to `normal` (which need not be unit length).
struct Plane {
    Vec3 point;
    Vec3 normal;
};

}  // namespace raystep
