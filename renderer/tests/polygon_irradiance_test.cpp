#include "renderer/polygon_irradiance.h"

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include "base/testing/catch.h"

using namespace raystep;

namespace {

// The form factor from a point to a parallel rectangle of sides a x b at height c, one corner
// straight above the point (Howell's catalogue, C-11): E / L = pi F.
double corner_form_factor(double a, double b, double c) {
    const double x = a / c;
    const double y = b / c;
    return (x / std::sqrt(1 + x * x) * std::atan(y / std::sqrt(1 + x * x)) +
            y / std::sqrt(1 + y * y) * std::atan(x / std::sqrt(1 + y * y))) /
           (2.0 * glm::pi<double>());
}

// E / L by the midpoint rule over the light's area: max(cos theta_i, 0) cos theta_l / d^2 dA,
// counting only what the emitting side sends.
double irradiance_by_quadrature(const QuadLight& light, const Vec3& point, const Vec3& normal) {
    const int steps = 1000;
    const Vec3 area_normal = glm::cross(light.edge2, light.edge1);  // the emitting side
    const double area = glm::length(area_normal);
    double sum = 0.0;
    for (int i = 0; i < steps; ++i) {
        for (int j = 0; j < steps; ++j) {
            const Vec3 y =
                light.corner + (i + 0.5) / steps * light.edge1 + (j + 0.5) / steps * light.edge2;
            const Vec3 to_light = y - point;
            const double d2 = glm::dot(to_light, to_light);
            const Vec3 l = to_light / std::sqrt(d2);
            const double cos_i = std::max(glm::dot(normal, l), 0.0);
            const double cos_l = std::max(-glm::dot(area_normal / area, l), 0.0);
            sum += cos_i * cos_l / d2;
        }
    }
    return sum * area / (steps * steps);
}

}  // namespace

TEST_CASE("quad_light_irradiance: a square light straight overhead, by its closed form", "[app]") {
    // A 2 x 2 light at height 1.5 facing down (ac x ab = -y): four corner rectangles of 1 x 1.
    const QuadLight light{Vec3(-1, 1.5, -1), Vec3(0, 0, 2), Vec3(2, 0, 0), Color(1.0), 0};
    const double expected = 4.0 * glm::pi<double>() * corner_form_factor(1.0, 1.0, 1.5);
    CHECK(quad_light_irradiance(light, Vec3(0.0), Vec3(0, 1, 0)) ==
          Approx(expected).epsilon(1e-12));
    // Off the centre, one rectangle of each size: 2 x 0.5, 2 x 1.5 split at x = 0.5 again.
    const Vec3 off(0.5, 0, 0.5);
    const double off_expected =
        glm::pi<double>() * (corner_form_factor(1.5, 1.5, 1.5) + corner_form_factor(0.5, 1.5, 1.5) +
                             corner_form_factor(1.5, 0.5, 1.5) + corner_form_factor(0.5, 0.5, 1.5));
    CHECK(quad_light_irradiance(light, off, Vec3(0, 1, 0)) == Approx(off_expected).epsilon(1e-12));
}

TEST_CASE("quad_light_irradiance: a light across the horizon counts only what lies above it",
          "[app]") {
    // A tilted light that the surface's tangent plane cuts: clipped, then Lambert's formula.
    const QuadLight light{Vec3(-1, -0.5, 1), Vec3(2, 0, 0), Vec3(0, 1.5, 0.5), Color(1.0), 0};
    const Vec3 normal = glm::normalize(Vec3(0, 1, 0.2));
    const double exact = quad_light_irradiance(light, Vec3(0.0), normal);
    CHECK(exact > 0.0);
    CHECK(exact == Approx(irradiance_by_quadrature(light, Vec3(0.0), normal)).epsilon(1e-4));
}

TEST_CASE("quad_light_irradiance: nothing behind the emitting side or under the horizon", "[app]") {
    const QuadLight down{Vec3(-1, 1.5, -1), Vec3(0, 0, 2), Vec3(2, 0, 0), Color(1.0), 0};
    CHECK(quad_light_irradiance(down, Vec3(0, 3, 0), Vec3(0, -1, 0)) == 0.0);    // above it
    CHECK(quad_light_irradiance(down, Vec3(0, 1.5, 5), Vec3(0, 0, -1)) == 0.0);  // in its plane
    CHECK(quad_light_irradiance(down, Vec3(0.0), Vec3(0, -1, 0)) == 0.0);  // the surface faces away
}
