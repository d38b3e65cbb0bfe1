#include "grading/3_intersect/decide_cases.h"

#include <cmath>
#include <limits>

#include "grading/3_intersect/exact_intersection.h"

namespace raystep {

namespace {

// The spacing of doubles at x: the larger of its two gaps.
double ulp(double x) {
    const double up = std::nextafter(x, std::numeric_limits<double>::infinity()) - x;
    const double down = x - std::nextafter(x, -std::numeric_limits<double>::infinity());
    return std::max(up, down);
}

}  // namespace

void decide_cases(CaseFamily& family, double t_ulps) {
    for (RayCase& ray_case : family.cases) {
        for (CasePrimitive& primitive : ray_case.primitives) {
            primitive.expected = expect_primitive(ray_case.ray, primitive.shape);
            if (t_ulps > 0.0 && !std::isnan(primitive.expected.t)) {
                primitive.expected.t_tolerance = t_ulps * ulp(primitive.expected.t);
            }
        }
    }
}

}  // namespace raystep
