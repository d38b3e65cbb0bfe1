#include "app/grade/error_bound_region.h"

#include <glm/geometric.hpp>

#include "app/grade/value_text.h"

namespace raystep::grade {

bool within(const ErrorBoundOrigin& region, const Vec3& origin) {
    const WideVec moved = widen(origin) - region.point;
    const Wide along = glm::dot(moved, region.normal);
    const Wide sideways = glm::length(moved - along * region.normal);
    return along > region.offset && along <= region.offset + region.ulps && sideways <= region.ulps;
}

std::string region_text(const ErrorBoundOrigin& region) {
    const double d = static_cast<double>(region.offset);
    return "origin more than " + full_text(d) + " and at most " + full_text(d + region.ulps) +
           " along " + full_text(narrow(region.normal)) + " from the point " +
           full_text(narrow(region.point)) + ", within " + full_text(region.ulps) + " of that line";
}

}  // namespace raystep::grade
