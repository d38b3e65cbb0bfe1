// Stage 9's data judges (grading/9_refraction/refraction_judges.h) on answers made by hand: where
// total internal reflection is in question, what each judge takes and what it never takes (a NaN);
// the media exactly; and radiance's rays in any order, each once.

#include <cmath>

#include "base/testing/catch.h"

#include "app/grade/data_judge.h"
#include "app/probe/tests/probe_answers.h"
#include "base/testing/special_values.h"
#include "grading/9_refraction/refraction_json.h"
#include "grading/9_refraction/refraction_judges.h"

namespace raystep::grade {
namespace {

using raystep::testing::kInf;
using raystep::testing::kNaN;

const DoubleDoubleVec3 kDown{0, -1, 0};

ProbeAnswer null_answer() {
    return testing::result_answer(probe::Json(nullptr));
}

ProbeAnswer vec3_answer(const Vec3& v) {
    return testing::result_answer(probe::vec3(v));
}

ExpectedRay expected_ray(const Vec3& origin, const Vec3& direction) {
    return {DoubleDoubleVec3(origin),
            DoubleDouble(1e-12),
            DoubleDoubleVec3(direction),
            DoubleDouble(1e-12),
            0.0,
            kInf,
            std::nullopt};
}

probe::Json rays_json(const std::vector<Ray>& rays) {
    probe::Json list = probe::Json::array();
    for (const Ray& r : rays)
        list.push_back(probe::ray(r));
    return list;
}

ProbeAnswer radiance_answer(const Vec3& colour, const std::vector<Ray>& rays) {
    return testing::result_answer({{"colour", probe::vec3(colour)}, {"rays", rays_json(rays)}});
}

TEST_CASE("refraction judge: within rounding of the critical angle takes nullopt or the ray") {
    const Judge either = build_judge(refraction_judge({true, true}, kDown, DoubleDouble(1e-9)));
    CHECK(either(null_answer()).passed);
    CHECK(either(vec3_answer({0, -1, 0})).passed);
    CHECK_FALSE(either(vec3_answer({0, -1 + 1e-8, 0})).passed);
    CHECK_FALSE(either(vec3_answer({kNaN, kNaN, kNaN})).passed);
}

TEST_CASE("refraction judge: beyond the critical angle takes nullopt alone, before it no nullopt") {
    const Judge none = build_judge(refraction_judge({false, true}, kDown, DoubleDouble(1e-9)));
    CHECK(none(null_answer()).passed);
    CHECK_FALSE(none(vec3_answer({0, -1, 0})).passed);
    const Judge direction = build_judge(refraction_judge({true, false}, kDown, DoubleDouble(1e-9)));
    CHECK_FALSE(direction(null_answer()).passed);
    CHECK(direction(vec3_answer({0, -1, 0})).passed);
}

TEST_CASE("media judge: the same solids in the same order, nothing else") {
    const Medium glass{1, 1.5};
    const Medium water{2, 1.33};
    const Judge judge = build_judge(media_judge({glass, water}));
    CHECK(judge(testing::result_answer(probe::media({glass, water}))).passed);
    CHECK_FALSE(judge(testing::result_answer(probe::media({water, glass}))).passed);
    CHECK_FALSE(judge(testing::result_answer(probe::media({glass}))).passed);
    CHECK_FALSE(judge(testing::result_answer(probe::media({glass, {2, 1.5}}))).passed);
}

TEST_CASE("refracted_ray judge: nullopt only where total internal reflection may be") {
    const ExpectedRay ray = expected_ray({0, 0, 0}, {0, -1, 0});
    const Judge through = build_judge(refracted_ray_judge({true, false}, ray));
    CHECK(through(testing::result_answer(probe::ray({{0, 0, 0}, {0, -1, 0}, 0.0, kInf}))).passed);
    CHECK_FALSE(through(null_answer()).passed);
    const Judge reflected_only = build_judge(refracted_ray_judge({false, true}, ray));
    CHECK(reflected_only(null_answer()).passed);
    CHECK_FALSE(
        reflected_only(testing::result_answer(probe::ray({{0, 0, 0}, {0, -1, 0}, 0.0, kInf})))
            .passed);
}

TEST_CASE("refraction_radiance judge: the rays in any order, each once, and the colour") {
    const Ray eye{{0, 0, 0}, {1, 0, 0}, 0.0, kInf};
    const Ray reflected{{40, 0, 0}, {0, 1, 0}, 0.0, kInf};
    const Ray refracted{{40, 0, 0}, {0, -1, 0}, 0.0, kInf};
    const Judge judge = build_judge(
        refraction_radiance_judge({0.14, 0.1, 1.06}, DoubleDoubleVec3(1e-12),
                                  {expected_ray(eye.origin, eye.direction),
                                   expected_ray(reflected.origin, reflected.direction),
                                   expected_ray(refracted.origin, refracted.direction)}));
    const Vec3 colour{0.14, 0.1, 1.06};
    CHECK(judge(radiance_answer(colour, {eye, reflected, refracted})).passed);
    CHECK(judge(radiance_answer(colour, {eye, refracted, reflected})).passed);
    CHECK_FALSE(judge(radiance_answer(colour, {eye, reflected, reflected})).passed);
    CHECK_FALSE(judge(radiance_answer(colour, {eye, reflected})).passed);
    CHECK_FALSE(judge(radiance_answer({0.14, 0.1, 1.1}, {eye, reflected, refracted})).passed);
    CHECK_FALSE(judge(radiance_answer({0.14, kNaN, 1.06}, {eye, reflected, refracted})).passed);
}

}  // namespace
}  // namespace raystep::grade
