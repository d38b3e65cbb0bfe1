// Stage 5 checks: the op matrices, compose and the moves between frames on hand-worked values
// (public and hidden), and random op chains, rays, points, normals and ellipsoids against the
// same products and roots computed in long double.
//
// Every call but compose gets its transform from here (matrix and inverse built from the ops in
// long double), so that each function is judged on its own.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <string>
#include <utility>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "base/math/portable_random.h"
#include "grader/grade/checks/cpp_literal.h"
#include "grader/grade/checks/judging.h"
#include "grader/grade/checks/stage_checks.h"

namespace raystep::grade {

namespace {

using probe::Json;
using WideVec4 = glm::vec<4, Wide>;
using WideMat = glm::mat<4, 4, Wide>;
// The vector forms (judging.h) beside the matrix forms below.
using grade::narrow;
using grade::widen;

constexpr double kUnit = 0x1p-53;
constexpr Wide kWideUnit = 0x1p-53L;
// A normal's length may be off by 4 ulps of 1 (2^-52 each): every normalization lands within 3.
constexpr double kUnitLength = 4 * 0x1p-52;
constexpr Wide kPi = 3.141592653589793238462643383279502884L;
const double kInf = std::numeric_limits<double>::infinity();

WideMat widen(const Mat4& m) {
    WideMat w;
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r)
            w[c][r] = m[c][r];
    }
    return w;
}

Mat4 narrow(const WideMat& w) {
    Mat4 m;
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r)
            m[c][r] = static_cast<double>(w[c][r]);
    }
    return m;
}

WideMat absolute(const WideMat& m) {
    WideMat a;
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r)
            a[c][r] = std::abs(m[c][r]);
    }
    return a;
}

TransformOp translate_op(const Vec3& offset) {
    return {TransformOp::Kind::translate, offset, 0.0};
}

TransformOp rotate_op(const Vec3& axis, double degrees) {
    return {TransformOp::Kind::rotate, axis, degrees};
}

TransformOp scale_op(const Vec3& factors) {
    return {TransformOp::Kind::scale, factors, 0.0};
}

// The op matrices in long double.
WideMat wide_translation(const WideVec& offset) {
    WideMat m(1.0L);
    m[3] = WideVec4(offset, 1.0L);
    return m;
}

WideMat wide_scaling(const WideVec& factors) {
    WideMat m(1.0L);
    for (int k = 0; k < 3; ++k)
        m[k][k] = factors[k];
    return m;
}

// Rodrigues: c I + (1 - c) a a^T + s [a]x, a the unit axis (a long double squares 1e-200).
WideMat wide_rotation(const Vec3& axis, Wide degrees) {
    const WideVec a = widen(axis) / glm::length(widen(axis));
    const Wide theta = degrees * kPi / 180;
    const Wide c = std::cos(theta);
    const Wide s = std::sin(theta);
    WideMat m(1.0L);
    for (int column = 0; column < 3; ++column) {
        for (int row = 0; row < 3; ++row) {
            m[column][row] = (row == column ? c : 0) + (1 - c) * a[row] * a[column];
        }
    }
    m[1][0] -= s * a.z;
    m[2][0] += s * a.y;
    m[0][1] += s * a.z;
    m[2][1] -= s * a.x;
    m[0][2] -= s * a.y;
    m[1][2] += s * a.x;
    return m;
}

// An op's matrix, its inverse in closed form, and the sizes its entries round at: a rotation's
// entries are off by a few ulps of 1 and of the angle in radians, wherever they are near 0.
struct WideOp {
    WideMat matrix;
    WideMat inverse;
    WideMat size;
    WideMat inverse_size;
};

WideOp wide_op(const TransformOp& op) {
    switch (op.kind) {
        case TransformOp::Kind::translate: {
            const WideMat m = wide_translation(widen(op.vector));
            const WideMat i = wide_translation(-widen(op.vector));
            return {m, i, absolute(m), absolute(i)};
        }
        case TransformOp::Kind::rotate: {
            const WideMat m = wide_rotation(op.vector, op.angle_degrees);
            const WideMat i = wide_rotation(op.vector, -Wide(op.angle_degrees));
            WideMat spread(0.0L);
            const Wide angle = 1 + std::abs(op.angle_degrees * kPi / 180);
            for (int c = 0; c < 3; ++c) {
                for (int r = 0; r < 3; ++r)
                    spread[c][r] = angle;
            }
            return {m, i, absolute(m) + spread, absolute(i) + spread};
        }
        case TransformOp::Kind::scale:
            break;
    }
    const WideMat m = wide_scaling(widen(op.vector));
    const WideMat i = wide_scaling(WideVec(1.0L) / widen(op.vector));
    return {m, i, absolute(m), absolute(i)};
}

// M = M1 ... Mn and M^-1 = Mn^-1 ... M1^-1, and the tolerance of each entry: a product of n
// matrices rounds each entry by about n ulps of the same product taken over the entries'
// sizes, whatever the order of the multiplications.
struct WideTransform {
    WideMat matrix;
    WideMat inverse;
    WideMat matrix_tolerance;
    WideMat inverse_tolerance;
};

WideTransform wide_compose(const std::vector<TransformOp>& ops) {
    WideTransform t{WideMat(1.0L), WideMat(1.0L), WideMat(1.0L), WideMat(1.0L)};
    for (const TransformOp& op : ops) {
        const WideOp w = wide_op(op);
        t.matrix = t.matrix * w.matrix;
        t.inverse = w.inverse * t.inverse;
        t.matrix_tolerance = t.matrix_tolerance * w.size;
        t.inverse_tolerance = w.inverse_size * t.inverse_tolerance;
    }
    const Wide ulps = 8 * kWideUnit * (ops.size() + 1);
    t.matrix_tolerance = ulps * t.matrix_tolerance;
    t.inverse_tolerance = ulps * t.inverse_tolerance;
    return t;
}

// The transform the probe gets: the long double products, each rounded once.
Transform transform_of(const std::vector<TransformOp>& ops) {
    const WideTransform w = wide_compose(ops);
    return {narrow(w.matrix), narrow(w.inverse)};
}

std::string op_text(const TransformOp& op) {
    switch (op.kind) {
        case TransformOp::Kind::translate:
            return "translate " + full_text(op.vector);
        case TransformOp::Kind::rotate:
            return "rotate " + full_text(op.vector) + " by " + full_text(op.angle_degrees);
        case TransformOp::Kind::scale:
            break;
    }
    return "scale " + full_text(op.vector);
}

std::string ops_text(const std::vector<TransformOp>& ops) {
    std::string text;
    for (const TransformOp& op : ops)
        text += (text.empty() ? "" : ", ") + op_text(op);
    return "[" + text + "]";
}

std::string matrix_text(const Mat4& m) {
    std::string text;
    for (int r = 0; r < 4; ++r) {
        text += r == 0 ? "rows [" : "; [";
        for (int c = 0; c < 4; ++c)
            text += (c == 0 ? "" : ", ") + full_text(m[c][r]);
        text += "]";
    }
    return text;
}

// Every entry within its tolerance; else the first that is not, and the whole matrix got.
Judgement near_matrix(const Mat4& got, const WideMat& expected, const WideMat& tolerance,
                      const std::string& name) {
    for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c) {
            if (!(std::abs(got[c][r] - expected[c][r]) <= tolerance[c][r])) {
                const std::string entry =
                    name + " row " + std::to_string(r) + " column " + std::to_string(c) + " ";
                return wrong(entry + full_text(static_cast<double>(expected[c][r])) + " (within " +
                                 full_text(static_cast<double>(tolerance[c][r])) + ")",
                             entry + full_text(got[c][r]) + "; " + name + " " + matrix_text(got));
            }
        }
    }
    return right();
}

Judgement near_matrix(const ProbeAnswer& answer, const WideMat& expected,
                      const WideMat& tolerance) {
    if (answer.kind != ProbeAnswer::Kind::result) return wrong(matrix_text(narrow(expected)), "");
    return near_matrix(probe::mat4_from(answer.value), expected, tolerance, "matrix");
}

// rotation(axis, degrees) against Rodrigues in long double.
ProbeCase rotation_case(const Vec3& axis, double degrees) {
    const WideOp w = wide_op(rotate_op(axis, degrees));
    const WideMat tolerance = 8 * kWideUnit * w.size;
    return {"rotation(" + full_text(axis) + ", " + full_text(degrees) + ")",
            {"rotation", Json::array({probe::vec3(axis), probe::number(degrees)})},
            [=](const ProbeAnswer& a) { return near_matrix(a, w.matrix, tolerance); },
            "rotation(" + cpp(axis) + ", " + cpp(degrees) + ")"};
}

// translation and scaling have exact entries.
ProbeCase exact_matrix_case(const std::string& call, const Vec3& v, const WideMat& expected) {
    return {call + "(" + full_text(v) + ")",
            {call, Json::array({probe::vec3(v)})},
            [=](const ProbeAnswer& a) { return near_matrix(a, expected, WideMat(0.0L)); },
            call + "(" + cpp(v) + ")"};
}

ProbeCase invalid_axis_case(const Vec3& axis, double degrees) {
    return {"rotation(" + full_text(axis) + ", " + full_text(degrees) + "): no axis",
            {"rotation", Json::array({probe::vec3(axis), probe::number(degrees)})},
            [](const ProbeAnswer& a) { return threw(a, "invalid_argument"); },
            "rotation(" + cpp(axis) + ", " + cpp(degrees) + ")"};
}

Json ops_json(const std::vector<TransformOp>& ops) {
    Json list = Json::array();
    for (const TransformOp& op : ops)
        list.push_back(probe::transform_op(op));
    return list;
}

// compose's argument as a student writes it: the ops in file order.
std::string compose_code(const std::vector<TransformOp>& ops) {
    std::string code;
    for (const TransformOp& op : ops)
        code += (code.empty() ? "" : ", ") + cpp(op);
    return "compose({" + code + "})";
}

Judgement judge_compose(const ProbeAnswer& answer, const WideTransform& expected,
                        const WideMat& inverse_tolerance) {
    if (answer.kind != ProbeAnswer::Kind::result) {
        return wrong("matrix " + matrix_text(narrow(expected.matrix)), "");
    }
    const Transform got = probe::transform_from(answer.value);
    const Judgement matrix =
        near_matrix(got.matrix, expected.matrix, expected.matrix_tolerance, "matrix");
    if (!matrix.passed) return matrix;
    return near_matrix(got.inverse, expected.inverse, inverse_tolerance, "inverse");
}

ProbeCase compose_case(const std::vector<TransformOp>& ops) {
    const WideTransform expected = wide_compose(ops);
    return {"compose(" + ops_text(ops) + ")",
            {"compose", ops_json(ops)},
            [=](const ProbeAnswer& a) {
                return judge_compose(a, expected, expected.inverse_tolerance);
            },
            compose_code(ops)};
}

// Where every op's inverse is exact in double (a negated offset, a reciprocal that rounds to
// itself) and each entry of their product is a single product, exact too, the inverse must be
// exact: built from the ops, never by inverting M, which divides by its determinant.
ProbeCase exact_inverse_case(const std::vector<TransformOp>& ops) {
    WideTransform expected = wide_compose(ops);
    expected.inverse = widen(narrow(expected.inverse));
    return {"compose(" + ops_text(ops) + "): the inverse from the ops' exact inverses",
            {"compose", ops_json(ops)},
            [=](const ProbeAnswer& a) { return judge_compose(a, expected, WideMat(0.0L)); },
            compose_code(ops)};
}

// A scale with a zero factor has no inverse, and 1 / 0 is infinite: M^-1 must carry that
// infinity on the zero axis's diagonal (NaN where a product meets it) rather than a finite
// stand-in, which would pass for an inverse and be none. M itself and the other axes'
// reciprocals are exact.
ProbeCase singular_scale_case(const Vec3& factors) {
    const std::vector<TransformOp> ops{scale_op(factors)};
    const Mat4 matrix = narrow(wide_scaling(widen(factors)));
    std::string diagonal;
    for (int k = 0; k < 3; ++k) {
        diagonal += (k == 0 ? "" : ", ") + (factors[k] == 0.0 ? std::string("not finite (1 / 0)")
                                                              : full_text(1.0 / factors[k]));
    }
    const std::string text = "matrix " + matrix_text(matrix) + ", inverse diagonal " + diagonal;
    return {"compose(" + ops_text(ops) + "): a zero factor's reciprocal is infinite",
            {"compose", ops_json(ops)},
            [=](const ProbeAnswer& a) {
                if (a.kind != ProbeAnswer::Kind::result) return wrong(text, "");
                const Transform got = probe::transform_from(a.value);
                const Judgement m = near_matrix(got.matrix, widen(matrix), WideMat(0.0L), "matrix");
                if (!m.passed) return m;
                for (int k = 0; k < 3; ++k) {
                    const double entry = got.inverse[k][k];
                    const bool ok =
                        factors[k] == 0.0 ? !std::isfinite(entry) : entry == 1.0 / factors[k];
                    if (!ok) return wrong(text, "inverse " + matrix_text(got.inverse));
                }
                return right();
            },
            compose_code(ops)};
}

// M v in long double, v = (x, y, z, w), and the size of the terms each coordinate sums.
struct WideProduct {
    WideVec value;
    WideVec size;
};

WideProduct wide_product(const Mat4& m, const Vec3& v, double w) {
    const WideVec4 x(widen(v), w);
    WideProduct p{WideVec(0.0L), WideVec(0.0L)};
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 4; ++c) {
            p.value[r] += m[c][r] * x[c];
            p.size[r] += std::abs(m[c][r] * x[c]);
        }
    }
    return p;
}

bool near(const Vec3& got, const WideVec& expected, const WideVec& tolerance) {
    for (int k = 0; k < 3; ++k) {
        if (!(std::abs(got[k] - expected[k]) <= tolerance[k])) return false;
    }
    return true;
}

std::string transform_text(const Transform& t) {
    return "M " + matrix_text(t.matrix);
}

std::string ray_text(const Ray& r) {
    return "origin " + full_text(r.origin) + ", direction " + full_text(r.direction) + ", t in [" +
           full_text(r.t_min) + ", " + full_text(r.t_max) + "]";
}

// The world ray in the object's frame: by M^-1, the direction not renormalized, t unchanged.
ProbeCase ray_to_object_case(const std::string& name, const Transform& t, const Ray& ray) {
    const WideProduct origin = wide_product(t.inverse, ray.origin, 1.0);
    const WideProduct direction = wide_product(t.inverse, ray.direction, 0.0);
    const Ray expected{narrow(origin.value), narrow(direction.value), ray.t_min, ray.t_max};
    return {name + ": ray_to_object of " + ray_text(ray) + ", " + transform_text(t),
            {"ray_to_object", Json::array({probe::transform(t), probe::ray(ray)})},
            [=](const ProbeAnswer& a) {
                const std::string text = ray_text(expected) + " (within " +
                                         full_text(8 * kUnit * narrow(origin.size)) + " and " +
                                         full_text(8 * kUnit * narrow(direction.size)) + ")";
                if (a.kind != ProbeAnswer::Kind::result) return wrong(text, "");
                const Ray got = probe::ray_from(a.value);
                const bool ok =
                    near(got.origin, origin.value, 8 * kWideUnit * origin.size) &&
                    near(got.direction, direction.value, 8 * kWideUnit * direction.size) &&
                    got.t_min == ray.t_min && got.t_max == ray.t_max;
                return ok ? right() : wrong(text, ray_text(got));
            },
            "ray_to_object(" + cpp(t) + ", " + cpp(ray) + ")"};
}

ProbeCase point_to_world_case(const std::string& name, const Transform& t, const Vec3& p) {
    const WideProduct expected = wide_product(t.matrix, p, 1.0);
    const Vec3 tolerance = 8 * kUnit * narrow(expected.size);
    return {name + ": point_to_world of " + full_text(p) + ", " + transform_text(t),
            {"point_to_world", Json::array({probe::transform(t), probe::vec3(p)})},
            [=](const ProbeAnswer& a) {
                const std::string text =
                    full_text(narrow(expected.value)) + " (within " + full_text(tolerance) + ")";
                if (a.kind != ProbeAnswer::Kind::result) return wrong(text, "");
                const Vec3 got = probe::vec3_from(a.value);
                return near(got, expected.value, widen(tolerance)) ? right()
                                                                   : wrong(text, full_text(got));
            },
            "point_to_world(" + cpp(t) + ", " + cpp(p) + ")"};
}

// M^-T n normalized, and how far rounding may move it: each coordinate of M^-T n by a few ulps
// of its terms, relative to the length it is divided by.
struct WideNormal {
    WideVec value;
    WideVec tolerance;
};

WideNormal wide_normal(const Mat4& inverse, const WideVec& n) {
    WideVec value(0.0L);
    WideVec size(0.0L);
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) {
            value[r] += inverse[r][c] * n[c];
            size[r] += std::abs(inverse[r][c] * n[c]);
        }
    }
    const Wide length = glm::length(value);
    return {value / length, 8 * kWideUnit * (size / length + WideVec(1.0L))};
}

bool unit_length(const Vec3& v) {
    const WideVec w = widen(v);
    return std::abs(std::sqrt(glm::dot(w, w)) - 1) <= kUnitLength;
}

ProbeCase normal_to_world_case(const std::string& name, const Transform& t, const Vec3& n) {
    const WideNormal expected = wide_normal(t.inverse, widen(n));
    return {name + ": normal_to_world of " + full_text(n) + ", " + transform_text(t),
            {"normal_to_world", Json::array({probe::transform(t), probe::vec3(n)})},
            [=](const ProbeAnswer& a) {
                const std::string text = "unit " + full_text(narrow(expected.value)) + " (within " +
                                         full_text(narrow(expected.tolerance)) + ")";
                if (a.kind != ProbeAnswer::Kind::result) return wrong(text, "");
                const Vec3 got = probe::vec3_from(a.value);
                return near(got, expected.value, expected.tolerance) && unit_length(got)
                           ? right()
                           : wrong(text, full_text(got));
            },
            "normal_to_world(" + cpp(t) + ", " + cpp(n) + ")"};
}

// The world ray against the sphere under M, solved in long double in the object frame: t, and
// the normal M^-T (p - C). The tolerances follow the rounding of the object-frame ray (a few
// ulps of the terms of M^-1 A and M^-1 D), magnified along the ray by 1 / cos of the angle of
// incidence, and for the normal by the condition of M's linear part.
struct ExpectedHit {
    bool hit = false;
    double t = 0.0;
    double t_tolerance = 0.0;
    WideNormal normal;
};

Wide frobenius(const Mat4& m) {
    Wide sum = 0;
    for (int c = 0; c < 3; ++c) {
        for (int r = 0; r < 3; ++r)
            sum += Wide(m[c][r]) * m[c][r];
    }
    return std::sqrt(sum);
}

ExpectedHit wide_transformed_hit(const Ray& ray, const Sphere& sphere, const Transform& t) {
    const WideProduct origin = wide_product(t.inverse, ray.origin, 1.0);
    const WideProduct direction = wide_product(t.inverse, ray.direction, 0.0);
    const WideVec f = origin.value - widen(sphere.center);
    const WideVec d = direction.value;
    const Wide a = glm::dot(d, d);
    const Wide b = glm::dot(d, f);
    const Wide c = glm::dot(f, f) - Wide(sphere.radius) * sphere.radius;
    const Wide discriminant = b * b - a * c;
    ExpectedHit e;
    if (discriminant < 0) return e;
    const Wide root = std::sqrt(discriminant);
    const Wide near_t = (-b - root) / a;
    const Wide far_t = (-b + root) / a;
    const auto in_range = [&](Wide x) { return x >= ray.t_min && x <= ray.t_max; };
    if (!in_range(near_t) && !in_range(far_t)) return e;
    const Wide hit_t = in_range(near_t) ? near_t : far_t;

    const Wide speed = std::sqrt(a);
    const Wide half_chord = root / speed;
    const Wide size =
        std::max({origin.size.x, origin.size.y, origin.size.z}) +
        glm::length(widen(sphere.center)) + sphere.radius +
        std::abs(hit_t) * std::max({direction.size.x, direction.size.y, direction.size.z});
    const Wide slant = sphere.radius / half_chord;
    e.hit = true;
    e.t = static_cast<double>(hit_t);
    e.t_tolerance = static_cast<double>(16 * kUnit * size * slant / speed + 8 * kUnit * hit_t);
    e.normal = wide_normal(t.inverse, f + hit_t * d);
    const Wide condition = frobenius(t.matrix) * frobenius(t.inverse);
    e.normal.tolerance += WideVec(16 * kUnit * size * slant / sphere.radius * condition);
    return e;
}

std::string hit_text(const std::optional<Hit>& h) {
    if (!h) return "a miss";
    return "t = " + full_text(h->t) + ", normal " + full_text(h->normal);
}

ProbeCase transformed_sphere_case(const std::string& name, const Ray& ray, const Sphere& sphere,
                                  const Transform& t) {
    const ExpectedHit e = wide_transformed_hit(ray, sphere, t);
    const std::string text = e.hit ? "t = " + full_text(e.t) + " (within " +
                                         full_text(e.t_tolerance) + "), unit normal " +
                                         full_text(narrow(e.normal.value)) + " (within " +
                                         full_text(narrow(e.normal.tolerance)) + ")"
                                   : "a miss";
    return {name + ": " + ray_text(ray) + ", sphere centre " + full_text(sphere.center) +
                " radius " + full_text(sphere.radius) + ", " + transform_text(t),
            {"intersect_transformed_sphere",
             Json::array({probe::ray(ray), probe::sphere(sphere), probe::transform(t)})},
            [=](const ProbeAnswer& a) {
                if (a.kind != ProbeAnswer::Kind::result) return wrong(text, "");
                const std::optional<Hit> got = probe::hit_from(a.value);
                if (!got || !e.hit)
                    return got.has_value() == e.hit ? right() : wrong(text, hit_text(got));
                const bool ok = std::abs(got->t - e.t) <= e.t_tolerance &&
                                near(got->normal, e.normal.value, e.normal.tolerance) &&
                                unit_length(got->normal);
                return ok ? right() : wrong(text, hit_text(got));
            },
            "intersect_transformed_sphere(" + cpp(ray) + ", " + cpp(sphere) + ", " + cpp(t) + ")"};
}

std::vector<ProbeCase> public_cases() {
    // M = T(1, 2, 3) S(2, 4, 0.5): object (1, 1, 2) goes to (2, 4, 1) + (1, 2, 3) = (3, 6, 4).
    const Transform moved_and_scaled =
        transform_of({translate_op({1, 2, 3}), scale_op({2, 4, 0.5})});
    // M = T(5, 5, 5) S(2, 1, 4): M^-T n = S^-1 n (the translation drops out of a direction).
    const Transform squashed = transform_of({translate_op({5, 5, 5}), scale_op({2, 1, 4})});
    // The unit sphere scaled to radii (3, 2, 1), centred at (1, 0, 0).
    const Transform ellipsoid = transform_of({translate_op({1, 0, 0}), scale_op({3, 2, 1})});
    const Sphere unit{{0, 0, 0}, 1.0};
    return {
        exact_matrix_case("translation", {2, -3, 0.5}, wide_translation({2, -3, 0.5})),
        exact_matrix_case("scaling", {2, -0.5, 4}, wide_scaling({2, -0.5, 4})),
        // A quarter turn about +z takes x to y: columns (0, 1, 0), (-1, 0, 0), (0, 0, 1).
        rotation_case({0, 0, 1}, 90),
        // About +x, y goes to z.
        rotation_case({1, 0, 0}, 90),
        // An axis of length 2 is the unit axis +y.
        rotation_case({0, 2, 0}, 30),
        invalid_axis_case({0, 0, 0}, 30),
        compose_case({}),
        // M = T R S: the point (1, 0, 0) is scaled to (2, 0, 0), turned to (0, 2, 0), moved to
        // (1, 4, 3).
        compose_case({translate_op({1, 2, 3}), rotate_op({0, 0, 1}, 90), scale_op({2, 1, 1})}),
        // Scale 1e-3, then translate 1e4: M^-1 = T(-t) S(1000), every entry exact (1 / 1e-3
        // rounds to 1000), where an inverse of M divides by its determinant, 1e-9.
        exact_inverse_case({scale_op({1e-3, 1e-3, 1e-3}), translate_op({1e4, -2e4, 5e3})}),
        // M^-1 (3, 6, 4, 1) = S^-1 (2, 4, 1) = (1, 1, 2); M^-1 (0, 8, 1, 0) = (0, 2, 2), not
        // normalized; t_min and t_max unchanged.
        ray_to_object_case("T S", moved_and_scaled, {{3, 6, 4}, {0, 8, 1}, 0.25, 9.0}),
        point_to_world_case("T S", moved_and_scaled, {1, 1, 2}),
        // n = (1, 1, 1): M^-T n = (0.5, 1, 0.25), normalized; M n = (2, 1, 4) leans away.
        normal_to_world_case("T S", squashed, {1, 1, 1}),
        // M = R S, a quarter turn about z after stretching x by 2: M^-T = R S^-1, so
        // n = (1, 1, 0) goes to R (0.5, 1, 0) = (-1, 0.5, 0), normalized. Neither M n = (-1, 2, 0)
        // nor M^-1 n = (0.5, -1, 0) points that way.
        normal_to_world_case("R S", transform_of({rotate_op({0, 0, 1}, 90), scale_op({2, 1, 1})}),
                             {1, 1, 0}),
        // Straight down the y axis of the ellipsoid from y = 10: its top is at y = 2, so t = 8
        // along the unit world direction, normal (0, 1, 0). (The object-frame direction has
        // length 1/2: normalized, t would come out as 4.)
        transformed_sphere_case("radii (3, 2, 1) at (1, 0, 0)", {{1, 10, 0}, {0, -1, 0}}, unit,
                                ellipsoid),
        // Aimed at (1 + 3 * 0.6, 2 * 0.8, 0) = (2.8, 1.6, 0) along minus its gradient
        // (x / 9, y / 4, 0) = (0.2, 0.4, 0): the normal there is (1, 2, 0) / sqrt 5.
        transformed_sphere_case("radii (3, 2, 1) at (1, 0, 0)",
                                {{4.8, 5.6, 0}, glm::normalize(Vec3{-1, -2, 0})}, unit, ellipsoid),
        // z = 1.5 is above the ellipsoid's top (z = 1): a miss.
        transformed_sphere_case("radii (3, 2, 1) at (1, 0, 0)", {{1, 10, 1.5}, {0, -1, 0}}, unit,
                                ellipsoid),
    };
}

// The hidden ones: the contract's edge cases a student's own tests may not reach.
std::vector<ProbeCase> hidden_cases() {
    const Transform turned_and_squashed =
        transform_of({translate_op({-2, 0.5, 7}), rotate_op({1, 1, 0}, 40), scale_op({0.5, 3, 1})});
    // A sphere of radius 0.5 at (1, 0, 0) under a uniform scale of 2: the world sphere of
    // radius 1 at (2, 0, 0).
    const Transform doubled = transform_of({scale_op({2, 2, 2})});
    const Sphere offset_sphere{{1, 0, 0}, 0.5};
    const Transform ellipsoid = transform_of({translate_op({0, 0, -5}), scale_op({1, 1, 2})});
    const Sphere unit{{0, 0, 0}, 1.0};
    return {
        rotation_case({0, 0, 1}, 0),
        // About (1, 1, 1) by 120 degrees: x -> y -> z -> x.
        rotation_case({1, 1, 1}, 120),
        // About -y: the same as about +y by -90, so x goes to z.
        rotation_case({0, -3, 0}, 90),
        // 450 degrees is a quarter turn and a whole one.
        rotation_case({0, 0, 1}, 450),
        // An axis of length 1e-200 is still an axis: its square underflows, its direction does
        // not.
        rotation_case({0, 0, 1e-200}, 90),
        // And one of length 1.4e200: its square overflows, its direction does not.
        rotation_case({1e200, 0, -1e200}, 60),
        invalid_axis_case({0, 0, 0}, 0),
        exact_matrix_case("scaling", {0, -2, 0.5}, wide_scaling({0, -2, 0.5})),
        // The inverse of scale(2, 0, 0.5) does not exist: diagonal (0.5, 1 / 0, 2).
        singular_scale_case({2, 0, 0.5}),
        compose_case({rotate_op({2, -1, 0.5}, 33)}),
        // M = R T: rotated after moving, so the origin goes to R (1, 0, 0) = (0, 1, 0).
        compose_case({rotate_op({0, 0, 1}, 90), translate_op({1, 0, 0})}),
        exact_inverse_case(
            {translate_op({-3e5, 7, 0.25}), scale_op({0.1, 0.5, 4}), translate_op({2, 0, -1})}),
        ray_to_object_case("T R S", turned_and_squashed, {{1, -2, 3}, {0.5, 0.25, -1}, 1e-3, kInf}),
        point_to_world_case("T R S", turned_and_squashed, {-0.5, 4, 2}),
        normal_to_world_case("T R S", turned_and_squashed, {0.3, -0.4, 0.2}),
        // A normal of length 7 under a translation alone: (0, 0, 1), exactly.
        normal_to_world_case("T", transform_of({translate_op({5, 6, 7})}), {0, 0, 7}),
        // A direction of length 2: t is in the world ray's own units, half the distance.
        transformed_sphere_case("radius 0.5 at (1, 0, 0) scaled by 2", {{2, 0, 10}, {0, 0, -2}},
                                offset_sphere, doubled),
        // From inside: the far side, z = -3 from the centre at z = -5 plus 2.
        transformed_sphere_case("radii (1, 1, 2) at (0, 0, -5)", {{0, 0, -5}, {0, 0, 1}}, unit,
                                ellipsoid),
        // t_max short of the ellipsoid, which the ray would enter at t = 3.
        transformed_sphere_case("radii (1, 1, 2) at (0, 0, -5)", {{0, 0, 0}, {0, 0, -1}, 0, 2.5},
                                unit, ellipsoid),
        // Behind the origin: a miss.
        transformed_sphere_case("radii (1, 1, 2) at (0, 0, -5)", {{0, 0, 0}, {0, 0, 1}}, unit,
                                ellipsoid),
        // t_min past the near side (t = 3) but short of the far side (t = 7): the far side.
        transformed_sphere_case("radii (1, 1, 2) at (0, 0, -5)", {{0, 0, 0}, {0, 0, -1}, 4, kInf},
                                unit, ellipsoid),
        // t_min past both sides: a miss.
        transformed_sphere_case("radii (1, 1, 2) at (0, 0, -5)", {{0, 0, 0}, {0, 0, -1}, 7.5, kInf},
                                unit, ellipsoid),
    };
}

// The oracle's cases, each drawn from its own generator, PortableRandom(kOracleSeed, k) for the
// case at index k, so that `--case k` rebuilds that case alone on any platform; the cases that
// share an op chain (a ray, a point and a normal under it) are drawn from their first one's.
constexpr std::uint64_t kOracleSeed = 0x5EED'0005;

// A chain of 1 to 6 random ops: offsets up to 1e3, any axis and angle, scale factors from 1e-2
// to 1e2 in magnitude, some negative.
std::vector<TransformOp> random_ops(PortableRandom& random) {
    const std::int64_t count = random.integer(1, 6);
    std::vector<TransformOp> ops;
    for (std::int64_t k = 0; k < count; ++k) {
        switch (random.integer(0, 2)) {
            case 0: {
                const double size = random.decade(-1, 3);
                ops.push_back(translate_op(size * random.point(1)));
                break;
            }
            case 1: {
                const Vec3 axis = random.point(1);
                ops.push_back(rotate_op(axis, random.uniform(-400, 400)));
                break;
            }
            default: {
                Vec3 factors;
                for (int i = 0; i < 3; ++i) {
                    const double size = random.decade(-2, 2);
                    factors[i] = random.unit() < 0.2 ? -size : size;
                }
                ops.push_back(scale_op(factors));
            }
        }
    }
    return ops;
}

ProbeCase random_rotation_case(PortableRandom& random) {
    const Vec3 axis = random.unit_vector() * (0.01 + 10 * random.unit());
    return rotation_case(axis, random.uniform(-720, 720));
}

// A ray, a point and a normal under one op chain.
std::vector<ProbeCase> random_frame_cases(PortableRandom& random) {
    const std::vector<TransformOp> ops = random_ops(random);
    const Transform t = transform_of(ops);
    const std::string name = ops_text(ops);
    const Vec3 origin = random.point(100);
    const Vec3 direction = random.point(1);
    const double t_min = random.unit();
    const Ray ray{origin, direction, t_min, 10 + 100 * random.unit()};
    const Vec3 point = random.point(10);
    const Vec3 normal = random.unit_vector();
    return {ray_to_object_case(name, t, ray), point_to_world_case(name, t, point),
            normal_to_world_case(name, t, normal)};
}

// A sphere, a point on it and a ray from outside aimed at that point at least 17 degrees off
// grazing (so that the point is where it enters); case k % 5 == 3 from inside, k % 5 == 4
// passing by; every other one with a world direction that is not unit length.
ProbeCase random_transformed_sphere_case(PortableRandom& random, int k) {
    const std::vector<TransformOp> ops = random_ops(random);
    const Transform t = transform_of(ops);
    const Vec3 center = random.point(1);
    const Sphere sphere{center, 0.5 + 1.5 * random.unit()};
    const Vec3 normal = random.unit_vector();
    Vec3 leaving = random.unit_vector();
    if (glm::dot(leaving, normal) < 0.3) leaving = glm::normalize(leaving + 2.0 * normal);
    const double distance = 0.5 + 5 * random.unit();
    Vec3 origin = sphere.center + sphere.radius * normal + distance * sphere.radius * leaving;
    const Vec3 towards = -leaving;
    if (k % 5 == 3) origin = sphere.center + 0.8 * sphere.radius * random.unit_vector();
    if (k % 5 == 4) {
        // The line passes 1.2 to 2 radii from the centre.
        const Vec3 side = glm::normalize(glm::cross(leaving, random.unit_vector()));
        const double miss = 1.2 + 0.8 * random.unit();
        origin = sphere.center + miss * sphere.radius * side + 5 * sphere.radius * leaving;
    }
    const Vec3 world_origin = Vec3(t.matrix * Vec4(origin, 1.0));
    Vec3 world_direction = Vec3(t.matrix * Vec4(towards, 0.0));
    const double speed = k % 2 ? 1.0 : 0.1 + 10 * random.unit();
    world_direction *= speed / glm::length(world_direction);
    return transformed_sphere_case(ops_text(ops), {world_origin, world_direction}, sphere, t);
}

std::vector<ProbeCase> oracle_cases() {
    std::vector<ProbeCase> cases;
    for (int k = 0; k < 100; ++k) {
        PortableRandom random(kOracleSeed, cases.size());
        cases.push_back(random_rotation_case(random));
    }
    for (int k = 0; k < 200; ++k) {
        PortableRandom random(kOracleSeed, cases.size());
        cases.push_back(compose_case(random_ops(random)));
    }
    for (int k = 0; k < 100; ++k) {
        PortableRandom random(kOracleSeed, cases.size());
        for (ProbeCase& c : random_frame_cases(random))
            cases.push_back(std::move(c));
    }
    for (int k = 0; k < 200; ++k) {
        PortableRandom random(kOracleSeed, cases.size());
        cases.push_back(random_transformed_sphere_case(random, k));
    }
    return cases;
}

}  // namespace

std::vector<CheckDefinition> stage5_checks() {
    return {
        case_check("stage5.unit", 5, "unit",
                   "transform matrices, compose and frames on hand-worked values", public_cases),
        case_check("stage5.hidden", 5, "unit", "transforms on the contract's edge cases",
                   hidden_cases),
        case_check(
            "stage5.oracle", 5, "oracle",
            "rotations, random op chains, rays, points, normals and ellipsoids against long double",
            oracle_cases),
    };
}

}  // namespace raystep::grade
