#include "grader/grade/checks/case_text.h"

namespace raystep::grade {

namespace {

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

}  // namespace

std::string vec3_text(const Vec3& v) {
    return full_text(v);
}

std::string vectors_text(const std::vector<Vec3>& vectors) {
    std::string text;
    for (const Vec3& v : vectors)
        text += (text.empty() ? "" : ", ") + full_text(v);
    return text;
}

std::string point_text(const SurfacePoint& p) {
    return "point " + full_text(p.position) + " error " + full_text(p.error) + " normal " +
           full_text(p.normal) + " shading normal " + full_text(p.shading_normal) + " to eye " +
           full_text(p.to_eye);
}

std::string offset_text(const RayOffset& o) {
    return std::string(offset_rule_name(o.rule)) +
           (o.rule == OffsetRule::error_bound ? "" : " epsilon " + full_text(o.epsilon));
}

std::string ops_text(const std::vector<TransformOp>& ops) {
    std::string text;
    for (const TransformOp& op : ops)
        text += (text.empty() ? "" : ", ") + op_text(op);
    return "[" + text + "]";
}

std::string transform_text(const Transform& t) {
    return "M " + matrix_text(t.matrix);
}

}  // namespace raystep::grade
