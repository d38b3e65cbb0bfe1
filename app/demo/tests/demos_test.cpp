#include "app/demo/demos.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "app/demo/demo_list.h"
#include "app/demo/tests/demo_checks.h"
#include "base/testing/catch.h"
#include "renderer/view.h"

using namespace raystep;
using raystep::testing::check_panels;
using raystep::testing::differing_pixels;
using raystep::testing::kTestDemoSize;

namespace {

const Color kLeak(1.0, 0.0, 1.0);

int count_colour(const Image& image, const Color& colour) {
    int count = 0;
    for (int j = 0; j < image.height(); ++j) {
        for (int i = 0; i < image.width(); ++i) {
            if (image.at(i, j) == colour) ++count;
        }
    }
    return count;
}

// Pixels where a channel of `a` is darker than `b`'s by more than `step`.
int darker_pixels(const Image& a, const Image& b, double step) {
    int count = 0;
    for (int j = 0; j < a.height(); ++j) {
        for (int i = 0; i < a.width(); ++i) {
            const Color d = b.at(i, j) - a.at(i, j);
            if (d.r > step || d.g > step || d.b > step) ++count;
        }
    }
    return count;
}

// Pixels at `cost` or more on a heat map's scale, for costs above its red stop (the middle of
// the scale), where the colour climbs in green towards yellow and white.
int pixels_costing_at_least(const Image& image, double cost, const LogHeatScale& scale) {
    const Color threshold = log_heat_colour(cost, scale);
    int count = 0;
    for (int j = 0; j < image.height(); ++j) {
        for (int i = 0; i < image.width(); ++i) {
            const Color c = image.at(i, j);
            if (c.r >= threshold.r - 1e-6 && c.g >= threshold.g - 1e-6) ++count;
        }
    }
    return count;
}

}  // namespace

TEST_CASE("demo_list: the twelve lecture demos, in lecture order, each described", "[app]") {
    CHECK(demo_names() == std::vector<std::string>{"ray-directions", "barycentrics", "watertight",
                                                   "bvh-cost", "grid-cost", "normal-transform",
                                                   "shadow-acne", "aliasing", "soft-shadows",
                                                   "refraction", "path-tracing", "surface-detail"});
    for (const DemoEntry& demo : demo_list()) {
        CAPTURE(demo.name);
        CHECK(demo.description.substr(0, 6) == "stage ");
        CHECK(&find_demo(demo.name) == &demo);
    }
}

TEST_CASE("find_demo: an unknown name is refused with the list of demos", "[app]") {
    CHECK_THROWS_WITH(find_demo("teapot"),
                      "no demo 'teapot'; the demos are ray-directions, barycentrics, watertight, "
                      "bvh-cost, grid-cost, normal-transform, shadow-acne, aliasing, "
                      "soft-shadows, refraction, path-tracing, surface-detail");
}

TEST_CASE("ray_directions_demo: perspective rays fan out, orthographic rays are one colour",
          "[app]") {
    const DemoFigure figure = ray_directions_demo(kTestDemoSize);
    check_panels(figure, 2);
    const Image& perspective = figure.panels[0].image;
    const Image& orthographic = figure.panels[1].image;
    // Down -z: (0.5, 0.5, 0) on every orthographic pixel
    CHECK(count_colour(orthographic, Color(0.5, 0.5, 0.0)) ==
          orthographic.width() * orthographic.height());
    // Red grows to the right, green upwards
    const int w = perspective.width();
    const int h = perspective.height();
    CHECK(perspective.at(w - 1, h / 2).r > perspective.at(0, h / 2).r + 0.3);
    CHECK(perspective.at(w / 2, 0).g > perspective.at(w / 2, h - 1).g + 0.3);
}

TEST_CASE("barycentrics_demo: red, green and blue corners on the triangles", "[app]") {
    const DemoFigure figure = barycentrics_demo(kTestDemoSize);
    check_panels(figure, 2);
    for (const DemoPanel& panel : figure.panels) {
        CAPTURE(panel.caption);
        int reddish = 0;
        int greenish = 0;
        int blueish = 0;
        for (int j = 0; j < panel.image.height(); ++j) {
            for (int i = 0; i < panel.image.width(); ++i) {
                const Color c = panel.image.at(i, j);
                reddish += c.r > 0.8;
                greenish += c.g > 0.8;
                blueish += c.b > 0.8;
            }
        }
        CHECK(reddish > 0);
        CHECK(greenish > 0);
        CHECK(blueish > 0);
    }
}

TEST_CASE("watertight_demo: intersect_triangle never leaks, the half-space test does", "[app]") {
    const DemoFigure figure = watertight_demo(kTestDemoSize);
    check_panels(figure, 2);
    CHECK(count_colour(figure.panels[0].image, kLeak) == 0);
    CHECK(count_colour(figure.panels[1].image, kLeak) > 0);
    CHECK(figure.panels[0].caption == "intersect_triangle: 0 leaking pixels");
    CHECK(figure.panels[1].caption ==
          "half-spaces: " + thousands(count_colour(figure.panels[1].image, kLeak)) +
              " leaking pixels");
}

TEST_CASE("watertight_demo_with: one panel per triangle test, leaks only off the watertight one",
          "[app]") {
    const DemoFigure watertight = watertight_demo_with("intersect_triangle", kTestDemoSize);
    check_panels(watertight, 1);
    CHECK(watertight.panels[0].caption == "intersect_triangle: 0 leaking pixels");
    const DemoFigure halfspaces =
        watertight_demo_with("intersect_triangle_halfspaces", kTestDemoSize);
    check_panels(halfspaces, 1);
    CHECK(count_colour(halfspaces.panels[0].image, kLeak) > 0);
    CHECK_THROWS_WITH(watertight_demo_with("moller", kTestDemoSize),
                      "no triangle test 'moller'; the tests are intersect_triangle, "
                      "intersect_triangle_halfspaces, intersect_triangle_projection, "
                      "intersect_triangle_cramer");
}

TEST_CASE("demo_list: a demo's parameter has choices its make_with takes", "[app]") {
    for (const DemoEntry& demo : demo_list()) {
        CAPTURE(demo.name);
        CHECK(demo.parameter.name.empty() == (demo.make_with == nullptr));
        CHECK(demo.parameter.name.empty() == demo.parameter.choices.empty());
        // Only that each choice is taken, so at a small size: what each one draws is
        // watertight_demo_with's test.
        for (const std::string_view choice : demo.parameter.choices)
            CHECK_NOTHROW(demo.make_with(choice, DemoSize{96, 72}));
    }
}

TEST_CASE("demo_list: a demo explored live opens a scene of scenes/ in a view of the renderer",
          "[app]") {
    for (const DemoEntry& demo : demo_list()) {
        CAPTURE(demo.name);
        if (demo.scene.empty()) {
            CHECK(demo.view.empty());
            CHECK(demo.controls.empty());
            continue;
        }
        CHECK(std::filesystem::is_regular_file(std::filesystem::path(RAYSTEP_SOURCE_DIR) /
                                               "scenes" / demo.scene));
        CHECK(parse_view(std::string(demo.view)));
    }
    // The renderer's cost view counts the BVH's work: live, grid-cost would be bvh-cost again.
    CHECK(find_demo("grid-cost").scene.empty());
    CHECK_FALSE(find_demo("bvh-cost").scene.empty());
}

TEST_CASE("bvh_cost_demo and grid_cost_demo: the grid pays far more in the stadium",
          "[app][meshes]") {
    const DemoFigure bvh = bvh_cost_demo(kTestDemoSize);
    const DemoFigure grid = grid_cost_demo(kTestDemoSize);
    check_panels(bvh, 2);
    check_panels(grid, 2);
    REQUIRE(bvh.scale);
    REQUIRE(grid.scale);
    CHECK(bvh.scale->top == grid.scale->top);
    // The BVH never needs 1,000 steps for a ray; the grid's rays through the bunny's cells do
    CHECK(pixels_costing_at_least(bvh.panels[1].image, 1000, *bvh.scale) == 0);
    CHECK(pixels_costing_at_least(grid.panels[1].image, 1000, *grid.scale) > 100);
}

TEST_CASE("normal_transform_demo: normals by M and by M^-T differ on the ellipsoids only",
          "[app]") {
    const DemoFigure figure = normal_transform_demo(kTestDemoSize);
    check_panels(figure, 2);
    const Image& by_m = figure.panels[0].image;
    const Image& by_inverse_transpose = figure.panels[1].image;
    const int pixels = by_m.width() * by_m.height();
    // The shapes, and so the background, are the same; the colours on them are not
    CHECK(count_colour(by_m, Color(0.0)) == count_colour(by_inverse_transpose, Color(0.0)));
    CHECK(differing_pixels(by_m, by_inverse_transpose, 0.1) > pixels / 20);
}

TEST_CASE("shadow_acne_demo: acne falls as epsilon grows, none with the error bound", "[app]") {
    const DemoFigure figure = shadow_acne_demo(kTestDemoSize);
    check_panels(figure, 4);
    const Image& error_bound = figure.panels[3].image;
    const int zero = darker_pixels(figure.panels[0].image, error_bound, 0.05);
    const int too_small = darker_pixels(figure.panels[1].image, error_bound, 0.05);
    const int good = darker_pixels(figure.panels[2].image, error_bound, 0.05);
    CAPTURE(zero, too_small, good);
    CHECK(zero > too_small);
    CHECK(too_small > good);
    CHECK(good == 0);
    CHECK(figure.panels[0].caption == "epsilon = 0: " + thousands(zero) + " pixels of acne");
}

namespace {

// The standard deviation of r + g + b over the lit pixels of columns [x0, x1) and rows
// [y0, y1), each a fraction of the image's size.
double brightness_spread(const Image& image, double x0, double x1, double y0, double y1) {
    double sum = 0.0, squares = 0.0;
    int count = 0;
    for (int j = static_cast<int>(y0 * image.height()); j < y1 * image.height(); ++j) {
        for (int i = static_cast<int>(x0 * image.width()); i < x1 * image.width(); ++i) {
            const Color c = image.at(i, j);
            const double b = c.r + c.g + c.b;
            if (b < 1e-3) continue;
            sum += b;
            squares += b * b;
            ++count;
        }
    }
    REQUIRE(count > 0);
    const double mean = sum / count;
    return std::sqrt(std::max(0.0, squares / count - mean * mean));
}

}  // namespace

TEST_CASE("surface_detail_demo: the maps put bricks on a flat wall, read along tangent frames",
          "[app]") {
    const DemoFigure figure = surface_detail_demo(kTestDemoSize);
    check_panels(figure, 4);
    // The walls of stage11/bumps.test fill the middle of each third across, and rows 0.35 to 0.65
    // of a panel as wide as the test's (a demo panel keeps the scene's horizontal view).
    const Image& walls = figure.panels[1].image;
    const double flat = brightness_spread(walls, 0.12, 0.3, 0.35, 0.65);
    const double bumped = brightness_spread(walls, 0.42, 0.58, 0.35, 0.65);
    const double mapped = brightness_spread(walls, 0.72, 0.88, 0.35, 0.65);
    CHECK(bumped > 3 * flat);
    CHECK(mapped > 3 * flat);
    // Every wall has a tangent frame: its view is nowhere black there.
    const Image& frames = figure.panels[2].image;
    for (const double x : {0.2, 0.5, 0.8})
        CHECK(frames.at(static_cast<int>(x * frames.width()), frames.height() / 2) != Color(0.0));
}
