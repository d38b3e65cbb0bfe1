#include "app/view/scene_controls.h"

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

TEST_CASE("scene_controls: the offset where a light casts shadows, the samples, the seed",
          "[app]") {
    const std::vector<SceneControl> lit = scene_controls(lit_scene());
    CHECK(value_of(lit, "offset") == "error-bound");
    CHECK(value_of(lit, "spp") == "1");
    CHECK(value_of(lit, "lightsamples") == "(none)");  // no quad light
    CHECK(value_of(lit, "ior") == "(none)");           // nothing transmits
    const std::vector<SceneControl> dark = scene_controls(
        parse_scene("size 4 4\ncamera 0 0 4 0 0 0 0 1 0 45\nsphere 0 0 0 1\n", "dark.test", "."));
    CHECK(value_of(dark, "offset") == "(none)");
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
