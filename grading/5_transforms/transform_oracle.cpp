#include "grading/5_transforms/transform_oracle.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "base/math/unit_roundoff.h"

namespace raystep {

namespace {

WideMat absolute(const WideMat& m) {
    WideMat a;
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r)
            a[c][r] = std::abs(m[c][r]);
    }
    return a;
}

Wide frobenius(const Mat4& m) {
    Wide sum = 0;
    for (int c = 0; c < 3; ++c) {
        for (int r = 0; r < 3; ++r)
            sum += Wide(m[c][r]) * m[c][r];
    }
    return std::sqrt(sum);
}

}  // namespace

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

WideMat wide_rotation(const Vec3& axis, Wide degrees) {
    const WideVec a = widen(axis) / glm::length(widen(axis));
    const Wide theta = degrees * kWidePi / 180;
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
            const Wide angle = 1 + std::abs(op.angle_degrees * kWidePi / 180);
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

WideTransform wide_compose(const std::vector<TransformOp>& ops) {
    WideTransform t{WideMat(1.0L), WideMat(1.0L), WideMat(1.0L), WideMat(1.0L)};
    for (const TransformOp& op : ops) {
        const WideOp w = wide_op(op);
        t.matrix = t.matrix * w.matrix;
        t.inverse = w.inverse * t.inverse;
        t.matrix_tolerance = t.matrix_tolerance * w.size;
        t.inverse_tolerance = w.inverse_size * t.inverse_tolerance;
    }
    const Wide ulps = 8 * kWideUnitRoundoff * (ops.size() + 1);
    t.matrix_tolerance = ulps * t.matrix_tolerance;
    t.inverse_tolerance = ulps * t.inverse_tolerance;
    return t;
}

Transform transform_of(const std::vector<TransformOp>& ops) {
    const WideTransform w = wide_compose(ops);
    return {narrow(w.matrix), narrow(w.inverse)};
}

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
    return {value / length, 8 * kWideUnitRoundoff * (size / length + WideVec(1.0L))};
}

TransformedSphereHit wide_transformed_hit(const Ray& ray, const Sphere& sphere,
                                          const Transform& t) {
    const WideProduct origin = wide_product(t.inverse, ray.origin, 1.0);
    const WideProduct direction = wide_product(t.inverse, ray.direction, 0.0);
    const WideVec f = origin.value - widen(sphere.center);
    const WideVec d = direction.value;
    const Wide a = glm::dot(d, d);
    const Wide b = glm::dot(d, f);
    const Wide c = glm::dot(f, f) - Wide(sphere.radius) * sphere.radius;
    const Wide discriminant = b * b - a * c;
    TransformedSphereHit e;
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
    e.t_tolerance =
        static_cast<double>(16 * kUnitRoundoff * size * slant / speed + 8 * kUnitRoundoff * hit_t);
    e.normal = wide_normal(t.inverse, f + hit_t * d);
    const Wide condition = frobenius(t.matrix) * frobenius(t.inverse);
    e.normal.tolerance += WideVec(16 * kUnitRoundoff * size * slant / sphere.radius * condition);
    return e;
}

}  // namespace raystep
