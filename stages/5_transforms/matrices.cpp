// Stage 5: the transform matrices and the stack's product. Handout: docs/stage5.md.

#include "base/errors/not_implemented.h"
#include "stages/5_transforms/transform.h"

namespace raystep {

Mat4 translation(const Vec3& offset) {
    // The identity with the offset in the last column: a point (w = 1) picks it up, a
    // direction (w = 0) does not. GLM is column-major: m[3] is the last column.
    RAYSTEP_TODO(5, "translation", "Translate, rotate, scale");
}

Mat4 rotation(const Vec3& axis, double degrees) {
    // Rodrigues' formula, with a = axis / |axis| and theta in radians:
    //   R = cos(theta) I + (1 - cos(theta)) a a^T + sin(theta) A*,
    //   A* = [ 0 -az ay ; az 0 -ax ; -ay ax 0 ]   (A* v = a x v)
    // in the upper-left 3x3, the rest the identity. A zero axis has no direction: throw.
    RAYSTEP_TODO(5, "rotation", "Translate, rotate, scale");
}

Mat4 scaling(const Vec3& factors) {
    // The factors on the diagonal, 1 in the corner.
    RAYSTEP_TODO(5, "scaling", "Translate, rotate, scale");
}

Transform compose(const std::vector<TransformOp>& ops) {
    // Start from the identity and right-multiply, M = M * op, in file order. Build the inverse
    // alongside from each op's inverse (translate by -offset, rotate by -degrees, scale by
    // 1 / factors), left-multiplied: M^-1 = op^-1 * M^-1, since (A B)^-1 = B^-1 A^-1.
    // A zero factor has no inverse: keep its 1 / 0 = infinity, never a finite stand-in.
    RAYSTEP_TODO(5, "compose", "The transform stack");
}

}  // namespace raystep
