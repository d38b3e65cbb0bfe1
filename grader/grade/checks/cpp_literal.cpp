#include "grader/grade/checks/cpp_literal.h"

#include <cmath>

#include "grader/grade/checks/judging.h"

namespace raystep::grade {

std::string cpp(double x) {
    if (std::isnan(x)) return "NAN";
    if (std::isinf(x)) return x > 0 ? "INFINITY" : "-INFINITY";
    return full_text(x);
}

std::string cpp(const Vec3& v) {
    return "{" + cpp(v.x) + ", " + cpp(v.y) + ", " + cpp(v.z) + "}";
}

std::string cpp(const Ray& ray) {
    return "Ray{" + cpp(ray.origin) + ", " + cpp(ray.direction) + ", " + cpp(ray.t_min) + ", " +
           cpp(ray.t_max) + "}";
}

std::string cpp(const Mat4& m) {
    std::string text = "Mat4(";
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r)
            text += (c + r == 0 ? "" : ", ") + cpp(m[c][r]);
    }
    return text + ")";
}

std::string cpp(const Transform& transform) {
    return "Transform{" + cpp(transform.matrix) + ", " + cpp(transform.inverse) + "}";
}

std::string cpp(const Sphere& sphere) {
    return "Sphere{" + cpp(sphere.center) + ", " + cpp(sphere.radius) + "}";
}

std::string cpp(const TransformOp& op) {
    const char* kind = op.kind == TransformOp::Kind::translate ? "translate"
                       : op.kind == TransformOp::Kind::rotate  ? "rotate"
                                                               : "scale";
    return std::string("TransformOp{TransformOp::Kind::") + kind + ", " + cpp(op.vector) + ", " +
           cpp(op.angle_degrees) + "}";
}

std::string cpp(const Attenuation& attenuation) {
    return "Attenuation{" + cpp(attenuation.constant) + ", " + cpp(attenuation.linear) + ", " +
           cpp(attenuation.quadratic) + "}";
}

std::string cpp(const PointLight& light) {
    return "PointLight{" + cpp(light.position) + ", " + cpp(light.color) + ", " +
           cpp(light.attenuation) + "}";
}

std::string cpp(const DirectionalLight& light) {
    return "DirectionalLight{" + cpp(light.direction) + ", " + cpp(light.color) + "}";
}

std::string cpp(const Material& material) {
    return "Material{" + cpp(material.ambient) + ", " + cpp(material.diffuse) + ", " +
           cpp(material.specular) + ", " + cpp(material.emission) + ", " + cpp(material.shininess) +
           "}";
}

std::string cpp(const SurfacePoint& point) {
    return "SurfacePoint{" + cpp(point.position) + ", " + cpp(point.error) + ", " +
           cpp(point.normal) + ", " + cpp(point.shading_normal) + ", " + cpp(point.to_eye) + "}";
}

std::string cpp(const LightSample& light) {
    return "LightSample{" + cpp(light.direction) + ", " + cpp(light.distance) + ", " +
           cpp(light.intensity) + "}";
}

std::string cpp(const RayOffset& offset) {
    const char* rule = offset.rule == OffsetRule::along_ray      ? "along_ray"
                       : offset.rule == OffsetRule::along_normal ? "along_normal"
                                                                 : "error_bound";
    return std::string("RayOffset{OffsetRule::") + rule + ", " + cpp(offset.epsilon) + "}";
}

std::string cpp(const ShadedHit& hit) {
    return "ShadedHit{" + cpp(hit.point) + ", " + cpp(hit.local) + ", " + cpp(hit.reflectance) +
           "}";
}

}  // namespace raystep::grade
