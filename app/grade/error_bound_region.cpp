#include "app/grade/error_bound_region.h"

#include <cmath>

#include "app/grade/value_text.h"

namespace raystep::grade {

bool within(const ErrorBoundOrigin& region, const Vec3& origin) {
    // Lengths scaled by the power of 2 that brings `ulps` near 1, exactly: about a point near 0 the
    // region is a few subnormals wide, where products and squares would underflow.
    const int exponent =
        std::isfinite(region.ulps) && region.ulps > 0 ? std::ilogb(region.ulps) : 0;
    const auto scaled = [exponent](const DoubleDouble& x) { return ldexp(x, -exponent); };
    const DoubleDoubleVec3 difference = DoubleDoubleVec3(origin) - region.point;
    const DoubleDoubleVec3 moved{scaled(difference.x), scaled(difference.y), scaled(difference.z)};
    const DoubleDouble offset = scaled(region.offset);
    const DoubleDouble ulps = scaled(DoubleDouble(region.ulps));

    const DoubleDouble along = dot(moved, region.normal);
    const DoubleDouble sideways = length(moved - along * region.normal);
    return along > offset && along <= offset + ulps && sideways <= ulps;
}

std::string region_text(const ErrorBoundOrigin& region) {
    const double d = region.offset.hi;
    return "origin more than " + full_text(d) + " and at most " + full_text(d + region.ulps) +
           " along " + full_text(narrow(region.normal)) + " from the point " +
           full_text(narrow(region.point)) + ", within " + full_text(region.ulps) + " of that line";
}

}  // namespace raystep::grade
