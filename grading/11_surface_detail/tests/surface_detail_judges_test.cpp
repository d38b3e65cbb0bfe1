// Stage 11's data judges (grading/11_surface_detail/surface_detail_judges.h) on answers made by
// hand: each component within the tolerance and no further, a NaN never, and nullopt only where
// nullopt is expected.

#include <optional>

#include "base/testing/catch.h"

#include "app/grade/data_judge.h"
#include "app/probe/tests/probe_answers.h"
#include "base/testing/special_values.h"
#include "grading/11_surface_detail/surface_detail_json.h"
#include "grading/11_surface_detail/surface_detail_judges.h"

namespace raystep::grade {
namespace {

using raystep::testing::kNaN;

template <class T>
ProbeAnswer answer_of(const T& value) {
    return testing::result_answer(probe::JsonCodec<T>::write(value));
}

const SurfaceDerivatives kDerivatives{{2, 0, 0}, {0, 3, 0}};
const TangentFrame kFrame{{1, 0, 0}, {0, -1, 0}, {0, 0, 1}};

TEST_CASE("near_vec2 judge: takes each coordinate within the tolerance, no further, never NaN") {
    const Judge judge = build_judge(near_vec2_judge({0.25, 0.75}, 1e-12));
    CHECK(judge(answer_of(Vec2{0.25 + 5e-13, 0.75 - 5e-13})).passed);
    CHECK_FALSE(judge(answer_of(Vec2{0.25, 0.75 + 2e-12})).passed);
    CHECK_FALSE(judge(answer_of(Vec2{0.75, 0.25})).passed);
    CHECK_FALSE(judge(answer_of(Vec2{kNaN, 0.75})).passed);
}

TEST_CASE("surface_derivatives judge: nullopt only where the uvs have no area") {
    const Judge some = build_judge(surface_derivatives_judge(kDerivatives, 1e-12));
    CHECK(some(answer_of(std::optional<SurfaceDerivatives>(kDerivatives))).passed);
    CHECK_FALSE(some(answer_of(std::optional<SurfaceDerivatives>())).passed);
    CHECK_FALSE(some(answer_of(std::optional<SurfaceDerivatives>(
                         SurfaceDerivatives{kDerivatives.dpdv, kDerivatives.dpdu})))
                    .passed);
    CHECK_FALSE(some(answer_of(std::optional<SurfaceDerivatives>(
                         SurfaceDerivatives{{2, kNaN, 0}, kDerivatives.dpdv})))
                    .passed);

    const Judge none = build_judge(surface_derivatives_judge(std::nullopt, 0.0));
    CHECK(none(answer_of(std::optional<SurfaceDerivatives>())).passed);
    const Verdict wrong = none(answer_of(std::optional<SurfaceDerivatives>(kDerivatives)));
    CHECK_FALSE(wrong.passed);
    CHECK_THAT(wrong.expected, Catch::Matchers::Contains("no area"));
}

TEST_CASE("tangent_frame judge: the bitangent's side counts, and nullopt only where expected") {
    const Judge judge = build_judge(tangent_frame_judge(kFrame, 1e-12));
    CHECK(judge(answer_of(std::optional<TangentFrame>(kFrame))).passed);
    CHECK_FALSE(
        judge(answer_of(std::optional<TangentFrame>(TangentFrame{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}})))
            .passed);
    CHECK_FALSE(judge(answer_of(std::optional<TangentFrame>())).passed);

    const Judge none = build_judge(tangent_frame_judge(std::nullopt, 0.0));
    CHECK(none(answer_of(std::optional<TangentFrame>())).passed);
    CHECK_FALSE(none(answer_of(std::optional<TangentFrame>(kFrame))).passed);
}

TEST_CASE("the wrap mode's JSON: the scene file's words, and nothing else read") {
    CHECK(probe::JsonCodec<WrapMode>::write(WrapMode::mirror) == "mirror");
    CHECK(probe::JsonCodec<WrapMode>::read("clamp") == WrapMode::clamp);
    CHECK_THROWS_WITH(probe::JsonCodec<WrapMode>::read("wrap"),
                      Catch::Matchers::Contains("repeat, clamp, mirror"));
    CHECK_THROWS(probe::JsonCodec<WrapMode>::read(1));
}

}  // namespace
}  // namespace raystep::grade
