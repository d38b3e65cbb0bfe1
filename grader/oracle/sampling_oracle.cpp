#include "grader/oracle/sampling_oracle.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace raystep {

namespace {

using Real = long double;

struct Wide {
    Real x, y, z;
};

Wide wide(const Vec3& v) {
    return {v.x, v.y, v.z};
}
Wide operator+(const Wide& a, const Wide& b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
Wide operator-(const Wide& a, const Wide& b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
Wide operator*(Real s, const Wide& a) {
    return {s * a.x, s * a.y, s * a.z};
}
Real dot(const Wide& a, const Wide& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
Wide cross(const Wide& a, const Wide& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
Real length(const Wide& a) {
    return std::sqrt(dot(a, a));
}
Vec3 narrow(const Wide& a) {
    return {static_cast<double>(a.x), static_cast<double>(a.y), static_cast<double>(a.z)};
}

constexpr Real kPi = 3.141592653589793238462643383279502884L;
const double kInfinity = std::numeric_limits<double>::infinity();

struct WideSample {
    Wide direction;
    Real distance;
    Real share;  ///< the intensity over the radiance
};

WideSample wide_sample(const QuadLight& light, const Vec3& point, const Vec2& u, int count) {
    const Wide a = wide(light.corner);
    const Wide ab = wide(light.edge1);
    const Wide ac = wide(light.edge2);
    const Wide y = a + static_cast<Real>(u.x) * ab + static_cast<Real>(u.y) * ac;
    const Wide to_light = y - wide(point);
    const Real d = length(to_light);
    const Wide l = (1 / d) * to_light;
    const Real area_cos = std::max(dot(cross(ab, ac), l), Real(0));
    return {l, d, area_cos / (kPi * d * d * count)};
}

}  // namespace

Ray expected_perspective_ray(const PerspectiveCamera& camera, const Vec2& film) {
    const Real alpha = 2 * static_cast<Real>(film.x) / camera.width - 1;
    const Real beta = 1 - 2 * static_cast<Real>(film.y) / camera.height;
    const Wide d = (alpha * camera.half_width) * wide(camera.frame.u) +
                   (beta * camera.half_height) * wide(camera.frame.v) - wide(camera.frame.w);
    return {camera.eye, narrow((1 / length(d)) * d), 0.0, kInfinity};
}

Ray expected_orthographic_ray(const OrthographicCamera& camera, const Vec2& film) {
    const Real x = camera.left + (static_cast<Real>(camera.right) - camera.left) *
                                     (static_cast<Real>(film.x) / camera.width);
    const Real y = camera.bottom + (static_cast<Real>(camera.top) - camera.bottom) *
                                       (1 - static_cast<Real>(film.y) / camera.height);
    const Wide origin = wide(camera.eye) + x * wide(camera.frame.u) + y * wide(camera.frame.v);
    return {narrow(origin), -camera.frame.w, 0.0, kInfinity};
}

LightSample expected_quad_light_sample(const QuadLight& light, const Vec3& point, const Vec2& u,
                                       int count) {
    const WideSample s = wide_sample(light, point, u, count);
    return {narrow(s.direction), static_cast<double>(s.distance),
            narrow(s.share * wide(light.radiance))};
}

Color quad_light_term(const Material& material, const SurfacePoint& point, const QuadLight& light,
                      const Vec2& u) {
    const WideSample s = wide_sample(light, point.position, u, 1);
    const Wide n = wide(point.shading_normal);
    const Real n_dot_l = dot(n, s.direction);
    if (!(n_dot_l > 0) || s.share == 0) return Color(0.0);
    const Wide half = s.direction + wide(point.to_eye);
    const Real half_length = length(half);
    const Real n_dot_h = half_length > 0 ? std::max(dot(n, (1 / half_length) * half), Real(0)) : 0;
    const Real highlight = std::pow(n_dot_h, static_cast<Real>(material.shininess));
    const Wide kd = wide(material.diffuse);
    const Wide ks = wide(material.specular);
    const Wide radiance = wide(light.radiance);
    const Wide reflected = n_dot_l * kd + highlight * ks;
    return narrow(s.share * Wide{radiance.x * reflected.x, radiance.y * reflected.y,
                                 radiance.z * reflected.z});
}

Color quad_light_integral(const Material& material, const SurfacePoint& point,
                          const QuadLight& light, double blocked_below, int resolution) {
    // Cells in x: `resolution` over the seen part [blocked_below, 1), so that the boundary
    // between seen and blocked is a cell edge and the rule never straddles it.
    const double seen = 1.0 - blocked_below;
    Wide sum{0, 0, 0};
    for (int b = 0; b < resolution; ++b) {
        const double y = (b + 0.5) / resolution;
        for (int a = 0; a < resolution; ++a) {
            const double x = blocked_below + seen * (a + 0.5) / resolution;
            sum = sum + wide(quad_light_term(material, point, light, {x, y}));
        }
    }
    return narrow((static_cast<Real>(seen) / (static_cast<Real>(resolution) * resolution)) * sum);
}

Color regular_quad_light_sum(const Material& material, const SurfacePoint& point,
                             const QuadLight& light, int strata_per_side, double blocked_below) {
    const int n = strata_per_side;
    Wide sum{0, 0, 0};
    for (int b = 0; b < n; ++b) {
        for (int a = 0; a < n; ++a) {
            const Vec2 u{(a + 0.5) / n, (b + 0.5) / n};
            if (u.x < blocked_below) continue;
            sum = sum + wide(quad_light_term(material, point, light, u));
        }
    }
    return narrow((1 / (static_cast<Real>(n) * n)) * sum);
}

double half_plane_share(const Vec2& low, const Vec2& high, const Vec2& through,
                        const Vec2& normal) {
    // Sutherland-Hodgman against one half-plane, then the shoelace formula.
    const std::vector<Vec2> corners = {low, {high.x, low.y}, high, {low.x, high.y}};
    const auto side = [&](const Vec2& p) {
        return static_cast<Real>(p.x - through.x) * normal.x +
               static_cast<Real>(p.y - through.y) * normal.y;
    };
    std::vector<std::pair<Real, Real>> kept;
    for (std::size_t k = 0; k < corners.size(); ++k) {
        const Vec2& p = corners[k];
        const Vec2& q = corners[(k + 1) % corners.size()];
        const Real sp = side(p);
        const Real sq = side(q);
        if (sp >= 0) kept.emplace_back(p.x, p.y);
        if ((sp >= 0) != (sq >= 0)) {
            const Real t = sp / (sp - sq);
            kept.emplace_back(p.x + t * (static_cast<Real>(q.x) - p.x),
                              p.y + t * (static_cast<Real>(q.y) - p.y));
        }
    }
    Real twice_area = 0;
    for (std::size_t k = 0; k < kept.size(); ++k) {
        const auto& [px, py] = kept[k];
        const auto& [qx, qy] = kept[(k + 1) % kept.size()];
        twice_area += px * qy - qx * py;
    }
    const Real whole = (static_cast<Real>(high.x) - low.x) * (static_cast<Real>(high.y) - low.y);
    return static_cast<double>(std::abs(twice_area) / (2 * whole));
}

}  // namespace raystep
