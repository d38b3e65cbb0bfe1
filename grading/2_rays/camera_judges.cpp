#include "grading/2_rays/camera_judges.h"

#include <cmath>
#include <limits>

#include "app/grade/data_judge.h"
#include "app/grade/value_text.h"

namespace raystep::grade {

namespace {

using probe::Json;

const JudgeRegistry::Registration camera_ray_registration{
    {"camera_ray", [](const Json& p) -> Judge {
         const Vec3 origin = probe::vec3_from(p.at("origin"));
         const double origin_tolerance = probe::number_from(p.at("origin_tolerance"));
         const Vec3 direction = probe::vec3_from(p.at("direction"));
         const double direction_tolerance = probe::number_from(p.at("direction_tolerance"));
         return [=](const ProbeAnswer& answer) {
             Verdict verdict;
             verdict.expected = "origin " + full_text(origin) + " (within " +
                                full_text(origin_tolerance) + "), unit direction " +
                                full_text(direction) + " (within " +
                                full_text(direction_tolerance) + "), t in [0, inf]";
             if (answer.kind != ProbeAnswer::Kind::result || !answer.value.is_array() ||
                 answer.value.size() != 1) {
                 return verdict;
             }
             const Ray got = probe::ray_from(answer.value[0]);
             // Written so that a NaN anywhere fails
             bool ok = got.t_min == 0.0 && got.t_max == std::numeric_limits<double>::infinity() &&
                       unit_length(got.direction);
             for (int k = 0; k < 3; ++k) {
                 ok = ok && std::abs(got.origin[k] - origin[k]) <= origin_tolerance &&
                      std::abs(got.direction[k] - direction[k]) <= direction_tolerance;
             }
             if (ok) return Verdict{true, "", "", "", std::nullopt, "", "", ""};
             verdict.got = ray_text(got);
             return verdict;
         };
     }}};

}  // namespace

Json camera_ray_judge(const Vec3& origin, double origin_tolerance, const Vec3& direction,
                      double direction_tolerance) {
    return {{"judge", "camera_ray"},
            {"origin", probe::vec3(origin)},
            {"origin_tolerance", probe::number(origin_tolerance)},
            {"direction", probe::vec3(direction)},
            {"direction_tolerance", probe::number(direction_tolerance)}};
}

}  // namespace raystep::grade
