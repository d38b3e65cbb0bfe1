#pragma once

#include <string>

#include "base/math/types.h"
#include "base/scene/ray_offset.h"
#include "base/scene/scene.h"
#include "base/scene/shapes.h"
#include "stages/2_rays/ray.h"
#include "stages/5_transforms/transform.h"
#include "stages/6_shading/shading.h"
#include "stages/7_recursion/recursion.h"

namespace raystep::grade {

// A check's inputs written as C++ that a student can paste into a Catch2 test of the student
// release, so that a counterexample's call reads `dot({1, 2, 3}, {4, 5, 6})` and runs as it
// reads. Every number has 17 significant digits, which reads back as exactly the same double;
// infinities and NaN are <cmath>'s INFINITY and NAN.

std::string cpp(double x);
std::string cpp(const Vec3& v);   ///< {x, y, z}: a Vec3 or Color argument, braced
std::string cpp(const Ray& ray);  ///< Ray{{origin}, {direction}, t_min, t_max}
std::string cpp(const Mat4& m);   ///< Mat4(16 numbers, column by column), glm's order
std::string cpp(const Transform& transform);
std::string cpp(const Sphere& sphere);
std::string cpp(const TransformOp& op);
std::string cpp(const Attenuation& attenuation);
std::string cpp(const PointLight& light);
std::string cpp(const DirectionalLight& light);
std::string cpp(const Material& material);
std::string cpp(const SurfacePoint& point);
std::string cpp(const LightSample& light);
std::string cpp(const RayOffset& offset);
std::string cpp(const ShadedHit& hit);

}  // namespace raystep::grade
