#include "grading/9_refraction/refraction_judges.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "app/grade/data_judge.h"
#include "app/grade/value_text.h"
#include "app/protocol/wide_json.h"
#include "grading/7_recursion/recursion_judges.h"
#include "grading/9_refraction/refraction_json.h"

namespace raystep::grade {

namespace {

using probe::Json;
using Kind = ProbeAnswer::Kind;

Json allowed_json(const AllowedAnswers& allowed) {
    return {{"direction", allowed.direction}, {"none", allowed.none}};
}

AllowedAnswers allowed_from(const Json& j) {
    const Json& direction = j.at("direction");
    const Json& none = j.at("none");
    if (!direction.is_boolean() || !none.is_boolean())
        throw std::invalid_argument("expected \"direction\" and \"none\" true or false");
    return {direction.get<bool>(), none.get<bool>()};
}

std::string allowed_text(const AllowedAnswers& allowed, const std::string& direction) {
    if (!allowed.direction) return "nullopt (total internal reflection)";
    if (!allowed.none) return direction;
    return direction + ", or nullopt (within rounding of the critical angle)";
}

std::string media_text(const MediumStack& stack) {
    std::string text;
    for (const Medium& m : stack) {
        text += text.empty() ? "" : ", ";
        text += "{" + std::to_string(m.solid) + ", " + full_text(m.index) + "}";
    }
    return "[" + text + "]";
}

const JudgeRegistry::Registration refraction_registration{
    {"refraction", [](const Json& p) -> Judge {
         const AllowedAnswers allowed = allowed_from(p);
         const DoubleDoubleVec3 direction = probe::wide_vec3_from(p.at("expected"));
         const DoubleDoubleVec3 tolerance(probe::wide_from(p.at("tolerance")));
         const std::string text = allowed_text(
             allowed, full_text(narrow(direction)) + " (within " + full_text(tolerance.x) + ")");
         return [=](const ProbeAnswer& answer) {
             if (answer.kind != Kind::result) return verdict_wrong(text, "");
             if (answer.value.is_null()) {
                 return allowed.none ? verdict_right() : verdict_wrong(text, "nullopt");
             }
             const Vec3 got = probe::vec3_from(answer.value);
             if (allowed.direction && near_wide(got, direction, tolerance)) return verdict_right();
             return verdict_wrong(text, full_text(got));
         };
     }}};

const JudgeRegistry::Registration media_registration{
    {"media", [](const Json& p) -> Judge {
         const MediumStack expected = probe::media_from(p.at("expected"));
         const std::string text = media_text(expected);
         return [=](const ProbeAnswer& answer) {
             if (answer.kind != Kind::result) return verdict_wrong(text, "");
             const MediumStack got = probe::media_from(answer.value);
             return got == expected ? verdict_right() : verdict_wrong(text, media_text(got));
         };
     }}};

const JudgeRegistry::Registration refracted_ray_registration{
    {"refracted_ray", [](const Json& p) -> Judge {
         const AllowedAnswers allowed = allowed_from(p);
         const ExpectedRay expected = expected_ray_from(p.at("ray"));
         const std::string text = allowed_text(allowed, expected_ray_text(expected));
         return [=](const ProbeAnswer& answer) {
             if (answer.kind != Kind::result) return verdict_wrong(text, "");
             if (answer.value.is_null()) {
                 return allowed.none ? verdict_right() : verdict_wrong(text, "nullopt");
             }
             const Ray got = probe::ray_from(answer.value);
             if (allowed.direction && ray_matches(got, expected)) return verdict_right();
             return verdict_wrong(text, ray_text(got));
         };
     }}};

// Each ray asked must match an expected ray not matched yet. The expected rays of one case are
// far apart (the fake scene's keys, refraction_calls.cpp), so the first match is the only one.
const JudgeRegistry::Registration refraction_radiance_registration{
    {"refraction_radiance", [](const Json& p) -> Judge {
         const DoubleDoubleVec3 colour = probe::wide_vec3_from(p.at("colour"));
         const DoubleDoubleVec3 tolerance = probe::wide_vec3_from(p.at("colour_tolerance"));
         const Json& ray_list = p.at("rays");
         if (!ray_list.is_array()) throw std::invalid_argument("expected a list of rays");
         std::vector<ExpectedRay> rays;
         for (const Json& ray : ray_list)
             rays.push_back(expected_ray_from(ray));
         const std::string text = "colour " + full_text(narrow(colour)) + " (within " +
                                  full_text(narrow(tolerance)) + ") after asking about " +
                                  std::to_string(rays.size()) + " ray(s), in any order";
         return [=](const ProbeAnswer& answer) {
             if (answer.kind != Kind::result) return verdict_wrong(text, "");
             const Vec3 got_colour = probe::vec3_from(answer.value.at("colour"));
             const Json& got_rays = answer.value.at("rays");
             if (!got_rays.is_array()) throw std::invalid_argument("expected a list of rays");
             const std::string got = "colour " + full_text(got_colour) + " after asking about " +
                                     std::to_string(got_rays.size()) + " ray(s)";
             if (!near_wide(got_colour, colour, tolerance)) return verdict_wrong(text, got);
             if (got_rays.size() != rays.size()) return verdict_wrong(text, got);
             std::vector<bool> matched(rays.size(), false);
             for (std::size_t i = 0; i < got_rays.size(); ++i) {
                 const Ray ray = probe::ray_from(got_rays[i]);
                 bool found = false;
                 for (std::size_t k = 0; k < rays.size() && !found; ++k) {
                     if (!matched[k] && ray_matches(ray, rays[k])) matched[k] = found = true;
                 }
                 if (!found) {
                     return verdict_wrong(text + "; no such ray expected",
                                          "ray " + std::to_string(i) + " asked: " + ray_text(ray));
                 }
             }
             return verdict_right();
         };
     }}};

}  // namespace

Json refraction_judge(const AllowedAnswers& allowed, const DoubleDoubleVec3& direction,
                      const DoubleDouble& tolerance) {
    Json j = allowed_json(allowed);
    j["judge"] = "refraction";
    j["expected"] = probe::wide_vec3(direction);
    j["tolerance"] = probe::wide(tolerance);
    return j;
}

Json media_judge(const MediumStack& expected) {
    return {{"judge", "media"}, {"expected", probe::media(expected)}};
}

Json refracted_ray_judge(const AllowedAnswers& allowed, const ExpectedRay& ray) {
    Json j = allowed_json(allowed);
    j["judge"] = "refracted_ray";
    j["ray"] = expected_ray_json(ray);
    return j;
}

Json refraction_radiance_judge(const DoubleDoubleVec3& colour, const DoubleDoubleVec3& tolerance,
                               const std::vector<ExpectedRay>& rays) {
    Json list = Json::array();
    for (const ExpectedRay& ray : rays)
        list.push_back(expected_ray_json(ray));
    return {{"judge", "refraction_radiance"},
            {"colour", probe::wide_vec3(colour)},
            {"colour_tolerance", probe::wide_vec3(tolerance)},
            {"rays", std::move(list)}};
}

}  // namespace raystep::grade
