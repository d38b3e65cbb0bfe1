#include "app/grade/value_judges.h"

#include <cmath>

#include "app/grade/data_judge.h"
#include "app/grade/value_text.h"
#include "app/protocol/wide_json.h"

namespace raystep::grade {

namespace {

using probe::Json;
using Kind = ProbeAnswer::Kind;

std::string within_text(const std::string& expected, double tolerance) {
    return expected + " (within " + full_text(tolerance) + ")";
}

const JudgeRegistry::Registration near_number_registration{
    {"near_number", [](const Json& p) -> Judge {
         const double expected = probe::number_from(p.at("expected"));
         const double tolerance = probe::number_from(p.at("tolerance"));
         return [=](const ProbeAnswer& answer) {
             if (answer.kind != Kind::result) return verdict_wrong(full_text(expected), "");
             const double got = probe::number_from(answer.value);
             if (std::abs(got - expected) <= tolerance) return verdict_right();
             return verdict_wrong(within_text(full_text(expected), tolerance), full_text(got));
         };
     }}};

const JudgeRegistry::Registration near_vec3_registration{
    {"near_vec3", [](const Json& p) -> Judge {
         const Vec3 expected = probe::vec3_from(p.at("expected"));
         const double tolerance = probe::number_from(p.at("tolerance"));
         return [=](const ProbeAnswer& answer) {
             if (answer.kind != Kind::result) return verdict_wrong(full_text(expected), "");
             const Vec3 got = probe::vec3_from(answer.value);
             if (near_double(got, expected, tolerance)) return verdict_right();
             return verdict_wrong(within_text(full_text(expected), tolerance), full_text(got));
         };
     }}};

const JudgeRegistry::Registration near_wide_number_registration{
    {"near_wide_number", [](const Json& p) -> Judge {
         const DoubleDouble expected = probe::wide_from(p.at("expected"));
         const DoubleDouble tolerance = probe::wide_from(p.at("tolerance"));
         const std::string text =
             within_text(full_text(static_cast<double>(expected)), static_cast<double>(tolerance));
         return [=](const ProbeAnswer& answer) {
             if (answer.kind != Kind::result) return verdict_wrong(text, "");
             const double got = probe::number_from(answer.value);
             if (near_wide(got, expected, tolerance)) return verdict_right();
             return verdict_wrong(text, full_text(got));
         };
     }}};

const JudgeRegistry::Registration near_wide_vec3_registration{
    {"near_wide_vec3", [](const Json& p) -> Judge {
         const DoubleDoubleVec3 expected = probe::wide_vec3_from(p.at("expected"));
         const DoubleDoubleVec3 tolerance = probe::wide_vec3_from(p.at("tolerance"));
         const bool unit = p.at("unit").get<bool>();
         const std::string text = std::string(unit ? "unit " : "") + full_text(narrow(expected)) +
                                  " (within " + full_text(narrow(tolerance)) + ")";
         return [=](const ProbeAnswer& answer) {
             if (answer.kind != Kind::result) return verdict_wrong(text, "");
             const Vec3 got = probe::vec3_from(answer.value);
             if (near_wide(got, expected, tolerance) && (!unit || unit_length(got)))
                 return verdict_right();
             return verdict_wrong(text, full_text(got));
         };
     }}};

const JudgeRegistry::Registration threw_registration{
    {"threw", [](const Json& p) -> Judge {
         const std::string type = p.at("type").get<std::string>();
         return [=](const ProbeAnswer& answer) {
             if (answer.kind == Kind::threw && answer.exception_type == type)
                 return verdict_right();
             return verdict_wrong("std::" + type + " thrown", "");
         };
     }}};

const JudgeRegistry::Registration frame_registration{
    {"frame", [](const Json& p) -> Judge {
         const Vec3 u = probe::vec3_from(p.at("u"));
         const Vec3 v = probe::vec3_from(p.at("v"));
         const Vec3 w = probe::vec3_from(p.at("w"));
         const double tolerance = probe::number_from(p.at("tolerance"));
         return [=](const ProbeAnswer& answer) {
             if (answer.kind != Kind::result) return verdict_wrong("a frame", "");
             const Vec3 got[3] = {probe::vec3_from(answer.value.at("u")),
                                  probe::vec3_from(answer.value.at("v")),
                                  probe::vec3_from(answer.value.at("w"))};
             if (near_double(got[0], u, tolerance) && near_double(got[1], v, tolerance) &&
                 near_double(got[2], w, tolerance)) {
                 return verdict_right();
             }
             return verdict_wrong(
                 within_text("u " + full_text(u) + " v " + full_text(v) + " w " + full_text(w),
                             tolerance),
                 "u " + full_text(got[0]) + " v " + full_text(got[1]) + " w " + full_text(got[2]));
         };
     }}};

}  // namespace

Json near_number_judge(double expected, double tolerance) {
    return {{"judge", "near_number"},
            {"expected", probe::number(expected)},
            {"tolerance", probe::number(tolerance)}};
}

Json near_vec3_judge(const Vec3& expected, double tolerance) {
    return {{"judge", "near_vec3"},
            {"expected", probe::vec3(expected)},
            {"tolerance", probe::number(tolerance)}};
}

Json near_wide_number_judge(const DoubleDouble& expected, const DoubleDouble& tolerance) {
    return {{"judge", "near_wide_number"},
            {"expected", probe::wide(expected)},
            {"tolerance", probe::wide(tolerance)}};
}

Json near_wide_vec3_judge(const DoubleDoubleVec3& expected, const DoubleDoubleVec3& tolerance,
                          bool unit) {
    return {{"judge", "near_wide_vec3"},
            {"expected", probe::wide_vec3(expected)},
            {"tolerance", probe::wide_vec3(tolerance)},
            {"unit", unit}};
}

Json threw_judge(const std::string& type) {
    return {{"judge", "threw"}, {"type", type}};
}

Json frame_judge(const Vec3& u, const Vec3& v, const Vec3& w, double tolerance) {
    return {{"judge", "frame"},
            {"u", probe::vec3(u)},
            {"v", probe::vec3(v)},
            {"w", probe::vec3(w)},
            {"tolerance", probe::number(tolerance)}};
}

}  // namespace raystep::grade
