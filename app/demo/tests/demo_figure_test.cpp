#include "app/demo/demo_figure.h"

#include <cmath>
#include <stdexcept>

#include <glm/trigonometric.hpp>

#include "app/demo/demo_scene.h"
#include "app/demo/label_text.h"
#include "base/testing/catch.h"
#include "base/testing/filled_image.h"

using namespace raystep;
using raystep::testing::filled_image;

namespace {

// Pixels of the rows [y0, y1) that are not the colour of the image's top-left corner.
int marked_pixels(const Image& image, int y0, int y1) {
    int count = 0;
    for (int j = y0; j < y1; ++j) {
        for (int i = 0; i < image.width(); ++i) {
            if (image.at(i, j) != image.at(0, 0)) ++count;
        }
    }
    return count;
}

DemoFigure two_panel_figure(const DemoSize& size) {
    const PanelSize panel = panel_size(size, 2, false);
    DemoFigure figure;
    figure.title = "A title";
    figure.panels.push_back({"red", filled_image(panel.width, panel.height, Color(1, 0, 0))});
    figure.panels.push_back({"blue", filled_image(panel.width, panel.height, Color(0, 0, 1))});
    return figure;
}

}  // namespace

TEST_CASE("figure_text_sizes: captions at a 26th of the height, titles at a 20th, for a hall",
          "[app]") {
    const FigureTextSizes lecture = figure_text_sizes(480);
    CHECK(lecture.caption_text == 18);
    CHECK(lecture.title_text == 24);
    CHECK(lecture.caption_strip == 29);  // the text and three tenths of it above and below
    CHECK(lecture.title_strip == 38);
    CHECK(lecture.scale_strip == 24 + 27);  // bar and ticks, then a line of numbers
    const FigureTextSizes projector = figure_text_sizes(1080);
    CHECK(projector.caption_text == 42);
    CHECK(projector.title_text == 54);
    CHECK(projector.caption_strip == 67);
    CHECK(projector.unit == Approx(2.25));
}

TEST_CASE("panel_size: one panel fills the width, two share it, four to eight make two rows",
          "[app]") {
    const DemoSize size{640, 480};
    // 480 = title 38 + panels + captions 29 each (+ the colour bar's 51)
    CHECK(panel_size(size, 1, false).width == 640);
    CHECK(panel_size(size, 1, false).height == 480 - 38 - 29);
    CHECK(panel_size(size, 2, true).width == 320);
    CHECK(panel_size(size, 2, true).height == 480 - 38 - 51 - 29);
    CHECK(panel_size(size, 4, false).width == 320);
    CHECK(panel_size(size, 4, false).height == (480 - 38) / 2 - 29);
    CHECK(panel_size(size, 6, false).width == 640 / 3);
    CHECK(panel_size(size, 6, false).height == (480 - 38) / 2 - 29);
    CHECK(panel_size(size, 7, false).width == 640 / 4);
    CHECK(panel_size(size, 8, false).width == 640 / 4);
    // At 1920 x 1080 the strips grow with the height: title 86, captions 67
    CHECK(panel_size({1920, 1080}, 2, false).height == 1080 - 86 - 67);
}

TEST_CASE("panel_size: no panels, nine panels or no room for them are refused", "[app]") {
    CHECK_THROWS_AS(panel_size({640, 480}, 0, false), std::invalid_argument);
    CHECK_THROWS_AS(panel_size({640, 480}, 9, false), std::invalid_argument);
    // The strips shrink with the image: what runs out first is a pixel for each panel
    CHECK_THROWS_AS(panel_size({640, 1}, 8, false), std::invalid_argument);
    CHECK_THROWS_AS(panel_size({3, 480}, 8, false), std::invalid_argument);
    CHECK_NOTHROW(panel_size({4, 480}, 8, false));
}

TEST_CASE("draw_figure: the panels side by side under the title, at the stated size", "[app]") {
    const DemoSize size{320, 240};
    const Image image = draw_figure(two_panel_figure(size), size, find_label_font());
    REQUIRE(image.width() == 320);
    REQUIRE(image.height() == 240);
    const PanelSize panel = panel_size(size, 2, false);
    const int top = figure_text_sizes(240).title_strip;  // 19
    CHECK(image.at(0, top) == Color(1, 0, 0));
    CHECK(image.at(panel.width - 1, top + panel.height - 1) == Color(1, 0, 0));
    CHECK(image.at(panel.width, top) == Color(0, 0, 1));
    CHECK(image.at(319, top + panel.height - 1) == Color(0, 0, 1));
    CHECK(image.at(0, top - 1) != Color(1, 0, 0));
}

TEST_CASE("draw_figure: with a font the title strip holds text, without one it stays blank",
          "[app]") {
    const DemoSize size{320, 240};
    const std::optional<LabelFont> font = find_label_font();
    if (!font) {
        WARN("no font: install fonts-dejavu-core to test the labels; tried " + label_fonts_tried());
    } else {
        CHECK(marked_pixels(draw_figure(two_panel_figure(size), size, font), 0, 19) > 50);
    }
    CHECK(marked_pixels(draw_figure(two_panel_figure(size), size, std::nullopt), 0, 19) == 0);
}

TEST_CASE("draw_figure: a panel of the wrong size is a programming error", "[app]") {
    DemoFigure figure = two_panel_figure({320, 240});
    figure.panels[1].image = Image(10, 10);
    CHECK_THROWS_AS(draw_figure(figure, {320, 240}, std::nullopt), std::logic_error);
}

TEST_CASE("draw_figure: a heat map's scale is drawn along the bottom, cold to hot", "[app]") {
    const DemoSize size{320, 240};
    const PanelSize panel = panel_size(size, 1, true);
    DemoFigure figure;
    figure.title = "scale";
    figure.panels.push_back({"", filled_image(panel.width, panel.height, Color(0.0))});
    figure.scale = LogHeatScale{1e5, "steps"};
    const Image image = draw_figure(figure, size, std::nullopt);
    // At 240 lines every length is half the 480-line layout's: the bar starts 3 rows into the
    // strip and is 7 high; it runs from 79 (margin 4 + label 75) to 290 (29 short of the edge,
    // for half the last number and the margin). Black at its left end, white at its right.
    const int row = 240 - figure_text_sizes(240).scale_strip + 3 + 3;
    CHECK(image.at(79, row) == Color(0.0));
    CHECK(image.at(78, row) != Color(0.0));
    CHECK(image.at(290, row) == Color(1.0));
}

TEST_CASE("log_heat_colour: black at 1 or less and for NaN, white at the top", "[app]") {
    const LogHeatScale scale{1e4, "steps"};
    CHECK(log_heat_colour(0.0, scale) == Color(0.0));
    CHECK(log_heat_colour(1.0, scale) == Color(0.0));
    CHECK(log_heat_colour(std::nan(""), scale) == Color(0.0));
    CHECK(log_heat_colour(1e4, scale) == Color(1.0));
    CHECK(log_heat_colour(1e9, scale) == Color(1.0));
    // Halfway up the scale, 100 of 10^4, is halfway along the heat map: its red stop
    CHECK(log_heat_colour(100.0, scale).r == Approx(0.9));
}

TEST_CASE("thousands: counts with a comma every three digits", "[app]") {
    CHECK(thousands(0) == "0");
    CHECK(thousands(999) == "999");
    CHECK(thousands(1000) == "1,000");
    CHECK(thousands(64893) == "64,893");
    CHECK(thousands(1234567) == "1,234,567");
}

TEST_CASE("draw_text: text beyond ASCII is refused before OpenImageIO garbles it", "[app]") {
    // Refused before the font is opened: no font needed
    Image image(100, 20);
    CHECK_THROWS_AS(draw_text(image, LabelFont{"no such font"}, "\xCE\xB5 = 0", 0, 10, 12, 100,
                              TextAlign::left),
                    std::invalid_argument);
}

TEST_CASE("load_demo_scene: a narrower panel keeps the view's width and shows more height",
          "[app][meshes]") {
    // stage4/bunny.test: 640 x 480, fovy 32
    const Scene scene = load_demo_scene("stage4/bunny.test", {320, 424});
    CHECK(scene.width == 320);
    CHECK(scene.height == 424);
    const double half_width = std::tan(glm::radians(scene.camera.fovy_degrees) / 2) * 320 / 424;
    CHECK(half_width == Approx(std::tan(glm::radians(32.0) / 2) * 640 / 480));
}

TEST_CASE("load_demo_scene: an orthographic window keeps its sides and its middle", "[app]") {
    // stage2/orthographic.test: 480 x 360, ortho -4 4 -3 3
    const Scene scene = load_demo_scene("stage2/orthographic.test", {320, 160});
    REQUIRE(scene.camera.ortho);
    CHECK(scene.camera.ortho->left == -4);
    CHECK(scene.camera.ortho->right == 4);
    CHECK(scene.camera.ortho->bottom == Approx(-2));
    CHECK(scene.camera.ortho->top == Approx(2));
}
