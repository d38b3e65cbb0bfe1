// Stage 5: the transform matrices and the stack's product. Handout: docs/stage5.md.

#include <cmath>
#include <stdexcept>

#include "stages/1_vectors/vectors.h"
#include "stages/5_transforms/transform.h"

namespace raystep {

namespace {

constexpr double kPi = 3.14159265358979323846;

// One op's matrix and its inverse, each in closed form: never a division by a determinant.
Transform op_transform(const TransformOp& op) {
    switch (op.kind) {
        case TransformOp::Kind::translate:
            return {translation(op.vector), translation(-op.vector)};
        case TransformOp::Kind::rotate:
            return {rotation(op.vector, op.angle_degrees), rotation(op.vector, -op.angle_degrees)};
        case TransformOp::Kind::scale:
            return {scaling(op.vector), scaling(1.0 / op.vector)};
    }
    throw std::logic_error("compose: unknown transform op");
}

}  // namespace

Mat4 translation(const Vec3& offset) {
    Mat4 m(1.0);
    m[3] = Vec4(offset, 1.0);  // the last column: GLM is column-major
    return m;
}

Mat4 rotation(const Vec3& axis, double degrees) {
    if (axis == Vec3(0.0)) throw std::invalid_argument("rotation: the axis is zero");
    const Vec3 a = normalize(axis);
    const double theta = degrees * kPi / 180.0;
    const double c = std::cos(theta);
    const double s = std::sin(theta);

    // Rodrigues: R = c I + (1 - c) a a^T + s A*, with A* v = a x v. m[column][row].
    Mat4 m(1.0);
    for (int column = 0; column < 3; ++column) {
        for (int row = 0; row < 3; ++row) {
            m[column][row] = (row == column ? c : 0.0) + (1.0 - c) * a[row] * a[column];
        }
    }
    // A* = [0 -az ay; az 0 -ax; -ay ax 0]
    m[1][0] -= s * a.z;
    m[2][0] += s * a.y;
    m[0][1] += s * a.z;
    m[2][1] -= s * a.x;
    m[0][2] -= s * a.y;
    m[1][2] += s * a.x;
    return m;
}

Mat4 scaling(const Vec3& factors) {
    Mat4 m(1.0);
    m[0][0] = factors.x;
    m[1][1] = factors.y;
    m[2][2] = factors.z;
    return m;
}

Transform compose(const std::vector<TransformOp>& ops) {
    // Right-multiplied in file order, M = M1 M2 ... Mn; the inverse alongside,
    // M^-1 = Mn^-1 ... M1^-1, since (A B)^-1 = B^-1 A^-1.
    Transform result{Mat4(1.0), Mat4(1.0)};
    for (const TransformOp& op : ops) {
        const Transform step = op_transform(op);
        result.matrix = result.matrix * step.matrix;
        result.inverse = step.inverse * result.inverse;
    }
    return result;
}

}  // namespace raystep
