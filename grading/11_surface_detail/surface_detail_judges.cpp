#include "grading/11_surface_detail/surface_detail_judges.h"

#include <cmath>
#include <optional>
#include <string>
#include <type_traits>

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

std::string surface_value_text(const Vec2& uv) {
    return full_text(uv);
}

std::string surface_value_text(const SurfaceDerivatives& d) {
    return "dp/du " + full_text(d.dpdu) + ", dp/dv " + full_text(d.dpdv);
}

std::string surface_value_text(const TangentFrame& f) {
    return "tangent " + full_text(f.tangent) + ", bitangent " + full_text(f.bitangent) +
           ", normal " + full_text(f.normal);
}

// The judge of an answer of type T, or of std::optional<T> where `none` names what nullopt means.
template <class T>
Judge near_judge(const Json& p, const char* none) {
    using Answer = std::conditional_t<std::is_same_v<T, Vec2>, T, std::optional<T>>;
    const Answer expected = probe::JsonCodec<Answer>::read(p.at("expected"));
    const double tolerance = probe::number_from(p.at("tolerance"));
    const auto answer_text = [none](const Answer& a) {
        if constexpr (std::is_same_v<Answer, T>) {
            return surface_value_text(a);
        } else {
            return a ? surface_value_text(*a) : std::string("nullopt: ") + none;
        }
    };
    std::string want = answer_text(expected);
    if (tolerance > 0) want += " (each component within " + full_text(tolerance) + ")";
    return [=](const ProbeAnswer& answer) {
        if (answer.kind != Kind::result) return verdict_wrong(want, "");
        const Answer got = probe::JsonCodec<Answer>::read(answer.value);
        bool right = false;
        if constexpr (std::is_same_v<Answer, T>) {
            right = near_double(got, expected, tolerance);
        } else {
            right =
                got && expected ? components_within(*got, *expected, tolerance) : !got && !expected;
        }
        return right ? verdict_right() : verdict_wrong(want, answer_text(got));
    };
}

const JudgeRegistry::Registration near_vec2_registration{
    {"near_vec2", [](const Json& p) { return near_judge<Vec2>(p, ""); }}};

const JudgeRegistry::Registration surface_derivatives_registration{
    {"surface_derivatives", [](const Json& p) {
         return near_judge<SurfaceDerivatives>(p, "the uv triangle has no area");
     }}};

const JudgeRegistry::Registration tangent_frame_registration{
    {"tangent_frame", [](const Json& p) {
         return near_judge<TangentFrame>(p, "dp/du has no part across the normal");
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
