#include "grading/8_sampling/sampling_oracle.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <glm/geometric.hpp>

#include "grader/oracle/wide_vec.h"

namespace raystep {

namespace {

const double kInfinity = std::numeric_limits<double>::infinity();

struct WideSample {
    WideVec direction;
    Wide distance;
    Wide share;  ///< the intensity over the radiance
};

WideSample wide_sample(const QuadLight& light, const Vec3& point, const Vec2& u, int count) {
    const WideVec a = widen(light.corner);
    const WideVec ab = widen(light.edge1);
    const WideVec ac = widen(light.edge2);
    const WideVec y = a + static_cast<Wide>(u.x) * ab + static_cast<Wide>(u.y) * ac;
    const WideVec to_light = y - widen(point);
    const Wide d = length(to_light);
    const WideVec l = (1 / d) * to_light;
    const Wide area_cos = std::max(dot(cross(ab, ac), l), Wide(0));
    return {l, d, area_cos / (kWidePi * d * d * count)};
}

}  // namespace

Ray expected_perspective_ray(const PerspectiveCamera& camera, const Vec2& film) {
    const Wide alpha = 2 * static_cast<Wide>(film.x) / camera.width - 1;
    const Wide beta = 1 - 2 * static_cast<Wide>(film.y) / camera.height;
    const WideVec d = (alpha * camera.half_width) * widen(camera.frame.u) +
                      (beta * camera.half_height) * widen(camera.frame.v) - widen(camera.frame.w);
    return {camera.eye, narrow((1 / length(d)) * d), 0.0, kInfinity};
}

Ray expected_orthographic_ray(const OrthographicCamera& camera, const Vec2& film) {
    const Wide x = camera.left + (static_cast<Wide>(camera.right) - camera.left) *
                                     (static_cast<Wide>(film.x) / camera.width);
    const Wide y = camera.bottom + (static_cast<Wide>(camera.top) - camera.bottom) *
                                       (1 - static_cast<Wide>(film.y) / camera.height);
    const WideVec origin =
        widen(camera.eye) + x * widen(camera.frame.u) + y * widen(camera.frame.v);
    return {narrow(origin), -camera.frame.w, 0.0, kInfinity};
}

LightSample expected_quad_light_sample(const QuadLight& light, const Vec3& point, const Vec2& u,
                                       int count) {
    const WideSample s = wide_sample(light, point, u, count);
    return {narrow(s.direction), static_cast<double>(s.distance),
            narrow(s.share * widen(light.radiance))};
}

Color quad_light_term(const Material& material, const SurfacePoint& point, const QuadLight& light,
                      const Vec2& u) {
    const WideSample s = wide_sample(light, point.position, u, 1);
    const WideVec n = widen(point.shading_normal);
    const Wide n_dot_l = dot(n, s.direction);
    if (!(n_dot_l > 0) || s.share == 0) return Color(0.0);
    const WideVec half = s.direction + widen(point.to_eye);
    const Wide half_length = length(half);
    const Wide n_dot_h = half_length > 0 ? std::max(dot(n, (1 / half_length) * half), Wide(0)) : 0;
    const Wide highlight = std::pow(n_dot_h, static_cast<Wide>(material.shininess));
    const WideVec kd = widen(material.diffuse);
    const WideVec ks = widen(material.specular);
    const WideVec radiance = widen(light.radiance);
    const WideVec reflected = n_dot_l * kd + highlight * ks;
    return narrow(s.share * (radiance * reflected));
}

namespace {

// The midpoint rule on `resolution` x `resolution` cells: in x over the seen part
// [blocked_below, 1), so that the boundary between seen and blocked is a cell edge and the rule
// never straddles it.
WideVec midpoint_rule(const Material& material, const SurfacePoint& point, const QuadLight& light,
                      double blocked_below, int resolution) {
    const double seen = 1.0 - blocked_below;
    WideVec sum{0, 0, 0};
    for (int b = 0; b < resolution; ++b) {
        const double y = (b + 0.5) / resolution;
        for (int a = 0; a < resolution; ++a) {
            const double x = blocked_below + seen * (a + 0.5) / resolution;
            sum = sum + widen(quad_light_term(material, point, light, {x, y}));
        }
    }
    return (static_cast<Wide>(seen) / (static_cast<Wide>(resolution) * resolution)) * sum;
}

}  // namespace

Color quad_light_integral(const Material& material, const SurfacePoint& point,
                          const QuadLight& light, double blocked_below, int resolution) {
    const WideVec coarse = midpoint_rule(material, point, light, blocked_below, resolution);
    const WideVec fine = midpoint_rule(material, point, light, blocked_below, 2 * resolution);
    return narrow((static_cast<Wide>(4) * fine - coarse) / static_cast<Wide>(3));
}

Color regular_quad_light_sum(const Material& material, const SurfacePoint& point,
                             const QuadLight& light, int strata_per_side, double blocked_below) {
    const int n = strata_per_side;
    WideVec sum{0, 0, 0};
    for (int b = 0; b < n; ++b) {
        for (int a = 0; a < n; ++a) {
            const Vec2 u{(a + 0.5) / n, (b + 0.5) / n};
            if (u.x < blocked_below) continue;
            sum = sum + widen(quad_light_term(material, point, light, u));
        }
    }
    return narrow((1 / (static_cast<Wide>(n) * n)) * sum);
}

double half_plane_share(const Vec2& low, const Vec2& high, const Vec2& through,
                        const Vec2& normal) {
    // Sutherland-Hodgman against one half-plane, then the shoelace formula.
    const std::vector<Vec2> corners = {low, {high.x, low.y}, high, {low.x, high.y}};
    const auto side = [&](const Vec2& p) {
        return static_cast<Wide>(p.x - through.x) * normal.x +
               static_cast<Wide>(p.y - through.y) * normal.y;
    };
    std::vector<std::pair<Wide, Wide>> kept;
    for (std::size_t k = 0; k < corners.size(); ++k) {
        const Vec2& p = corners[k];
        const Vec2& q = corners[(k + 1) % corners.size()];
        const Wide sp = side(p);
        const Wide sq = side(q);
        if (sp >= 0) kept.emplace_back(p.x, p.y);
        if ((sp >= 0) != (sq >= 0)) {
            const Wide t = sp / (sp - sq);
            kept.emplace_back(p.x + t * (static_cast<Wide>(q.x) - p.x),
                              p.y + t * (static_cast<Wide>(q.y) - p.y));
        }
    }
    Wide twice_area = 0;
    for (std::size_t k = 0; k < kept.size(); ++k) {
        const auto& [px, py] = kept[k];
        const auto& [qx, qy] = kept[(k + 1) % kept.size()];
        twice_area += px * qy - qx * py;
    }
    const Wide whole = (static_cast<Wide>(high.x) - low.x) * (static_cast<Wide>(high.y) - low.y);
    return static_cast<double>(std::abs(twice_area) / (2 * whole));
}

}  // namespace raystep
