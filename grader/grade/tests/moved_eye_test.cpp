// The eye a render check looks from (grader/grade/checks/moved_eye.h): the scene's turned about
// its look-at point for each grade, far enough that the image a student release holds for the
// check (the reference's, from the scene's own eye) fails it.

#include "grader/grade/checks/moved_eye.h"

#include <cmath>
#include <filesystem>

#include <glm/geometric.hpp>

#include "app/compare/render_rule.h"
#include "app/probe/render_calls.h"
#include "base/scene/scene_loader.h"
#include "base/testing/catch.h"
#include "grader/grade/checks/stage_checks.h"

using namespace raystep;
namespace fs = std::filesystem;

namespace {

double angle_degrees(const Vec3& a, const Vec3& b) {
    const double c = glm::dot(a, b) / (glm::length(a) * glm::length(b));
    return std::acos(std::min(1.0, std::max(-1.0, c))) * 180.0 / 3.14159265358979323846;
}

}  // namespace

TEST_CASE("moved_eye: the eye keeps its distance to the look-at point, turned by the stated angles",
          "[grader]") {
    const CameraSpec camera{Vec3(3.2, 3.3, 5.2), Vec3(0, 0.8, 0), Vec3(0, 1, 0), 40.0, {}, 1};
    const Vec3 from_target = camera.lookfrom - camera.lookat;
    // The turn and the tilt are about perpendicular axes: together at least the smaller turn, at
    // most their sum.
    const double least = grade::kEyeTurnMinDegrees;
    const double most = grade::kEyeTurnMaxDegrees + grade::kEyeTiltMaxDegrees;
    for (std::uint64_t seed = 1; seed <= 200; ++seed) {
        CAPTURE(seed);
        const Vec3 eye = grade::moved_eye(camera, seed, "stage5.render.table.depth");
        CHECK(glm::length(eye - camera.lookat) == Approx(glm::length(from_target)).epsilon(1e-12));
        const double angle = angle_degrees(eye - camera.lookat, from_target);
        CHECK(angle >= least - 1e-9);
        CHECK(angle <= most + 1e-9);
    }
}

TEST_CASE("moved_eye: the same grade and check give the same eye; another of either, another eye",
          "[grader]") {
    const CameraSpec camera{Vec3(0, 2, 8), Vec3(0, 0.5, 0), Vec3(0, 1, 0), 40.0, {}, 1};
    const Vec3 eye = grade::moved_eye(camera, 7, "stage3.render.spheres-on-plane.depth");
    CHECK(grade::moved_eye(camera, 7, "stage3.render.spheres-on-plane.depth") == eye);
    CHECK(grade::moved_eye(camera, 8, "stage3.render.spheres-on-plane.depth") != eye);
    CHECK(grade::moved_eye(camera, 7, "stage3.render.spheres-on-plane.normal") != eye);
}

TEST_CASE("moved_eye: an eye straight along the up hint still moves, and stays finite",
          "[grader]") {
    const CameraSpec camera{Vec3(0, 10, 0), Vec3(0, 0, 0), Vec3(0, 1, 0), 45.0, {}, 1};
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
        CAPTURE(seed);
        const Vec3 eye = grade::moved_eye(camera, seed, "pipeline.render.top.full");
        CHECK(std::isfinite(eye.x + eye.y + eye.z));
        CHECK(glm::length(eye) == Approx(10.0).epsilon(1e-12));
        CHECK(angle_degrees(eye, camera.lookfrom) >= grade::kEyeTiltMinDegrees - 1e-9);
    }
}

TEST_CASE("render checks: the image a release holds for a check fails it from the moved eye",
          "[grader]") {
    // Every render check a release holds as data, with the reference's image from the scene's own
    // eye: from the eye a grade moves it to, that image must be far outside the rule, so that a
    // submission that answers with it (or with any image a release holds) fails.
    const std::vector<grade::PublicCheck> checks = grade::render_public_checks(RAYSTEP_SOURCE_DIR);
    REQUIRE(checks.size() >= 20);
    for (const grade::PublicCheck& check : checks) {
        REQUIRE(check.cases.size() == 1);
        const grade::PublicCase& shown = check.cases.front();
        const Image held = probe::image_from(shown.judge.at("reference"), 1u << 20);
        probe::RenderQuestion question =
            probe::JsonCodec<probe::RenderQuestion>::read(shown.query.args);
        question.scene = (fs::path(RAYSTEP_SOURCE_DIR) / question.scene).string();
        const CameraSpec camera = load_scene(question.scene).camera;
        for (std::uint64_t grade_seed = 1; grade_seed <= 5; ++grade_seed) {
            CAPTURE(check.id, grade_seed);
            question.lookfrom = grade::moved_eye(camera, grade_seed, check.id);
            const RenderVerdict verdict = judge_render(probe::render_for_probe(question), held);
            // Four times the share a render may differ in and still pass: the view that changes
            // least, the flat fan of triangles facing the eye, changes by more than that at
            // every seed tried (docs/measurements/render-eye.md).
            CHECK(verdict.share_over > 4.0 * kDifferingShareAllowed);
        }
    }
}
