#include "app/trace/trace_printer.h"

#include <string>
#include <vector>

#include "app/trace/tests/trace_lines.h"
#include "base/scene/scene_loader.h"
#include "base/testing/catch.h"
#include "renderer/render_pixel.h"

using namespace raystep;
using raystep::testing::count_lines_starting;
using raystep::testing::has_line_starting;

namespace {

std::vector<std::string> trace(const std::string& text, View view, int x, int y) {
    const Scene scene = parse_scene(text, "trace.test", RAYSTEP_TEST_DATA);
    const RenderScene render_scene = prepare_render_scene(scene);
    std::vector<std::string> lines;
    TracePrinter printer(render_scene, lines);
    render_pixel(render_scene, view, x, y, printer);
    return lines;
}

}  // namespace

TEST_CASE("trace: lists the camera ray, every primitive with its result, and the closest hit",
          "[app]") {
    const std::vector<std::string> lines = trace(
        "size 3 3\ncamera 0 0 5 0 0 0 0 1 0 45\nsphere 0 0 0 1\nsphere 0 0 -3 1\n"
        "sphere 5 0 0 1\nplane 0 0 -10 0 0 1\n",
        View::normal, 1, 1);
    REQUIRE(lines.size() == 6);
    CHECK(lines[0] == "camera ray: origin (0, 0, 5) direction (0, 0, -1) t in [0, inf]");
    CHECK(lines[1] == "sphere 0 (line 3): hit t=4 normal (0, 0, 1)");
    CHECK(lines[2] == "sphere 1 (line 4): hit t=7 normal (0, 0, 1)");
    CHECK(lines[3] == "sphere 2 (line 5): miss");
    CHECK(lines[4] == "plane 0 (line 6): hit t=15 normal (0, 0, 1)");
    CHECK(lines[5] == "closest_hit: sphere 0 at t=4 point (0, 0, 1) normal (0, 0, 1)");
}

TEST_CASE("trace: the rays view stops after the camera ray", "[app]") {
    const std::vector<std::string> lines =
        trace("size 3 3\ncamera 0 0 5 0 0 0 0 1 0 45\nsphere 0 0 0 1\n", View::rays, 1, 1);
    REQUIRE(lines.size() == 1);
    CHECK(lines[0].rfind("camera ray:", 0) == 0);
}

TEST_CASE("trace: a mesh's misses are counted, not listed one by one", "[app]") {
    std::string text = "size 3 3\ncamera 0 0 5 0 0 0 0 1 0 45\n";
    for (int k = 0; k < 100; ++k)
        text += "sphere " + std::to_string(10 + k) + " 0 0 0.5\n";
    text += "sphere 0 0 0 1\n";
    const std::vector<std::string> lines = trace(text, View::depth, 1, 1);
    REQUIRE(lines.size() == 5);
    CHECK(lines[1] == "sphere 100 (line 103): hit t=4 normal (0, 0, 1)");
    CHECK(lines[2] == "100 other spheres: miss");
    // 101 spheres: enough for a BVH, which says what the ray cost.
    CHECK(lines[3].rfind("BVH: ", 0) == 0);
    CHECK(lines[4].rfind("closest_hit: sphere 100", 0) == 0);
}

TEST_CASE("trace: a miss says so", "[app]") {
    const std::vector<std::string> lines =
        trace("size 3 3\ncamera 0 0 5 0 0 0 0 1 0 45\nsphere 9 9 9 1\n", View::depth, 0, 0);
    CHECK(lines.back() == "closest_hit: miss");
}

TEST_CASE("trace: an instance names its mesh and line, with the object-frame ray when moved",
          "[app]") {
    // The unit square of meshes/square.off placed as it is at z = 0, and again pushed back and
    // grown: the ray meets both, the first at t = 5.
    const std::vector<std::string> lines = trace(
        "size 3 3\ncamera 0.5 0.5 5 0.5 0.5 0 0 1 0 45\ndefine square meshes/square.off\n"
        "instance square\ntranslate 0 0 -1\nscale 2 2 2\ninstance square\n",
        View::depth, 1, 1);
    REQUIRE(lines.size() == 4);
    CHECK_THAT(lines[1], Catch::Matchers::StartsWith("mesh instance of 'square' (line 4): "
                                                     "triangle 0 (line 4) hit t=5 "));
    CHECK_THAT(lines[2],
               Catch::Matchers::StartsWith(
                   "mesh instance of 'square' (line 7), under a transform: object-frame ray "
                   "origin (0.25, 0.25, 3) direction (0, 0, -0.5): triangle "));
    CHECK(lines[3].rfind("closest_hit: triangle 0 at t=5 ", 0) == 0);
}

TEST_CASE("trace: each primitive under a shared transform is named with its own line", "[app]") {
    // Two spheres and a triangle under one translate: one instance, three lines.
    const std::vector<std::string> lines = trace(
        "size 3 3\ncamera 0 0 5 0 0 0 0 1 0 45\ntranslate 0 0 -1\nsphere 3 0 0 0.5\n"
        "vertex -9 -9 -5\nvertex 9 -9 -5\nvertex 0 9 -5\ntri 0 1 2\nsphere 0 0 0 1\n",
        View::depth, 1, 1);
    REQUIRE(lines.size() == 3);
    CHECK_THAT(lines[1], Catch::Matchers::StartsWith(
                             "3 primitives under one transform (the first at line 4), under a "
                             "transform: object-frame ray origin (0, 0, 6) direction (0, 0, -1): "
                             "sphere 1 (line 9) hit t=5 "));
    CHECK(lines[2].rfind("closest_hit: sphere 1 at t=5 ", 0) == 0);
}

TEST_CASE("trace: a sampled pixel shows its first sample's steps, each sample, and the mean",
          "[app]") {
    const std::vector<std::string> lines =
        trace("size 3 3\ncamera 0 0 5 0 0 0 0 1 0 45\nspp 4\nsphere 0 0 0 1\n", View::full, 1, 1);
    CHECK(count_lines_starting(lines, "camera sample ") == 4);
    CHECK(count_lines_starting(lines, "camera ray: ") == 1);  // the first sample's, in full
    CHECK_THAT(lines[0], Catch::Matchers::StartsWith("camera sample 0 through film point ("));
    CHECK(lines.back().rfind("pixel colour: the mean of 4 samples, ", 0) == 0);
}

TEST_CASE("trace: a quad light shows each light sample's shadow ray and the light's term",
          "[app]") {
    const std::vector<std::string> lines = trace(
        "size 3 3\ncamera 0 5 0 0 0 0 0 0 -1 45\nlightsamples 4\nlightstratify on\n"
        "quadLight -0.5 2 -0.5 0 0 1 1 0 0 5 5 5\ndiffuse 1 1 1\nplane 0 0 0 0 1 0\n",
        View::shaded, 1, 1);
    CHECK(has_line_starting(lines, "quad light (line 5): 4 samples, jittered"));
    CHECK(count_lines_starting(lines, "  light sample ") == 4);
    CHECK(has_line_starting(lines, "  quad light (line 5) term "));
}

TEST_CASE("trace: in the CSE168 dialect a quad light before the closest hit is seen, unshaded",
          "[app]") {
    // The light of the test above, now between the camera and the floor, emitting upwards.
    const std::string scene =
        "size 3 3\ncamera 0 5 0 0 0 0 0 0 -1 45\nintegrator direct\n"
        "quadLight -0.5 2 -0.5 1 0 0 0 0 1 5 5 5\ndiffuse 1 1 1\nplane 0 0 0 0 1 0\n";
    const std::vector<std::string> lines = trace(scene, View::full, 1, 1);
    CHECK(has_line_starting(lines, "closest_hit: plane 0 at t=5"));
    CHECK(has_line_starting(lines,
                            "quad light (line 4) seen at t 3, nearer than any surface "
                            "(the CSE168 dialect draws quad lights): its radiance (5, 5, 5)"));
    CHECK(count_lines_starting(lines, "  light sample ") == 0);
}

TEST_CASE("trace: a path-traced pixel shows each ray of its path and each shadow ray", "[app]") {
    // A floor under a light beside the eye ray, path-traced with a light sample at each hit: the
    // eye ray hits the floor and samples the light; its next ray leaves the scene or meets the
    // light.
    const std::string scene =
        "size 3 3\ncamera 0 5 0 0 0 0 0 0 -1 45\nintegrator pathtracer\nmaxdepth 1\n"
        "nexteventestimation on\nquadLight 1 2 -0.5 0 0 1 1 0 0 5 5 5\ndiffuse 1 1 1\n"
        "plane 0 0 0 0 1 0\n";
    const std::vector<std::string> lines = trace(scene, View::full, 1, 1);
    CHECK(has_line_starting(lines,
                            "path ray 0 (the eye ray): origin (0, 5, 0) direction "
                            "(0, -1, 0) hits plane 0 (line 8) at t=5"));
    CHECK(count_lines_starting(lines, "  shadow ray ") == 1);
    CHECK(has_line_starting(lines, "  shadow ray origin "));
    CHECK(count_lines_starting(lines, "path ray 1: ") == 1);
}

TEST_CASE("trace: a ray into the prism of total-internal-reflection.test reflects totally",
          "[app]") {
    const Scene scene = load_scene(std::string(RAYSTEP_SOURCE_DIR) +
                                   "/scenes/stage9/total-internal-reflection.test");
    const RenderScene render_scene = prepare_render_scene(scene);
    std::vector<std::string> lines;
    TracePrinter printer(render_scene, lines);
    render_pixel(render_scene, View::full, 160, 110, printer);
    CHECK(has_line_starting(lines, "transmission 1: entering solid "));
    CHECK(has_line_starting(lines, "transmission 2: leaving solid "));
    CHECK(has_line_starting(lines, "  total internal reflection: reflected ray "));
    CHECK(has_line_starting(lines, "  refracted ray "));
}
