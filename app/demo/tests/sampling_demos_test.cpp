#include <set>
#include <string>
#include <tuple>

#include "app/demo/demos.h"
#include "app/demo/tests/demo_checks.h"
#include "base/testing/catch.h"

using namespace raystep;
using raystep::testing::check_panels;
using raystep::testing::differing_pixels;
using raystep::testing::kTestDemoSize;

// The demos of stages 8 and 9 (sampling_demos.cpp, and shading_demos.cpp's refraction), at the
// test size of demo_checks.h, as demos_test.cpp renders the others.

namespace {

std::size_t distinct_colours(const Image& image) {
    std::set<std::tuple<float, float, float>> colours;
    for (int j = 0; j < image.height(); ++j) {
        for (int i = 0; i < image.width(); ++i) {
            const Color c = image.at(i, j);
            colours.emplace(static_cast<float>(c.r), static_cast<float>(c.g),
                            static_cast<float>(c.b));
        }
    }
    return colours.size();
}

// The sum of squared differences between horizontal neighbours: noise raises it.
double roughness(const Image& image) {
    double sum = 0.0;
    for (int j = 0; j < image.height(); ++j) {
        for (int i = 1; i < image.width(); ++i) {
            const Color d = image.at(i, j) - image.at(i - 1, j);
            sum += d.r * d.r + d.g * d.g + d.b * d.b;
        }
    }
    return sum;
}

}  // namespace

TEST_CASE("aliasing_demo: one ray per pixel keeps three flat colours, 16 jittered blend them",
          "[app]") {
    const DemoFigure figure = aliasing_demo(kTestDemoSize);
    check_panels(figure, 6);
    CHECK(figure.panels[0].caption == "regular, 1 spp (the centre)");
    CHECK(figure.panels[5].caption == "jittered, 16 spp (4 x 4)");
    // Sky, dark floor and white bands: a single sample per pixel sees one of them
    CHECK(distinct_colours(figure.panels[0].image) <= 3);
    CHECK(distinct_colours(figure.panels[3].image) <= 3);
    // Means over 16 samples mix them at every edge
    CHECK(distinct_colours(figure.panels[5].image) > 20);
    // One jittered sample lands elsewhere than the centre
    CHECK(differing_pixels(figure.panels[0].image, figure.panels[3].image) > 100);
}

TEST_CASE("soft_shadows_demo: 8 x 8 stratified light samples are smoother than 64 random ones",
          "[app]") {
    const DemoFigure figure = soft_shadows_demo(kTestDemoSize);
    check_panels(figure, 8);
    CHECK(figure.panels[3].caption == "stratified 8 x 8");
    CHECK(figure.panels[7].caption == "random 64");
    CHECK(roughness(figure.panels[3].image) < roughness(figure.panels[7].image));
    // More samples, less noise, either way
    CHECK(roughness(figure.panels[7].image) < roughness(figure.panels[4].image));
}

TEST_CASE("refraction_demo: each index renders the cube differently, captioned", "[app]") {
    const DemoFigure figure = refraction_demo(kTestDemoSize);
    check_panels(figure, 4);
    CHECK(figure.panels[0].caption == "n = 1 (air): no bending");
    CHECK(figure.panels[2].caption == "n = 1.5 (glass): critical angle 41.8 deg");
    CHECK(figure.panels[3].caption == "n = 2.4 (diamond): critical angle 24.6 deg");
    // The index reaches the renderer: every pair of panels differs where the cube is
    for (int a = 0; a < 4; ++a) {
        for (int b = a + 1; b < 4; ++b) {
            CAPTURE(a, b);
            CHECK(differing_pixels(figure.panels[a].image, figure.panels[b].image) > 100);
        }
    }
}

namespace {

// The RMSE a path-tracing panel's caption ends with: "MIS, 16 spp, RMSE 0.077".
double caption_rmse(const std::string& caption) {
    const std::size_t at = caption.rfind("RMSE ");
    REQUIRE(at != std::string::npos);
    return std::stod(caption.substr(at + 5));
}

}  // namespace

TEST_CASE("path_tracing_demo: light sampling beats hitting the light, and MIS converges", "[app]") {
    const DemoFigure figure = path_tracing_demo(kTestDemoSize);
    check_panels(figure, 8);
    CHECK(figure.panels[0].caption.rfind("hemisphere, RMSE ", 0) == 0);
    CHECK(figure.panels[3].caption.rfind("MIS, RMSE ", 0) == 0);
    CHECK(figure.panels[7].caption.rfind("MIS, 64 spp, RMSE ", 0) == 0);
    // At 16 paths a pixel: a light sample at each hit is far less noisy than waiting to hit the
    // small light, and cosine-weighted directions no worse than uniform ones.
    CHECK(caption_rmse(figure.panels[2].caption) < 0.5 * caption_rmse(figure.panels[1].caption));
    CHECK(caption_rmse(figure.panels[3].caption) < 0.5 * caption_rmse(figure.panels[0].caption));
    CHECK(caption_rmse(figure.panels[1].caption) <= caption_rmse(figure.panels[0].caption));
    // Four times the paths, about half the error.
    for (int k = 4; k < 7; ++k) {
        CAPTURE(k);
        CHECK(caption_rmse(figure.panels[k + 1].caption) <
              0.7 * caption_rmse(figure.panels[k].caption));
    }
}
