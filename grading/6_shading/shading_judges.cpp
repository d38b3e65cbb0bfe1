#include "grading/6_shading/shading_judges.h"

#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>

#include "app/grade/data_judge.h"
#include "app/grade/value_text.h"
#include "app/protocol/wide_json.h"

namespace raystep::grade {

namespace {

using probe::Json;
using Kind = ProbeAnswer::Kind;

const JudgeRegistry::Registration light_sample_registration{
    {"light_sample", [](const Json& p) -> Judge {
         const DoubleDoubleVec3 direction = probe::wide_vec3_from(p.at("direction"));
         const double direction_tolerance = probe::number_from(p.at("direction_tolerance"));
         const DoubleDouble distance = probe::wide_from(p.at("distance"));
         const DoubleDouble distance_tolerance = probe::wide_from(p.at("distance_tolerance"));
         const DoubleDoubleVec3 intensity = probe::wide_vec3_from(p.at("intensity"));
         const DoubleDoubleVec3 intensity_tolerance =
             probe::wide_vec3_from(p.at("intensity_tolerance"));
         const std::string text =
             "direction " + full_text(narrow(direction)) + " (within " +
             full_text(direction_tolerance) + "), distance " + full_text(distance) + " (within " +
             full_text(distance_tolerance) + "), intensity " + full_text(narrow(intensity)) +
             " (within " + full_text(narrow(intensity_tolerance)) + ")";
         return [=](const ProbeAnswer& answer) {
             if (answer.kind != Kind::result) return verdict_wrong(text, "");
             const LightSample got = probe::light_sample_from(answer.value);
             // An infinite distance is asked exactly; a finite one within its tolerance, written
             // so that a NaN fails.
             const bool distance_ok = is_infinite(distance)
                                          ? got.distance == std::numeric_limits<double>::infinity()
                                          : near_wide(got.distance, distance, distance_tolerance);
             if (distance_ok &&
                 near_wide(got.direction, direction, DoubleDoubleVec3(direction_tolerance)) &&
                 near_wide(got.intensity, intensity, intensity_tolerance)) {
                 return verdict_right();
             }
             return verdict_wrong(text, light_sample_text(got));
         };
     }}};

// The origin a rule promises: its text (up to the t range's start) and its test.
struct OriginRule {
    std::string text;
    std::function<bool(const Vec3&)> accept;
};

OriginRule origin_rule(const Json& p) {
    const std::string rule = p.at("rule").get<std::string>();
    if (rule == "along_ray") {
        const Vec3 origin = probe::vec3_from(p.at("origin"));
        return {"origin " + full_text(origin), [origin](const Vec3& got) { return got == origin; }};
    }
    if (rule == "along_normal") {
        const DoubleDoubleVec3 origin = probe::wide_vec3_from(p.at("origin"));
        const DoubleDoubleVec3 tolerance = probe::wide_vec3_from(p.at("origin_tolerance"));
        return {"origin " + full_text(narrow(origin)) + " (within " + full_text(narrow(tolerance)) +
                    ")",
                [origin, tolerance](const Vec3& got) { return near_wide(got, origin, tolerance); }};
    }
    if (rule == "error_bound") {
        const ErrorBoundOrigin region = region_from(p.at("region"));
        return {region_text(region), [region](const Vec3& got) { return within(region, got); }};
    }
    throw std::invalid_argument("no offset rule named '" + rule + "'");
}

const JudgeRegistry::Registration leaving_ray_registration{
    {"leaving_ray", [](const Json& p) -> Judge {
         const OriginRule origin = origin_rule(p);
         const double t_min = probe::number_from(p.at("t_min"));
         const Vec3 direction = probe::vec3_from(p.at("direction"));
         const DoubleDoubleVec3 direction_tolerance(
             probe::number_from(p.at("direction_tolerance")));
         const double t_max = probe::number_from(p.at("t_max"));
         const std::string text = origin.text + ", t in [" + full_text(t_min) + ", " +
                                  full_text(t_max) + "], direction " + full_text(direction);
         return [=](const ProbeAnswer& answer) {
             if (answer.kind != Kind::result) return verdict_wrong(text, "");
             const Ray got = probe::ray_from(answer.value);
             if (got.t_max == t_max && got.t_min == t_min &&
                 near_wide(got.direction, DoubleDoubleVec3(direction), direction_tolerance) &&
                 origin.accept(got.origin)) {
                 return verdict_right();
             }
             return verdict_wrong(text, ray_text(got));
         };
     }}};

Json leaving_ray_judge(const std::string& rule, double t_min, const LeavingDirection& end) {
    return {{"judge", "leaving_ray"},
            {"rule", rule},
            {"t_min", probe::number(t_min)},
            {"direction", probe::vec3(end.direction)},
            {"direction_tolerance", probe::number(end.tolerance)},
            {"t_max", probe::number(end.t_max)}};
}

}  // namespace

std::string light_sample_text(const LightSample& l) {
    return "light from " + full_text(l.direction) + " at " + full_text(l.distance) +
           ", intensity " + full_text(l.intensity);
}

Json light_sample_judge(const DoubleDoubleVec3& direction, double direction_tolerance,
                        const DoubleDouble& distance, const DoubleDouble& distance_tolerance,
                        const DoubleDoubleVec3& intensity,
                        const DoubleDoubleVec3& intensity_tolerance) {
    return {{"judge", "light_sample"},
            {"direction", probe::wide_vec3(direction)},
            {"direction_tolerance", probe::number(direction_tolerance)},
            {"distance", probe::wide(distance)},
            {"distance_tolerance", probe::wide(distance_tolerance)},
            {"intensity", probe::wide_vec3(intensity)},
            {"intensity_tolerance", probe::wide_vec3(intensity_tolerance)}};
}

Json along_ray_judge(const Vec3& origin, double t_min, const LeavingDirection& end) {
    Json judge = leaving_ray_judge("along_ray", t_min, end);
    judge["origin"] = probe::vec3(origin);
    return judge;
}

Json along_normal_judge(const DoubleDoubleVec3& origin, const DoubleDoubleVec3& tolerance,
                        const LeavingDirection& end) {
    Json judge = leaving_ray_judge("along_normal", 0.0, end);
    judge["origin"] = probe::wide_vec3(origin);
    judge["origin_tolerance"] = probe::wide_vec3(tolerance);
    return judge;
}

Json error_bound_judge(const ErrorBoundOrigin& region, const LeavingDirection& end) {
    Json judge = leaving_ray_judge("error_bound", 0.0, end);
    judge["region"] = region_json(region);
    return judge;
}

Json region_json(const ErrorBoundOrigin& region) {
    return {{"point", probe::wide_vec3(region.point)},
            {"normal", probe::wide_vec3(region.normal)},
            {"offset", probe::wide(region.offset)},
            {"ulps", probe::number(region.ulps)}};
}

ErrorBoundOrigin region_from(const Json& j) {
    return {probe::wide_vec3_from(j.at("point")), probe::wide_vec3_from(j.at("normal")),
            probe::wide_from(j.at("offset")), probe::number_from(j.at("ulps"))};
}

}  // namespace raystep::grade
