#pragma once

// What every demo's test checks of its figure (app/demo/demos.h), and the pixel counts its
// checks compare with, at half the lecture size.

#include <cstddef>

#include "app/demo/demos.h"
#include "base/testing/catch.h"

namespace raystep::testing {

/// Half the lecture size in each direction: a quarter of the pixels, so that all the demos
/// together render in about a second.
inline const DemoSize kTestDemoSize{320, 240};

/// That `figure` has `count` captioned panels of the size its layout gives, and a title, and
/// draws at the test size.
inline void check_panels(const DemoFigure& figure, int count) {
    REQUIRE(figure.panels.size() == static_cast<std::size_t>(count));
    CHECK_FALSE(figure.title.empty());
    const PanelSize panel = panel_size(kTestDemoSize, count, figure.scale.has_value());
    for (const DemoPanel& p : figure.panels) {
        CAPTURE(p.caption);
        CHECK_FALSE(p.caption.empty());
        CHECK(p.image.width() == panel.width);
        CHECK(p.image.height() == panel.height);
    }
    const Image image = draw_figure(figure, kTestDemoSize, std::nullopt);
    CHECK(image.width() == kTestDemoSize.width);
    CHECK(image.height() == kTestDemoSize.height);
}

/// The pixels where a channel of `a` and `b` differ by more than `step`.
inline int differing_pixels(const Image& a, const Image& b, double step = 0.0) {
    int count = 0;
    for (int j = 0; j < a.height(); ++j) {
        for (int i = 0; i < a.width(); ++i) {
            const Color d = glm::abs(a.at(i, j) - b.at(i, j));
            if (d.r > step || d.g > step || d.b > step) ++count;
        }
    }
    return count;
}

}  // namespace raystep::testing
