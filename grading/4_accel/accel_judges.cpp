#include "grading/4_accel/accel_judges.h"

#include <cmath>
#include <string>

#include "app/grade/data_judge.h"
#include "app/grade/value_text.h"
#include "app/protocol/wide_json.h"
#include "renderer/render_scene.h"

namespace raystep::grade {

std::string primitive_hit_text(const std::optional<PrimitiveHit>& h) {
    if (!h) return "a miss";
    return std::string(kind_name(h->kind)) + " " + std::to_string(h->index) +
           " at t = " + full_text(h->hit.t);
}

namespace {

using probe::Json;
using Kind = ProbeAnswer::Kind;

std::string interval_text(double enter, double exit) {
    return "[" + full_text(enter) + ", " + full_text(exit) + "]";
}

std::string slab_interval_text(const SlabInterval& exact) {
    if (exact.must_miss) return "a miss";
    const std::string interval = "t in " + interval_text(exact.enter.hi, exact.exit.hi) +
                                 " (within " + full_text(exact.enter_tolerance) + " and " +
                                 full_text(exact.exit_tolerance) + ")";
    return exact.must_hit ? interval : interval + " or a miss (the ray passes within rounding)";
}

// An infinite end is compared exactly; written so that a NaN fails.
bool within_tolerance(double got, const DoubleDouble& expected, const DoubleDouble& tolerance) {
    if (is_infinite(expected)) return got == expected.hi;
    return near_wide(got, expected, tolerance);
}

const JudgeRegistry::Registration slab_interval_registration{
    {"slab_interval", [](const Json& p) -> Judge {
         SlabInterval exact;
         exact.must_hit = p.at("must_hit").get<bool>();
         exact.must_miss = p.at("must_miss").get<bool>();
         exact.enter = probe::wide_from(p.at("enter"));
         exact.exit = probe::wide_from(p.at("exit"));
         exact.enter_tolerance = probe::wide_from(p.at("enter_tolerance"));
         exact.exit_tolerance = probe::wide_from(p.at("exit_tolerance"));
         const std::string expected = slab_interval_text(exact);
         return [=](const ProbeAnswer& answer) {
             if (answer.kind != Kind::result) return verdict_wrong(expected, "");
             if (answer.value.is_null())
                 return exact.must_hit ? verdict_wrong(expected, "a miss") : verdict_right();
             const double enter = probe::number_from(answer.value.at("enter"));
             const double exit = probe::number_from(answer.value.at("exit"));
             const std::string got = "t in " + interval_text(enter, exit);
             if (exact.must_miss) return verdict_wrong(expected, got);
             if (!(enter <= exit)) return verdict_wrong(expected, got + ", which is empty");
             const bool ok = within_tolerance(enter, exact.enter, exact.enter_tolerance) &&
                             within_tolerance(exit, exact.exit, exact.exit_tolerance);
             return ok ? verdict_right() : verdict_wrong(expected, got);
         };
     }}};

std::string cells_text(const glm::ivec3& cells) {
    return std::to_string(cells.x) + " x " + std::to_string(cells.y) + " x " +
           std::to_string(cells.z);
}

const JudgeRegistry::Registration grid_cells_registration{
    {"grid_cells", [](const Json& p) -> Judge {
         const Json& e = p.at("expected");
         const glm::ivec3 expected(e.at(0).get<int>(), e.at(1).get<int>(), e.at(2).get<int>());
         return [=](const ProbeAnswer& answer) {
             if (answer.kind != Kind::result) return verdict_wrong(cells_text(expected), "");
             const Json& v = answer.value;
             const bool cells = v.is_array() && v.size() == 3 && v[0].is_number_integer() &&
                                v[1].is_number_integer() && v[2].is_number_integer();
             if (!cells) return verdict_wrong(cells_text(expected), v.dump());
             const glm::ivec3 got(v[0].get<int>(), v[1].get<int>(), v[2].get<int>());
             return got == expected ? verdict_right()
                                    : verdict_wrong(cells_text(expected), cells_text(got));
         };
     }}};

// The one answer of a list of one ray, or nothing when the result is not such a list.
const Json* only_answer(const ProbeAnswer& answer) {
    if (answer.kind != Kind::result || !answer.value.is_array() || answer.value.size() != 1) {
        return nullptr;
    }
    return &answer.value[0];
}

std::string got_text(const ProbeAnswer& answer) {
    return answer.kind == Kind::result ? answer.value.dump() + ", not a list of one answer" : "";
}

const JudgeRegistry::Registration structure_hit_registration{
    {"structure_hit", [](const Json& p) -> Judge {
         const std::optional<PrimitiveHit> expected = probe::primitive_hit_from(p.at("expected"));
         const double tolerance = probe::number_from(p.at("t_tolerance"));
         const std::string text =
             primitive_hit_text(expected) +
             (expected && tolerance > 0 ? " (within " + full_text(tolerance) + ")" : "");
         return [=](const ProbeAnswer& answer) {
             const Json* const one = only_answer(answer);
             if (!one) return verdict_wrong(text, got_text(answer));
             const std::optional<PrimitiveHit> got = probe::primitive_hit_from(*one);
             // Written so that a NaN t fails
             const bool same =
                 got.has_value() == expected.has_value() &&
                 (!got || (got->kind == expected->kind && got->index == expected->index &&
                           std::fabs(got->hit.t - expected->hit.t) <= tolerance));
             return same ? verdict_right() : verdict_wrong(text, primitive_hit_text(got));
         };
     }}};

const JudgeRegistry::Registration structure_occluded_registration{
    {"structure_occluded", [](const Json& p) -> Judge {
         const bool expected = p.at("expected").get<bool>();
         const std::string text = expected ? "occluded" : "not occluded";
         return [=](const ProbeAnswer& answer) {
             const Json* const one = only_answer(answer);
             if (!one) return verdict_wrong(text, got_text(answer));
             if (!one->is_boolean()) return verdict_wrong(text, "not a boolean");
             const bool got = one->get<bool>();
             return got == expected ? verdict_right()
                                    : verdict_wrong(text, got ? "occluded" : "not occluded");
         };
     }}};

}  // namespace

Json slab_interval_judge(const SlabInterval& exact) {
    return {{"judge", "slab_interval"},
            {"must_hit", exact.must_hit},
            {"must_miss", exact.must_miss},
            {"enter", probe::wide(exact.enter)},
            {"exit", probe::wide(exact.exit)},
            {"enter_tolerance", probe::wide(exact.enter_tolerance)},
            {"exit_tolerance", probe::wide(exact.exit_tolerance)}};
}

Json grid_cells_judge(const glm::ivec3& expected) {
    return {{"judge", "grid_cells"},
            {"expected", Json::array({expected.x, expected.y, expected.z})}};
}

Json structure_hit_judge(const std::optional<PrimitiveHit>& expected, double t_tolerance) {
    return {{"judge", "structure_hit"},
            {"expected", probe::primitive_hit(expected)},
            {"t_tolerance", probe::number(t_tolerance)}};
}

Json structure_occluded_judge(bool expected) {
    return {{"judge", "structure_occluded"}, {"expected", expected}};
}

}  // namespace raystep::grade
