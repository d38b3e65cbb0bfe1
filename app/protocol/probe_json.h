#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/check/case_answer.h"
#include "app/check/ray_case.h"
#include "base/scene/scene.h"
#include "stages/3_intersect/intersect.h"
#include "stages/5_transforms/transform.h"
#include "stages/6_shading/shading.h"

namespace raystep::probe {

// The values that cross between raystep-grade and a probe, as JSON (grader/probe/README.md
// describes the protocol). Both sides use these, so a value is read exactly as it was written:
// doubles keep all their digits (nlohmann writes 17 significant digits), and the non-finite ones,
// which JSON has no numbers for, become the strings "nan", "inf" and "-inf".
//
// Reading is strict and never trusts the other side: a missing field, a wrong type or a string
// that is not one of those three throws (std::invalid_argument, or nlohmann's json::exception),
// which the grader scores as a wrong answer.

using Json = nlohmann::json;

/// The deepest that arrays and objects may nest in a line the other side sent: every value of the
/// protocol nests a few levels, and a line nested hundreds of thousands deep would exhaust the
/// stack of whatever walks it (nlohmann's dump is recursive), so it is refused before parsing.
inline constexpr int kDeepestNesting = 64;

/// Whether JSON text nests arrays and objects deeper than kDeepestNesting (what lies in strings
/// is skipped, escapes included). Reads the text once; never throws.
bool nested_too_deep(const std::string& text);

Json number(double x);
double number_from(const Json& j);
int integer_from(const Json& j);  ///< a whole number that fits an int, nothing else

/// The field `name` of an object; throws naming it where there is no such field.
const Json& field(const Json& j, const char* name);

Json vec2(const Vec2& v);  ///< a film or sample point [x, y]
Vec2 vec2_from(const Json& j);
Json vec3(const Vec3& v);
Vec3 vec3_from(const Json& j);

Json mat4(const Mat4& m);  ///< 16 numbers, column by column
Mat4 mat4_from(const Json& j);

Json ray(const Ray& r);
Ray ray_from(const Json& j);
std::vector<Ray> rays_from(const Json& j);  ///< from an array of rays

Json hit(const std::optional<Hit>& h);  ///< null for a miss
std::optional<Hit> hit_from(const Json& j);

Json primitive_hit(const std::optional<PrimitiveHit>& h);  ///< null for a miss
std::optional<PrimitiveHit> primitive_hit_from(const Json& j);

Json sphere(const Sphere& s);
Sphere sphere_from(const Json& j);
Json triangle(const Triangle& t);
Triangle triangle_from(const Json& j);
Json plane(const Plane& p);
Plane plane_from(const Json& j);

Json primitive_list(const PrimitiveList& list);
PrimitiveList primitive_list_from(const Json& j);

Json transform(const Transform& t);
Transform transform_from(const Json& j);
Json transform_op(const TransformOp& op);
TransformOp transform_op_from(const Json& j);

Json material(const Material& m);
Material material_from(const Json& j);
Json attenuation(const Attenuation& a);
Attenuation attenuation_from(const Json& j);
Json point_light(const PointLight& l);
PointLight point_light_from(const Json& j);
Json directional_light(const DirectionalLight& l);
DirectionalLight directional_light_from(const Json& j);

Json surface_point(const SurfacePoint& p);
SurfacePoint surface_point_from(const Json& j);
Json light_sample(const LightSample& l);
LightSample light_sample_from(const Json& j);
Json ray_offset(const RayOffset& o);
RayOffset ray_offset_from(const Json& j);

/// A stage-3 case as the probe gets it: the ray, the primitives and whether they are a
/// watertight group, never the expectations.
Json case_question(const RayCase& c);
RayCase case_question_from(const Json& j);

Json case_answer(const CaseAnswer& a);
CaseAnswer case_answer_from(const Json& j);

}  // namespace raystep::probe
