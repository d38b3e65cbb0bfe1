// The renderer's use of stages 5, 6 and 7: one pixel at a time, on scenes whose colour can be
// worked out by hand.

#include <string>
#include <vector>

#include "app/trace/tests/trace_lines.h"
#include "app/trace/trace_printer.h"
#include "base/scene/scene_loader.h"
#include "base/testing/catch.h"
#include "base/testing/vec3_matchers.h"
#include "renderer/render_pixel.h"

using namespace raystep;
using raystep::testing::has_line_starting;
using raystep::testing::IsNear;

namespace {

constexpr double kTight = 1e-12;

// A 1 x 1 image from (0, 0, 5) down -z: its one ray goes straight through the origin.
const std::string kCentreCamera = "size 1 1\ncamera 0 0 5 0 0 0 0 1 0 45\n";

Color pixel(const std::string& text, View view) {
    const Scene scene = parse_scene(text, "shading.test", ".");
    return render_pixel(prepare_render_scene(scene), view, 0, 0);
}

std::vector<std::string> traced(const std::string& text, View view) {
    const Scene scene = parse_scene(text, "shading.test", ".");
    const RenderScene render_scene = prepare_render_scene(scene);
    std::vector<std::string> lines;
    TracePrinter printer(render_scene, lines);
    render_pixel(render_scene, view, 0, 0, printer);
    return lines;
}

}  // namespace

TEST_CASE("shaded view: ambient plus a head-on directional light's diffuse term", "[app]") {
    // The ray meets the unit sphere at (0, 0, 1), normal +z; the light comes from +z, so
    // N . L = 1: I = A + Kd = 0.1 + 0.5.
    const Color c = pixel(kCentreCamera +
                              "directional 0 0 1 1 1 1\nambient 0.1 0.1 0.1\ndiffuse 0.5 0.5 0.5\n"
                              "sphere 0 0 0 1\n",
                          View::shaded);
    CHECK_THAT(c, IsNear(Color(0.6), kTight));
}

TEST_CASE("shaded view: a point light is divided by its attenuation", "[app]") {
    // The plane z = 0 at the origin, the light 2 above it: att = 0 + 0 * 2 + 1 * 2^2 = 4, so
    // I = Kd / 4 = 0.8 / 4.
    const Color c = pixel(kCentreCamera +
                              "attenuation 0 0 1\npoint 0 0 2 1 1 1\nambient 0 0 0\n"
                              "diffuse 0.8 0.8 0.8\nplane 0 0 0 0 0 1\n",
                          View::shaded);
    CHECK_THAT(c, IsNear(Color(0.2), kTight));
}

TEST_CASE("shaded view: an object between the point and the light leaves only ambient", "[app]") {
    // The camera looks at the origin from (3, 0, 3), past the sphere (its ray stays 1.06 from
    // the centre (0, 0, 1.5), beyond the radius 0.5), and sees the plane z = 0 there. The shadow
    // ray from the origin straight up to the light at z = 3 goes through the sphere.
    const std::string scene =
        "size 1 1\ncamera 3 0 3 0 0 0 0 0 1 30\npoint 0 0 3 1 1 1\nambient 0.1 0.1 0.1\n"
        "diffuse 0.5 0.5 0.5\nplane 0 0 0 0 0 1\nsphere 0 0 1.5 0.5\n";
    CHECK_THAT(pixel(scene, View::shaded), IsNear(Color(0.1), kTight));
    // Without the sphere, the light reaches: 0.1 + 0.5 (N . L = 1, no attenuation).
    const std::string unblocked = scene.substr(0, scene.find("sphere"));
    CHECK_THAT(pixel(unblocked, View::shaded), IsNear(Color(0.6), kTight));
}

TEST_CASE("full view: a mirror adds its reflectance times what the reflected ray sees", "[app]") {
    // The plane z = 0 reflects the eye ray back up +z, where a sphere behind the camera (the eye
    // ray starts at z = 5 and goes down) glows with ambient 0.8. I = 0.1 + 0.5 * 0.8.
    const std::string scene = kCentreCamera +
                              "ambient 0.1 0.1 0.1\nspecular 0.5 0.5 0.5\nplane 0 0 0 0 0 1\n"
                              "ambient 0.8 0.8 0.8\nspecular 0 0 0\nsphere 0 0 10 1\n";
    CHECK_THAT(pixel(scene + "maxdepth 1\n", View::full), IsNear(Color(0.5), kTight));
    // maxdepth 0 turns reflection off; the shaded view never reflects.
    CHECK_THAT(pixel(scene + "maxdepth 0\n", View::full), IsNear(Color(0.1), kTight));
    CHECK_THAT(pixel(scene + "maxdepth 1\n", View::shaded), IsNear(Color(0.1), kTight));
}

TEST_CASE("full view: an ellipsoid is shaded with its transformed normal", "[app]") {
    // The unit sphere squashed to (2, 1, 0.5) and lit from +z: the eye ray meets its top at
    // (0, 0, 0.5), where the normal is +z, so I = Kd exactly; with M n instead of M^-T n it
    // would still be +z here, so also check the depth: t = 5 - 0.5.
    const std::string scene = kCentreCamera +
                              "directional 0 0 1 1 1 1\nambient 0 0 0\ndiffuse 0.7 0.7 0.7\n"
                              "scale 2 1 0.5\nsphere 0 0 0 1\n";
    CHECK_THAT(pixel(scene, View::full), IsNear(Color(0.7), kTight));
    CHECK(pixel(scene, View::depth).r == Approx(4.5).epsilon(kTight));
}

TEST_CASE("trace: the full view prints every shadow ray, shading term and reflected ray", "[app]") {
    const std::vector<std::string> trace =
        traced(kCentreCamera +
                   "point 0 0 3 1 1 1\nambient 0.1 0.1 0.1\ndiffuse 0.5 0.5 0.5\n"
                   "specular 0.5 0.5 0.5\nshininess 10\nmaxdepth 2\nplane 0 0 0 0 0 1\n",
               View::full);
    CHECK(has_line_starting(trace, "surface point (0, 0, 0)"));
    CHECK(has_line_starting(trace, "point light (line 3): direction (0, 0, 1) distance 3"));
    CHECK(has_line_starting(trace, "  shadow ray origin"));
    CHECK(has_line_starting(trace, "  point light (line 3) diffuse (0.5, 0.5, 0.5)"));
    CHECK(has_line_starting(trace, "reflected ray 1: origin"));
    CHECK(has_line_starting(trace, "colour ("));
}

TEST_CASE("shaded view: a spot light lights a point inside its cone and not one outside", "[app]") {
    // The spot at (0, 0, 3) points at the sphere's front (0, 0, 1), 2 units away, head-on:
    // I = Kd = 0.5 there. Turned 45 degrees away, beyond its 30-degree cutoff, it adds nothing.
    const std::string sphere = "ambient 0 0 0\ndiffuse 0.5 0.5 0.5\nsphere 0 0 0 1\n";
    CHECK_THAT(pixel(kCentreCamera + "spot 0 0 3 0 0 -1 30 1 1 1 1\n" + sphere, View::shaded),
               IsNear(Color(0.5), kTight));
    CHECK(pixel(kCentreCamera + "spot 0 0 3 1 0 -1 30 1 1 1 1\n" + sphere, View::shaded) ==
          Color(0.0));
}
