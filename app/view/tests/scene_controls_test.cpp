#include "app/view/scene_controls.h"

#include <filesystem>
#include <limits>
#include <map>
#include <string>

#include "base/scene/scene_loader.h"
#include "base/testing/catch.h"

using namespace raystep;

namespace {

Scene lit_scene(const std::string& extra = "") {
    return parse_scene(
        "size 4 4\ncamera 0 0 4 0 0 0 0 1 0 45\npoint 0 0 4 1 1 1\n"
        "sphere 0 0 0 1\n" +
            extra,
        "controls.test", ".");
}

std::string value_of(const std::vector<SceneControl>& controls, const std::string& name) {
    for (const SceneControl& control : controls) {
        if (control.name == name) return control.scene_value;
    }
    return "(none)";
}

}  // namespace

TEST_CASE("scene_controls: the offset where a light casts shadows, the samples where it samples",
          "[app]") {
    const std::vector<SceneControl> lit = scene_controls(lit_scene());
    CHECK(value_of(lit, "offset") == "error-bound");
    CHECK(value_of(lit, "spp") == "(none)");  // one sample per pixel: no stage 8
    CHECK(value_of(lit, "seed") == "(none)");
    CHECK(value_of(lit, "lightsamples") == "(none)");  // no quad light
    CHECK(value_of(lit, "ior") == "(none)");           // nothing transmits
    const std::vector<SceneControl> sampled = scene_controls(lit_scene("spp 4\n"));
    CHECK(value_of(sampled, "spp") == "4");
    CHECK(value_of(sampled, "pixelsampling") == "jittered");
    CHECK(value_of(sampled, "seed") != "(none)");
    const std::vector<SceneControl> dark = scene_controls(
        parse_scene("size 4 4\ncamera 0 0 4 0 0 0 0 1 0 45\nsphere 0 0 0 1\n", "dark.test", "."));
    CHECK(dark.empty());
}

TEST_CASE("scene_controls: the lecture scenes get the controls of the stages they use", "[app]") {
    const auto names_of = [](const std::string& relative) {
        const Scene scene = load_scene(std::string(RAYSTEP_SOURCE_DIR) + "/scenes/" + relative);
        std::string names;
        for (const SceneControl& control : scene_controls(scene))
            names += (names.empty() ? "" : " ") + control.name;
        return names;
    };
    // Stage 2: rays from a camera, nothing to light or sample
    CHECK(names_of("stage2/perspective-wide.test").empty());
    // Stage 6: a point light's shadows
    CHECK(names_of("stage6/cornell-box.test") == "offset epsilon");
    // Stage 8: an area light, sampled
    CHECK(names_of("demos/soft-shadows.test") ==
          "offset epsilon spp pixelsampling seed lightsamples lightstratify");
    // Stage 8's antialiasing: samples per pixel, no light
    CHECK(names_of("demos/aliasing.test") == "spp pixelsampling seed");
    // Stage 9: glass under a point light
    CHECK(names_of("stage9/glass-sphere.test") == "offset epsilon ior");
}

TEST_CASE("scene_controls: no scene of stages 2 to 7 shows a stage-8 or stage-9 control", "[app]") {
    for (int stage = 2; stage <= 7; ++stage) {
        const std::filesystem::path folder = std::filesystem::path(RAYSTEP_SOURCE_DIR) / "scenes" /
                                             ("stage" + std::to_string(stage));
        for (const auto& entry : std::filesystem::directory_iterator(folder)) {
            if (entry.path().extension() != ".test") continue;
            CAPTURE(entry.path().string());
            for (const SceneControl& control : scene_controls(load_scene(entry.path().string()))) {
                CAPTURE(control.name);
                CHECK((control.name == "offset" || control.name == "epsilon"));
                CHECK(stage >= 3);  // stage 2's scenes have no lights: no control at all
            }
        }
    }
}

TEST_CASE("apply_scene_controls: every sample count a scene file may ask for is taken back",
          "[app]") {
    // The page sends the scene's own values back with each render: a scene at spp 8192 must
    // render through the page as it does through raystep render.
    Scene scene = lit_scene("spp 65536\npixelsampling random\n");
    REQUIRE(scene.samples_per_pixel == kMaxSamples);
    const std::vector<SceneControl> controls = scene_controls(scene);
    CHECK_NOTHROW(apply_scene_controls(
        {{"spp", value_of(controls, "spp")}, {"pixelsampling", "random"}}, scene));
    CHECK(scene.samples_per_pixel == kMaxSamples);
    CHECK_THROWS_WITH(apply_scene_controls({{"spp", "65537"}}, scene),
                      "control spp: '65537' is not a whole number from 1 to 65536");
    CHECK_THROWS_WITH(apply_scene_controls({{"spp", "0"}}, scene),
                      "control spp: '0' is not a whole number from 1 to 65536");
}

TEST_CASE("apply_scene_controls: epsilon 0 is the lecture's shadow ray from the surface", "[app]") {
    Scene scene = lit_scene();
    apply_scene_controls({{"offset", "along-ray"}, {"epsilon", "0"}}, scene);
    CHECK(scene.ray_offset.rule == OffsetRule::along_ray);
    CHECK(scene.ray_offset.epsilon == 0.0);
    CHECK_THROWS_WITH(apply_scene_controls({{"offset", "along-ray"}, {"epsilon", "-1e-9"}}, scene),
                      "control epsilon: the offset distance must be >= 0");
    CHECK_THROWS_WITH(apply_scene_controls({{"offset", "along-ray"}, {"epsilon", "abc"}}, scene),
                      "control epsilon: 'abc' is not a number");
}

TEST_CASE("apply_scene_controls: a subnormal epsilon is a number, one beyond a double is not",
          "[app]") {
    Scene scene = lit_scene();
    apply_scene_controls({{"offset", "along-ray"}, {"epsilon", "1e-320"}}, scene);
    CHECK(scene.ray_offset.epsilon > 0.0);
    CHECK(scene.ray_offset.epsilon < std::numeric_limits<double>::min());
    CHECK_THROWS_WITH(apply_scene_controls({{"offset", "along-ray"}, {"epsilon", "1e400"}}, scene),
                      "control epsilon: '1e400' is beyond the largest double");
    CHECK_THROWS_WITH(apply_scene_controls({{"offset", "along-ray"}, {"epsilon", "nan"}}, scene),
                      "control epsilon: 'nan' is not a number");
    CHECK_THROWS_WITH(apply_scene_controls({{"offset", "along-ray"}, {"epsilon", ""}}, scene),
                      "control offset: along-ray needs epsilon, the offset distance");
}

TEST_CASE("controls_change_scene: the scene's own values change nothing, another value does",
          "[app]") {
    const Scene scene = lit_scene("spp 4\n");
    const std::vector<SceneControl> controls = scene_controls(scene);
    std::map<std::string, std::string> own;
    for (const SceneControl& control : controls)
        own[control.name] = control.scene_value;
    CHECK_FALSE(controls_change_scene(own, scene));
    own["spp"] = "9";
    CHECK(controls_change_scene(own, scene));
}
