#include "grader/oracle/error_bound_origin.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace raystep {

WideVec leaving_normal(const SurfacePoint& point, const Vec3& direction) {
    const WideVec n = widen(point.normal);
    return glm::dot(n, widen(direction)) < 0 ? -n : n;
}

ErrorBoundOrigin error_bound_origin(const SurfacePoint& point, const Vec3& direction) {
    const WideVec n = leaving_normal(point, direction);
    const Wide d = glm::dot(glm::abs(n), widen(point.error));
    const double size = std::max({std::abs(point.position.x), std::abs(point.position.y),
                                  std::abs(point.position.z), static_cast<double>(d)});
    // At the origin with no error, the step goes to the smallest subnormal.
    const double ulp = std::max(std::ldexp(size, -52), std::numeric_limits<double>::denorm_min());
    return {DoubleDoubleVec3(point.position), double_double(n), double_double(d), 4 * ulp};
}

}  // namespace raystep
