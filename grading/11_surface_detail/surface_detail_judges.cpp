#include "grading/11_surface_detail/surface_detail_judges.h"

#include <cmath>
#include <optional>
#include <string>

#include "app/grade/data_judge.h"
#include "app/grade/value_text.h"
#include "grading/11_surface_detail/surface_detail_json.h"

namespace raystep::grade {

namespace {

using probe::Json;
using Kind = ProbeAnswer::Kind;

// Each vector within `tolerance` per coordinate (near_double). Written so that a NaN fails.
bool components_within(const SurfaceDerivatives& got, const SurfaceDerivatives& expected,
                       double tolerance) {
    return near_double(got.dpdu, expected.dpdu, tolerance) &&
           near_double(got.dpdv, expected.dpdv, tolerance);
}

bool components_within(const TangentFrame& got, const TangentFrame& expected, double tolerance) {
    return near_double(got.tangent, expected.tangent, tolerance) &&
           near_double(got.bitangent, expected.bitangent, tolerance) &&
           near_double(got.normal, expected.normal, tolerance);
}

std::string surface_value_text(const SurfaceDerivatives& d) {
    return "dp/du " + full_text(d.dpdu) + ", dp/dv " + full_text(d.dpdv);
}

std::string surface_value_text(const TangentFrame& f) {
    return "tangent " + full_text(f.tangent) + ", bitangent " + full_text(f.bitangent) +
           ", normal " + full_text(f.normal);
}

std::string tolerance_text(double tolerance) {
    return tolerance > 0 ? " (each component within " + full_text(tolerance) + ")" : "";
}

const JudgeRegistry::Registration near_vec2_registration{
    {"near_vec2", [](const Json& p) -> Judge {
         const Vec2 expected = probe::vec2_from(p.at("expected"));
         const double tolerance = probe::number_from(p.at("tolerance"));
         const std::string want = full_text(expected) + tolerance_text(tolerance);
         return [=](const ProbeAnswer& answer) {
             if (answer.kind != Kind::result) return verdict_wrong(want, "");
             const Vec2 got = probe::vec2_from(answer.value);
             if (near_double(got, expected, tolerance)) return verdict_right();
             return verdict_wrong(want, full_text(got));
         };
     }}};

// The judge of a std::optional<T> answer: nullopt (which `none` explains) where the expectation
// is, else each component within the tolerance.
template <class T>
Judge optional_near_judge(const Json& p, const char* none) {
    const auto expected = probe::JsonCodec<std::optional<T>>::read(p.at("expected"));
    const double tolerance = probe::number_from(p.at("tolerance"));
    const auto answer_text = [none](const std::optional<T>& a) {
        return a ? surface_value_text(*a) : std::string("nullopt: ") + none;
    };
    const std::string want = answer_text(expected) + tolerance_text(tolerance);
    return [=](const ProbeAnswer& answer) {
        if (answer.kind != Kind::result) return verdict_wrong(want, "");
        const auto got = probe::JsonCodec<std::optional<T>>::read(answer.value);
        const bool right =
            got && expected ? components_within(*got, *expected, tolerance) : !got && !expected;
        return right ? verdict_right() : verdict_wrong(want, answer_text(got));
    };
}

const JudgeRegistry::Registration surface_derivatives_registration{
    {"surface_derivatives", [](const Json& p) {
         return optional_near_judge<SurfaceDerivatives>(p, "the uv triangle has no area");
     }}};

const JudgeRegistry::Registration tangent_frame_registration{
    {"tangent_frame", [](const Json& p) {
         return optional_near_judge<TangentFrame>(p, "dp/du has no part across the normal");
     }}};

}  // namespace

Json near_vec2_judge(const Vec2& expected, double tolerance) {
    return {{"judge", "near_vec2"},
            {"expected", probe::vec2(expected)},
            {"tolerance", probe::number(tolerance)}};
}

Json surface_derivatives_judge(const std::optional<SurfaceDerivatives>& expected,
                               double tolerance) {
    return {{"judge", "surface_derivatives"},
            {"expected", probe::JsonCodec<std::optional<SurfaceDerivatives>>::write(expected)},
            {"tolerance", probe::number(tolerance)}};
}

Json tangent_frame_judge(const std::optional<TangentFrame>& expected, double tolerance) {
    return {{"judge", "tangent_frame"},
            {"expected", probe::JsonCodec<std::optional<TangentFrame>>::write(expected)},
            {"tolerance", probe::number(tolerance)}};
}

}  // namespace raystep::grade
