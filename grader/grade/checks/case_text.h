#pragma once

#include <string>
#include <vector>

#include "app/grade/value_text.h"
#include "base/math/types.h"
#include "base/scene/ray_offset.h"
#include "base/scene/scene.h"
#include "stages/2_rays/ray.h"
#include "stages/5_transforms/transform.h"
#include "stages/6_shading/shading.h"

namespace raystep::grade {

// How a case's values are written in a report, in full_text's digits (app/grade/value_text.h).

/// full_text of a vector, as one function (not an overload set) to pass to a judge.
std::string vec3_text(const Vec3& v);

/// The case's vectors, separated by commas.
std::string vectors_text(const std::vector<Vec3>& vectors);

/// A surface point: its position, error bound, both normals and the direction to the eye.
std::string point_text(const SurfacePoint& p);

/// A ray offset: the rule's name, and its epsilon unless the rule is the error bound.
std::string offset_text(const RayOffset& o);

/// A transform's ops in file order: `[translate (...), rotate (...) by 30, scale (...)]`.
std::string ops_text(const std::vector<TransformOp>& ops);

/// A transform by its matrix: `M rows [...]`.
std::string transform_text(const Transform& t);

}  // namespace raystep::grade
