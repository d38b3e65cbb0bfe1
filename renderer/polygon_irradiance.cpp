#include "renderer/polygon_irradiance.h"

#include <array>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>

namespace raystep {

namespace {

// The polygon's vertices relative to the point, clipped to the half-space above the surface
// (Sutherland-Hodgman against one plane): a quad keeps at most five.
std::vector<Vec3> clipped_to_horizon(const std::array<Vec3, 4>& polygon, const Vec3& normal) {
    std::vector<Vec3> kept;
    for (std::size_t k = 0; k < polygon.size(); ++k) {
        const Vec3& a = polygon[k];
        const Vec3& b = polygon[(k + 1) % polygon.size()];
        const double height_a = glm::dot(normal, a);
        const double height_b = glm::dot(normal, b);
        if (height_a >= 0.0) kept.push_back(a);
        if ((height_a >= 0.0) != (height_b >= 0.0)) {
            kept.push_back(a + (b - a) * (height_a / (height_a - height_b)));
        }
    }
    return kept;
}

}  // namespace

double quad_light_irradiance(const QuadLight& light, const Vec3& point, const Vec3& normal) {
    const Vec3 a = light.corner - point;
    const Vec3 emitting_side = glm::cross(light.edge2, light.edge1);
    if (!(glm::dot(a, emitting_side) < 0.0)) return 0.0;  // behind the light, or in its plane
    const std::vector<Vec3> polygon = clipped_to_horizon(
        {a, a + light.edge1, a + light.edge1 + light.edge2, a + light.edge2}, normal);
    Vec3 phi(0.0);
    for (std::size_t k = 0; k < polygon.size(); ++k) {
        const Vec3& from = polygon[k];
        const Vec3& to = polygon[(k + 1) % polygon.size()];
        const Vec3 across = glm::cross(from, to);
        const double sine = glm::length(across);
        // An edge through the point or pointing at it subtends no angle.
        if (!(sine > 0.0)) continue;
        const double theta = std::atan2(sine, glm::dot(from, to));
        phi += 0.5 * theta * across / sine;
    }
    // The edges wind one way or the other as seen from the point; the clipped polygon lies above
    // the horizon, where the integrand cos(theta) is positive, so the magnitude is the answer.
    return std::abs(glm::dot(phi, normal));
}

}  // namespace raystep
