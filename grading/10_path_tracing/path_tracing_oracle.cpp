#include "grading/10_path_tracing/path_tracing_oracle.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/geometric.hpp>

namespace raystep::grade {

namespace {

using Wide = long double;
using WideVec3 = glm::vec<3, long double, glm::defaultp>;

constexpr Wide kPi = 3.141592653589793238462643383279502884L;

WideVec3 wide(const Vec3& v) {
    return {v.x, v.y, v.z};
}

Vec3 narrow(const WideVec3& v) {
    return {static_cast<double>(v.x), static_cast<double>(v.y), static_cast<double>(v.z)};
}

WideVec3 unit(const WideVec3& v) {
    return v / std::sqrt(glm::dot(v, v));
}

// The mirror direction of -wo about n: 2 (n . wo) n - wo.
WideVec3 mirror(const WideVec3& normal, const WideVec3& to_eye) {
    return 2 * glm::dot(normal, to_eye) * normal - to_eye;
}

Vec3 polar(Wide cos_theta, Wide u) {
    const Wide sin_theta = std::sqrt(std::max<Wide>(0, 1 - cos_theta * cos_theta));
    const Wide phi = 2 * kPi * u;
    return narrow({sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta});
}

Wide phong_pdf(Wide cos_alpha, Wide exponent) {
    if (!(cos_alpha > 0)) return 0;
    return (exponent + 1) / (2 * kPi) * std::pow(std::min<Wide>(cos_alpha, 1), exponent);
}

// D(h) from h's cosine and squared sine with the normal.
Wide ggx_d(Wide cos_h, Wide sin2_h, Wide roughness) {
    if (!(cos_h > 0)) return 0;
    const Wide alpha2 = roughness * roughness;
    const Wide denominator = alpha2 * cos_h * cos_h + sin2_h;
    return alpha2 / (kPi * denominator * denominator);
}

Wide smith_g1(Wide cos_theta, Wide roughness) {
    const Wide cos2 = cos_theta * cos_theta;
    const Wide tan2 = (1 - cos2) / cos2;
    return 2 / (1 + std::sqrt(1 + roughness * roughness * tan2));
}

Wide mean(const Color& c) {
    return (static_cast<Wide>(c.x) + c.y + c.z) / 3;
}

WideVec3 brdf_wide(const SurfaceBrdf& brdf, const WideVec3& n, const WideVec3& wi,
                   const WideVec3& wo) {
    const Wide cos_i = glm::dot(n, wi);
    const Wide cos_o = glm::dot(n, wo);
    if (!(cos_i > 0 && cos_o > 0)) return WideVec3(0);
    WideVec3 value = wide(brdf.diffuse) / kPi;
    if (brdf.model == BrdfModel::phong) {
        // Ks (s + 2) / (2 pi) (r . wi)^s where r . wi > 0, r . wi no more than 1.
        const Wide cos_alpha = glm::dot(mirror(n, wo), wi);
        if (!(cos_alpha > 0)) return value;
        const Wide lobe = (brdf.shininess + 2.0L) / (2 * kPi) *
                          std::pow(std::min<Wide>(cos_alpha, 1), brdf.shininess);
        return value + wide(brdf.specular) * lobe;
    }
    const WideVec3 h = unit(wi + wo);
    const Wide cos_h = glm::dot(n, h);
    const WideVec3 tangential = h - cos_h * n;
    const Wide d = ggx_d(cos_h, glm::dot(tangential, tangential), brdf.roughness);
    const Wide g = smith_g1(cos_i, brdf.roughness) * smith_g1(cos_o, brdf.roughness);
    const Wide schlick = std::pow(1 - std::clamp<Wide>(glm::dot(wi, h), 0, 1), 5);
    const WideVec3 ks = wide(brdf.specular);
    const WideVec3 fresnel = ks + (WideVec3(1) - ks) * schlick;
    return value + fresnel * (g * d / (4 * cos_i * cos_o));
}

}  // namespace

double path_tolerance(double expected) {
    return std::max(kPathRelativeTolerance * std::abs(expected), 1e-300);
}

double expected_uniform_hemisphere_pdf(const Vec3& direction) {
    return direction.z >= 0 ? static_cast<double>(1 / (2 * kPi)) : 0.0;
}

double expected_cosine_hemisphere_pdf(const Vec3& direction) {
    return direction.z > 0 ? static_cast<double>(direction.z / kPi) : 0.0;
}

double expected_phong_lobe_pdf(const Vec3& direction, double exponent) {
    if (!(direction.z >= 0)) return 0.0;
    if (direction.z == 0) return exponent == 0 ? static_cast<double>(1 / (2 * kPi)) : 0.0;
    return static_cast<double>((exponent + 1.0L) / (2 * kPi) *
                               std::pow(static_cast<Wide>(direction.z), exponent));
}

double expected_ggx_distribution(const Vec3& half_vector, double roughness) {
    const WideVec3 h = wide(half_vector);
    return static_cast<double>(ggx_d(h.z, h.x * h.x + h.y * h.y, roughness));
}

double expected_ggx_half_vector_pdf(const Vec3& half_vector, double roughness) {
    const WideVec3 h = wide(half_vector);
    return static_cast<double>(ggx_d(h.z, h.x * h.x + h.y * h.y, roughness) *
                               std::max<Wide>(h.z, 0));
}

Vec3 expected_uniform_hemisphere(const Vec2& u) {
    return polar(u.x, u.y);
}

Vec3 expected_cosine_hemisphere(const Vec2& u) {
    return polar(std::sqrt(1 - static_cast<Wide>(u.x)), u.y);
}

Vec3 expected_phong_lobe(const Vec2& u, double exponent) {
    return polar(std::pow(static_cast<Wide>(u.x), 1 / (exponent + 1.0L)), u.y);
}

Vec3 expected_ggx_half_vector(const Vec2& u, double roughness) {
    const Wide tan_theta = roughness * std::sqrt(static_cast<Wide>(u.x)) / std::sqrt(1 - u.x);
    return polar(1 / std::sqrt(1 + tan_theta * tan_theta), u.y);
}

Color expected_brdf(const SurfaceBrdf& brdf, const Vec3& normal, const Vec3& to_light,
                    const Vec3& to_eye) {
    return narrow(brdf_wide(brdf, wide(normal), wide(to_light), wide(to_eye)));
}

double expected_specular_probability(const SurfaceBrdf& brdf) {
    const Wide d = mean(brdf.diffuse);
    const Wide s = mean(brdf.specular);
    const Wide share = d + s > 0 ? s / (d + s) : 0;
    return static_cast<double>(brdf.model == BrdfModel::ggx ? std::max<Wide>(0.25L, share) : share);
}

double expected_brdf_pdf(const SurfaceBrdf& brdf, const Vec3& normal, const Vec3& to_eye,
                         const Vec3& to_light) {
    const WideVec3 n = wide(normal);
    const WideVec3 wo = wide(to_eye);
    const WideVec3 wi = wide(to_light);
    const Wide t = expected_specular_probability(brdf);
    const Wide diffuse = std::max<Wide>(glm::dot(n, wi), 0) / kPi;
    Wide lobe = 0;
    if (t > 0 && brdf.model == BrdfModel::phong) {
        lobe = phong_pdf(glm::dot(mirror(n, wo), wi), brdf.shininess);
    } else if (t > 0) {
        const WideVec3 sum = wi + wo;
        if (glm::dot(sum, sum) > 0) {
            WideVec3 h = unit(sum);
            if (glm::dot(h, n) < 0) h = -h;
            const Wide cos_h = glm::dot(n, h);
            const WideVec3 tangential = h - cos_h * n;
            lobe = ggx_d(cos_h, glm::dot(tangential, tangential), brdf.roughness) *
                   std::max<Wide>(cos_h, 0) / (4 * std::abs(glm::dot(wi, h)));
        }
    }
    return static_cast<double>((1 - t) * diffuse + t * lobe);
}

LightDirectionSample expected_light_direction(const QuadLight& light, const Vec3& point,
                                              const Vec2& u) {
    const WideVec3 y = wide(light.corner) + static_cast<Wide>(u.x) * wide(light.edge1) +
                       static_cast<Wide>(u.y) * wide(light.edge2);
    const WideVec3 to_light = y - wide(point);
    const Wide distance2 = glm::dot(to_light, to_light);
    LightDirectionSample sample;
    if (distance2 == 0) return sample;
    const Wide distance = std::sqrt(distance2);
    const WideVec3 direction = to_light / distance;
    const WideVec3 emitting = glm::cross(wide(light.edge2), wide(light.edge1));
    const Wide area = std::sqrt(glm::dot(emitting, emitting));
    const Wide cos_light = -glm::dot(emitting, direction) / area;
    sample.direction = narrow(direction);
    sample.distance = static_cast<double>(distance);
    if (cos_light == 0) return sample;
    sample.pdf = static_cast<double>(distance2 / (area * std::abs(cos_light)));
    if (cos_light > 0) sample.radiance = light.radiance;
    return sample;
}

double expected_light_direction_pdf(const QuadLight& light, const Vec3& point,
                                    const Vec3& direction) {
    const WideVec3 n = glm::cross(wide(light.edge1), wide(light.edge2));
    const WideVec3 d = unit(wide(direction));
    const Wide facing = glm::dot(n, d);
    if (facing == 0) return 0.0;
    const Wide t = glm::dot(n, wide(light.corner) - wide(point)) / facing;
    if (!(t > 0)) return 0.0;
    const WideVec3 q = wide(point) + t * d - wide(light.corner);
    const Wide n2 = glm::dot(n, n);
    const Wide s = glm::dot(glm::cross(q, wide(light.edge2)), n) / n2;
    const Wide r = glm::dot(glm::cross(wide(light.edge1), q), n) / n2;
    if (!(s >= 0 && s <= 1 && r >= 0 && r <= 1)) return 0.0;
    return static_cast<double>(t * t / std::abs(facing));
}

double expected_balance_heuristic(double pdf, double other_pdf) {
    const Wide sum = static_cast<Wide>(pdf) + other_pdf;
    return sum > 0 ? static_cast<double>(pdf / sum) : 0.0;
}

double expected_power_heuristic(double pdf, double other_pdf) {
    const Wide a = static_cast<Wide>(pdf) * pdf;
    const Wide b = static_cast<Wide>(other_pdf) * other_pdf;
    return a + b > 0 ? static_cast<double>(a / (a + b)) : 0.0;
}

std::optional<Color> expected_russian_roulette(const Color& throughput, double u) {
    const double q = std::min(1.0, std::max({throughput.x, throughput.y, throughput.z}));
    if (!(u < q)) return std::nullopt;
    return narrow(wide(throughput) / static_cast<Wide>(q));
}

Color furnace_radiance(const Color& emission, const Color& albedo, int max_depth) {
    Color sum(0.0);
    for (int k = 0; k < 3; ++k) {
        const Wide a = albedo[k];
        sum[k] = static_cast<double>(
            max_depth < 0 ? emission[k] / (1 - a)
                          : emission[k] * (1 - std::pow(a, max_depth + 1)) / (1 - a));
    }
    return sum;
}

Color floor_radiance(const SurfaceBrdf& brdf, const Vec3& point, const Vec3& normal,
                     const Vec3& to_eye, const QuadLight& light) {
    // Composite 8-point Gauss-Legendre over 48 x 48 cells of the light's (s, r) square.
    constexpr std::array<Wide, 4> kNodes{0.1834346424956498049394761L, 0.5255324099163289858177390L,
                                         0.7966664774136267395915539L,
                                         0.9602898564975362316835609L};
    constexpr std::array<Wide, 4> kWeights{
        0.3626837833783619829651504L, 0.3137066458778872873379622L, 0.2223810344533744705443560L,
        0.1012285362903762591525314L};
    constexpr int kCells = 48;
    std::array<Wide, 8> nodes{};
    std::array<Wide, 8> weights{};
    for (int k = 0; k < 4; ++k) {
        nodes[2 * k] = (1 - kNodes[k]) / 2;
        nodes[2 * k + 1] = (1 + kNodes[k]) / 2;
        weights[2 * k] = weights[2 * k + 1] = kWeights[k] / 2;
    }
    const WideVec3 n = wide(normal);
    const WideVec3 wo = wide(to_eye);
    const WideVec3 emitting = glm::cross(wide(light.edge2), wide(light.edge1));
    const Wide area = std::sqrt(glm::dot(emitting, emitting));
    WideVec3 sum(0);
    for (int a = 0; a < kCells; ++a) {
        for (int b = 0; b < kCells; ++b) {
            for (int i = 0; i < 8; ++i) {
                for (int j = 0; j < 8; ++j) {
                    const Wide s = (a + nodes[i]) / kCells;
                    const Wide r = (b + nodes[j]) / kCells;
                    const WideVec3 y =
                        wide(light.corner) + s * wide(light.edge1) + r * wide(light.edge2);
                    const WideVec3 to_light = y - wide(point);
                    const Wide d2 = glm::dot(to_light, to_light);
                    const WideVec3 wi = to_light / std::sqrt(d2);
                    const Wide cos_light = -glm::dot(emitting, wi) / area;
                    const Wide cos_i = glm::dot(n, wi);
                    if (!(cos_light > 0 && cos_i > 0)) continue;
                    sum += weights[i] * weights[j] * brdf_wide(brdf, n, wi, wo) * cos_i *
                           cos_light / d2;
                }
            }
        }
    }
    const Wide cell_area = area / (kCells * kCells);
    return narrow(sum * cell_area * wide(light.radiance));
}

double form_factor(const Vec3& point, const Vec3& normal, const QuadLight& light) {
    const std::array<WideVec3, 4> corners{
        wide(light.corner), wide(light.corner) + wide(light.edge1),
        wide(light.corner) + wide(light.edge1) + wide(light.edge2),
        wide(light.corner) + wide(light.edge2)};
    Wide sum = 0;
    for (int k = 0; k < 4; ++k) {
        const WideVec3 a = unit(corners[k] - wide(point));
        const WideVec3 b = unit(corners[(k + 1) % 4] - wide(point));
        const WideVec3 across = glm::cross(a, b);
        const Wide angle = std::atan2(std::sqrt(glm::dot(across, across)), glm::dot(a, b));
        sum += angle * glm::dot(unit(across), wide(normal));
    }
    return static_cast<double>(std::abs(sum) / (2 * kPi));
}

}  // namespace raystep::grade
