#include "grading/5_transforms/transform_judges.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "app/grade/data_judge.h"
#include "app/grade/value_text.h"
#include "app/protocol/wide_json.h"

namespace raystep::grade {

namespace {

using probe::Json;
using Kind = ProbeAnswer::Kind;

// How singular_transform writes an inverse's entry that must not be finite.
constexpr const char* kNotFinite = "not finite";

// Every entry within its tolerance; else the first that is not, and the whole matrix got, which
// the report calls `name`. Written so that a NaN fails.
Verdict near_matrix(const Mat4& got, const DoubleDoubleMat4& expected,
                    const DoubleDoubleMat4& tolerance, const std::string& name) {
    for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c) {
            if (!near_wide(got[c][r], expected[c][r], tolerance[c][r])) {
                const std::string entry =
                    name + " row " + std::to_string(r) + " column " + std::to_string(c) + " ";
                return verdict_wrong(
                    entry + full_text(expected[c][r]) + " (within " + full_text(tolerance[c][r]) +
                        ")",
                    entry + full_text(got[c][r]) + "; " + name + " " + matrix_text(got));
            }
        }
    }
    return verdict_right();
}

std::string hit_text(const std::optional<Hit>& h) {
    if (!h) return "a miss";
    return "t = " + full_text(h->t) + ", normal " + full_text(h->normal);
}

// An entry of singular_transform's diagonal: a number, or kNotFinite.
std::optional<double> diagonal_entry_from(const Json& j) {
    if (j.is_string() && j.get<std::string>() == kNotFinite) return std::nullopt;
    return probe::number_from(j);
}

const JudgeRegistry::Registration near_wide_matrix_registration{
    {"near_wide_matrix", [](const Json& p) -> Judge {
         const DoubleDoubleMat4 expected = probe::wide_mat4_from(p.at("expected"));
         const DoubleDoubleMat4 tolerance = probe::wide_mat4_from(p.at("tolerance"));
         return [=](const ProbeAnswer& answer) {
             if (answer.kind != Kind::result)
                 return verdict_wrong(matrix_text(narrow(expected)), "");
             return near_matrix(probe::mat4_from(answer.value), expected, tolerance, "matrix");
         };
     }}};

const JudgeRegistry::Registration near_wide_transform_registration{
    {"near_wide_transform", [](const Json& p) -> Judge {
         const DoubleDoubleMat4 matrix = probe::wide_mat4_from(p.at("matrix"));
         const DoubleDoubleMat4 matrix_tolerance = probe::wide_mat4_from(p.at("matrix_tolerance"));
         const DoubleDoubleMat4 inverse = probe::wide_mat4_from(p.at("inverse"));
         const DoubleDoubleMat4 inverse_tolerance =
             probe::wide_mat4_from(p.at("inverse_tolerance"));
         return [=](const ProbeAnswer& answer) {
             if (answer.kind != Kind::result) {
                 return verdict_wrong("matrix " + matrix_text(narrow(matrix)), "");
             }
             const Transform got = probe::transform_from(answer.value);
             const Verdict m = near_matrix(got.matrix, matrix, matrix_tolerance, "matrix");
             if (!m.passed) return m;
             return near_matrix(got.inverse, inverse, inverse_tolerance, "inverse");
         };
     }}};

const JudgeRegistry::Registration singular_transform_registration{
    {"singular_transform", [](const Json& p) -> Judge {
         const Mat4 matrix = probe::mat4_from(p.at("matrix"));
         const Json& diagonal_json = p.at("inverse_diagonal");
         if (!diagonal_json.is_array() || diagonal_json.size() != 3) {
             throw std::invalid_argument("expected an inverse_diagonal of three entries");
         }
         std::array<std::optional<double>, 3> diagonal;
         std::string diagonal_text;
         for (int k = 0; k < 3; ++k) {
             diagonal[k] = diagonal_entry_from(diagonal_json[k]);
             diagonal_text += (k == 0 ? "" : ", ") +
                              (diagonal[k] ? full_text(*diagonal[k]) : "not finite (1 / 0)");
         }
         const std::string text =
             "matrix " + matrix_text(matrix) + ", inverse diagonal " + diagonal_text;
         return [=](const ProbeAnswer& answer) {
             if (answer.kind != Kind::result) return verdict_wrong(text, "");
             const Transform got = probe::transform_from(answer.value);
             const Verdict m =
                 near_matrix(got.matrix, DoubleDoubleMat4(matrix), DoubleDoubleMat4(), "matrix");
             if (!m.passed) return m;
             for (int k = 0; k < 3; ++k) {
                 const double entry = got.inverse[k][k];
                 const bool ok = diagonal[k] ? entry == *diagonal[k] : !std::isfinite(entry);
                 if (!ok) return verdict_wrong(text, "inverse " + matrix_text(got.inverse));
             }
             return verdict_right();
         };
     }}};

const JudgeRegistry::Registration near_wide_ray_registration{
    {"near_wide_ray", [](const Json& p) -> Judge {
         const DoubleDoubleVec3 origin = probe::wide_vec3_from(p.at("origin"));
         const DoubleDoubleVec3 origin_tolerance = probe::wide_vec3_from(p.at("origin_tolerance"));
         const DoubleDoubleVec3 direction = probe::wide_vec3_from(p.at("direction"));
         const DoubleDoubleVec3 direction_tolerance =
             probe::wide_vec3_from(p.at("direction_tolerance"));
         const double t_min = probe::number_from(p.at("t_min"));
         const double t_max = probe::number_from(p.at("t_max"));
         const std::string text = ray_text({narrow(origin), narrow(direction), t_min, t_max}) +
                                  " (within " + full_text(narrow(origin_tolerance)) + " and " +
                                  full_text(narrow(direction_tolerance)) + ")";
         return [=](const ProbeAnswer& answer) {
             if (answer.kind != Kind::result) return verdict_wrong(text, "");
             const Ray got = probe::ray_from(answer.value);
             if (near_wide(got.origin, origin, origin_tolerance) &&
                 near_wide(got.direction, direction, direction_tolerance) && got.t_min == t_min &&
                 got.t_max == t_max) {
                 return verdict_right();
             }
             return verdict_wrong(text, ray_text(got));
         };
     }}};

// A miss's data is {"hit": false} alone; a hit's adds what it is judged by.
const JudgeRegistry::Registration near_wide_hit_registration{
    {"near_wide_hit", [](const Json& p) -> Judge {
         const bool hit = p.at("hit").get<bool>();
         double t = 0.0;
         double t_tolerance = 0.0;
         DoubleDoubleVec3 normal;
         DoubleDoubleVec3 normal_tolerance;
         std::string text = "a miss";
         if (hit) {
             t = probe::number_from(p.at("t"));
             t_tolerance = probe::number_from(p.at("t_tolerance"));
             normal = probe::wide_vec3_from(p.at("normal"));
             normal_tolerance = probe::wide_vec3_from(p.at("normal_tolerance"));
             text = "t = " + full_text(t) + " (within " + full_text(t_tolerance) +
                    "), unit normal " + full_text(narrow(normal)) + " (within " +
                    full_text(narrow(normal_tolerance)) + ")";
         }
         return [=](const ProbeAnswer& answer) {
             if (answer.kind != Kind::result) return verdict_wrong(text, "");
             const std::optional<Hit> got = probe::hit_from(answer.value);
             const bool ok = !got || !hit ? got.has_value() == hit
                                          : std::abs(got->t - t) <= t_tolerance &&
                                                near_wide(got->normal, normal, normal_tolerance) &&
                                                unit_length(got->normal);
             return ok ? verdict_right() : verdict_wrong(text, hit_text(got));
         };
     }}};

}  // namespace

Json near_wide_matrix_judge(const DoubleDoubleMat4& expected, const DoubleDoubleMat4& tolerance) {
    return {{"judge", "near_wide_matrix"},
            {"expected", probe::wide_mat4(expected)},
            {"tolerance", probe::wide_mat4(tolerance)}};
}

Json near_wide_transform_judge(const DoubleDoubleMat4& matrix,
                               const DoubleDoubleMat4& matrix_tolerance,
                               const DoubleDoubleMat4& inverse,
                               const DoubleDoubleMat4& inverse_tolerance) {
    return {{"judge", "near_wide_transform"},
            {"matrix", probe::wide_mat4(matrix)},
            {"matrix_tolerance", probe::wide_mat4(matrix_tolerance)},
            {"inverse", probe::wide_mat4(inverse)},
            {"inverse_tolerance", probe::wide_mat4(inverse_tolerance)}};
}

Json singular_transform_judge(const Mat4& matrix,
                              const std::array<std::optional<double>, 3>& inverse_diagonal) {
    Json diagonal = Json::array();
    for (const std::optional<double>& entry : inverse_diagonal)
        diagonal.push_back(entry ? probe::number(*entry) : Json(kNotFinite));
    return {{"judge", "singular_transform"},
            {"matrix", probe::mat4(matrix)},
            {"inverse_diagonal", diagonal}};
}

Json near_wide_ray_judge(const DoubleDoubleVec3& origin, const DoubleDoubleVec3& origin_tolerance,
                         const DoubleDoubleVec3& direction,
                         const DoubleDoubleVec3& direction_tolerance, double t_min, double t_max) {
    return {{"judge", "near_wide_ray"},
            {"origin", probe::wide_vec3(origin)},
            {"origin_tolerance", probe::wide_vec3(origin_tolerance)},
            {"direction", probe::wide_vec3(direction)},
            {"direction_tolerance", probe::wide_vec3(direction_tolerance)},
            {"t_min", probe::number(t_min)},
            {"t_max", probe::number(t_max)}};
}

Json near_wide_hit_judge(double t, double t_tolerance, const DoubleDoubleVec3& normal,
                         const DoubleDoubleVec3& normal_tolerance) {
    return {{"judge", "near_wide_hit"},
            {"hit", true},
            {"t", probe::number(t)},
            {"t_tolerance", probe::number(t_tolerance)},
            {"normal", probe::wide_vec3(normal)},
            {"normal_tolerance", probe::wide_vec3(normal_tolerance)}};
}

Json wide_miss_judge() {
    return {{"judge", "near_wide_hit"}, {"hit", false}};
}

}  // namespace raystep::grade
