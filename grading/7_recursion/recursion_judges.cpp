#include "grading/7_recursion/recursion_judges.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "app/grade/data_judge.h"
#include "app/grade/value_text.h"
#include "app/protocol/wide_json.h"
#include "grading/6_shading/shading_judges.h"

namespace raystep::grade {

namespace {

using probe::Json;
using Kind = ProbeAnswer::Kind;

const double kInf = std::numeric_limits<double>::infinity();

Json ray_json(const ExpectedRay& e) {
    Json j = {{"direction", probe::wide_vec3(e.direction)},
              {"direction_tolerance", probe::wide(e.direction_tolerance)},
              {"t_min", probe::number(e.t_min)},
              {"t_max", probe::number(e.t_max)}};
    if (e.region) {
        j["region"] = region_json(*e.region);
    } else {
        j["origin"] = probe::wide_vec3(e.origin);
        j["origin_tolerance"] = probe::wide(e.origin_tolerance);
    }
    return j;
}

// Read strictly: a ray has either a region or an origin with its tolerance.
ExpectedRay ray_from(const Json& j) {
    ExpectedRay e{};
    e.direction = probe::wide_vec3_from(j.at("direction"));
    e.direction_tolerance = probe::wide_from(j.at("direction_tolerance"));
    e.t_min = probe::number_from(j.at("t_min"));
    e.t_max = probe::number_from(j.at("t_max"));
    if (j.contains("region")) {
        e.region = region_from(j.at("region"));
    } else {
        e.origin = probe::wide_vec3_from(j.at("origin"));
        e.origin_tolerance = probe::wide_from(j.at("origin_tolerance"));
    }
    return e;
}

std::string expected_text(const ExpectedRay& e) {
    const std::string origin = e.region ? region_text(*e.region)
                                        : "origin " + full_text(narrow(e.origin)) + " (within " +
                                              full_text(e.origin_tolerance) + ")";
    return origin + ", direction " + full_text(narrow(e.direction)) + " (within " +
           full_text(e.direction_tolerance) + "), t in [" + full_text(e.t_min) + ", " +
           full_text(e.t_max) + "]";
}

// t_max as the judges take it: exact, except that an unbounded ray may end at the largest
// double, which no finite t exceeds, so that it admits the same hits as infinity. The header's
// promise of infinity itself is one case's ("unbounded_ray"): a ray bounded in name only loses
// that promise, not every case that follows a mirror ray.
bool same_t_max(double got, double expected) {
    if (expected == kInf) return got >= std::numeric_limits<double>::max();
    return got == expected;
}

// Written so that a NaN anywhere fails.
bool matches(const Ray& got, const ExpectedRay& e) {
    bool ok = got.t_min == e.t_min && same_t_max(got.t_max, e.t_max);
    for (int k = 0; k < 3; ++k) {
        ok = ok && near_wide(got.direction[k], e.direction[k], e.direction_tolerance);
        if (!e.region) ok = ok && near_wide(got.origin[k], e.origin[k], e.origin_tolerance);
    }
    return ok && (!e.region || within(*e.region, got.origin));
}

const JudgeRegistry::Registration mirror_ray_registration{
    {"mirror_ray", [](const Json& p) -> Judge {
         const ExpectedRay expected = ray_from(p.at("ray"));
         const std::string text = expected_text(expected);
         return [=](const ProbeAnswer& answer) {
             if (answer.kind != Kind::result) return verdict_wrong(text, "");
             const Ray got = probe::ray_from(answer.value);
             if (matches(got, expected)) return verdict_right();
             return verdict_wrong(text, ray_text(got));
         };
     }}};

const JudgeRegistry::Registration unbounded_ray_registration{
    {"unbounded_ray", [](const Json&) -> Judge {
         return [](const ProbeAnswer& answer) {
             const std::string text = "t_max infinity (reflected_ray is unbounded)";
             if (answer.kind != Kind::result) return verdict_wrong(text, "");
             const Ray got = probe::ray_from(answer.value);
             if (got.t_max == kInf) return verdict_right();
             const std::string note =
                 got.t_max == std::numeric_limits<double>::max()
                     ? " (the largest double admits the same hits, but the header promises "
                       "infinity; only this case asks for it)"
                     : "";
             return verdict_wrong(text, "t_max " + full_text(got.t_max) + note);
         };
     }}};

const JudgeRegistry::Registration radiance_registration{
    {"radiance", [](const Json& p) -> Judge {
         const DoubleDoubleVec3 colour = probe::wide_vec3_from(p.at("colour"));
         const DoubleDoubleVec3 tolerance = probe::wide_vec3_from(p.at("colour_tolerance"));
         const Json& ray_list = p.at("rays");
         if (!ray_list.is_array()) throw std::invalid_argument("expected a list of rays");
         std::vector<ExpectedRay> rays;
         for (const Json& ray : ray_list)
             rays.push_back(ray_from(ray));
         const std::string text = "colour " + full_text(narrow(colour)) + " (within " +
                                  full_text(narrow(tolerance)) + ") after asking about " +
                                  std::to_string(rays.size()) + " ray(s)";
         return [=](const ProbeAnswer& answer) {
             if (answer.kind != Kind::result) return verdict_wrong(text, "");
             const Vec3 got_colour = probe::vec3_from(answer.value.at("colour"));
             const Json& got_rays = answer.value.at("rays");
             const std::string got = "colour " + full_text(got_colour) + " after asking about " +
                                     std::to_string(got_rays.size()) + " ray(s)";
             if (!near_wide(got_colour, colour, tolerance)) return verdict_wrong(text, got);
             if (got_rays.size() != rays.size()) return verdict_wrong(text, got);
             for (std::size_t i = 0; i < rays.size(); ++i) {
                 const Ray ray = probe::ray_from(got_rays[i]);
                 if (!matches(ray, rays[i])) {
                     return verdict_wrong(
                         "ray " + std::to_string(i) + ": " + expected_text(rays[i]),
                         "ray " + std::to_string(i) + ": " + ray_text(ray));
                 }
             }
             return verdict_right();
         };
     }}};

}  // namespace

Json expected_ray_json(const ExpectedRay& expected) {
    return ray_json(expected);
}

ExpectedRay expected_ray_from(const Json& j) {
    return ray_from(j);
}

bool ray_matches(const Ray& got, const ExpectedRay& expected) {
    return matches(got, expected);
}

std::string expected_ray_text(const ExpectedRay& expected) {
    return expected_text(expected);
}

Json mirror_ray_judge(const ExpectedRay& expected) {
    return {{"judge", "mirror_ray"}, {"ray", ray_json(expected)}};
}

Json unbounded_ray_judge() {
    return {{"judge", "unbounded_ray"}};
}

Json radiance_judge(const DoubleDoubleVec3& colour, const DoubleDoubleVec3& tolerance,
                    const std::vector<ExpectedRay>& rays) {
    Json list = Json::array();
    for (const ExpectedRay& ray : rays)
        list.push_back(ray_json(ray));
    return {{"judge", "radiance"},
            {"colour", probe::wide_vec3(colour)},
            {"colour_tolerance", probe::wide_vec3(tolerance)},
            {"rays", std::move(list)}};
}

}  // namespace raystep::grade
