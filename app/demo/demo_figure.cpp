#include "app/demo/demo_figure.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "app/render/heat_map.h"

namespace raystep {

namespace {

// Strip heights and text sizes in pixels, chosen for a 640 x 480 image on a lecture-hall
// projector: the title readable from the back, captions from the middle. Smaller images (the
// tests') keep the strips and get smaller panels.
constexpr int kTitleHeight = 32;
constexpr int kTitleText = 20;
constexpr int kCaptionHeight = 24;
constexpr int kCaptionText = 15;
constexpr int kScaleHeight = 44;
constexpr int kScaleText = 13;
constexpr int kMargin = 8;

const Color kStripColour(0.1, 0.1, 0.12);
const Color kCaptionTextColour(0.9, 0.9, 0.9);

// One panel fills the width, two to four make rows of two, five to eight two rows of three or
// four: a series side by side, a second series under it (regular against jittered samples).
int columns_for(int panels) {
    if (panels == 1) return 1;
    if (panels <= 4) return 2;
    return (panels + 1) / 2;
}
int rows_for(int panels) {
    return (panels + columns_for(panels) - 1) / columns_for(panels);
}

void fill(Image& image, int x0, int y0, int width, int height, const Color& colour) {
    for (int j = std::max(0, y0); j < std::min(image.height(), y0 + height); ++j) {
        for (int i = std::max(0, x0); i < std::min(image.width(), x0 + width); ++i) {
            image.set(i, j, colour);
        }
    }
}

void paste(Image& image, const Image& panel, int x0, int y0) {
    for (int j = 0; j < panel.height(); ++j) {
        for (int i = 0; i < panel.width(); ++i) {
            image.set(x0 + i, y0 + j, panel.at(i, j));
        }
    }
}

// The bar of the scale across the strip at y0, a tick and a number at each power of ten.
void draw_scale(Image& image, const LogHeatScale& scale, int y0,
                const std::optional<LabelFont>& font) {
    const int label_width = 150;
    const int bar_x0 = kMargin + label_width;
    const int bar_x1 = image.width() - 5 * kMargin;  // room for half the last number
    const int bar_y0 = y0 + 6;
    const int bar_height = 14;
    if (bar_x1 <= bar_x0) return;  // an image too narrow for a bar: the caption says the range
    const double log_top = std::log10(scale.top);
    for (int i = bar_x0; i < bar_x1; ++i) {
        const double fraction = static_cast<double>(i - bar_x0) / (bar_x1 - 1 - bar_x0);
        fill(image, i, bar_y0, 1, bar_height, heat_colour(fraction));
    }
    for (int exponent = 0; exponent <= static_cast<int>(std::floor(log_top)); ++exponent) {
        const int x =
            bar_x0 + static_cast<int>(std::lround(exponent / log_top * (bar_x1 - 1 - bar_x0)));
        fill(image, x, bar_y0 + bar_height, 1, 4, kCaptionTextColour);
        if (font) {
            draw_text(image, *font, thousands(static_cast<std::uint64_t>(std::pow(10.0, exponent))),
                      x, bar_y0 + bar_height + 12, kScaleText, 60, TextAlign::centre,
                      kCaptionTextColour);
        }
    }
    if (font) {
        draw_text(image, *font, scale.quantity, kMargin, y0 + kScaleHeight / 2, kScaleText,
                  label_width - kMargin, TextAlign::left, kCaptionTextColour);
    }
}

}  // namespace

PanelSize panel_size(const DemoSize& size, int panels, bool scale) {
    if (panels < 1 || panels > 8) {
        throw std::invalid_argument("a demo figure holds 1 to 8 panels, not " +
                                    std::to_string(panels));
    }
    const int rows = rows_for(panels);
    const int free_height = size.height - kTitleHeight - (scale ? kScaleHeight : 0);
    const PanelSize panel{size.width / columns_for(panels), free_height / rows - kCaptionHeight};
    if (panel.width < 1 || panel.height < 1) {
        throw std::invalid_argument("a " + std::to_string(size.width) + " x " +
                                    std::to_string(size.height) + " image is too small for " +
                                    std::to_string(panels) + " panels and their labels");
    }
    return panel;
}

Image draw_figure(const DemoFigure& figure, const DemoSize& size,
                  const std::optional<LabelFont>& font) {
    const int count = static_cast<int>(figure.panels.size());
    const PanelSize panel = panel_size(size, count, figure.scale.has_value());
    Image image(size.width, size.height);
    fill(image, 0, 0, size.width, size.height, kStripColour);

    // The title across the top
    if (font) {
        draw_text(image, *font, figure.title, size.width / 2, kTitleHeight / 2, kTitleText,
                  size.width - 2 * kMargin, TextAlign::centre);
    }

    // Each panel with its caption under it, row by row; a short last row is centred
    const int columns = columns_for(count);
    const int last_row = (count - 1) / columns;
    const int in_last_row = count - last_row * columns;
    for (int k = 0; k < count; ++k) {
        const DemoPanel& p = figure.panels[static_cast<std::size_t>(k)];
        if (p.image.width() != panel.width || p.image.height() != panel.height) {
            throw std::logic_error("demo panel " + std::to_string(k) + " is " +
                                   std::to_string(p.image.width()) + " x " +
                                   std::to_string(p.image.height()) + ", not the panel size");
        }
        const int row_start =
            k / columns == last_row ? (size.width - in_last_row * panel.width) / 2 : 0;
        const int x0 = row_start + (k % columns) * panel.width;
        const int y0 = kTitleHeight + (k / columns) * (panel.height + kCaptionHeight);
        paste(image, p.image, x0, y0);
        if (font) {
            draw_text(image, *font, p.caption, x0 + panel.width / 2,
                      y0 + panel.height + kCaptionHeight / 2, kCaptionText,
                      panel.width - 2 * kMargin, TextAlign::centre, kCaptionTextColour);
        }
    }

    // The colour scale along the bottom
    if (figure.scale) {
        draw_scale(image, *figure.scale, size.height - kScaleHeight, font);
    }
    return image;
}

Color log_heat_colour(double value, const LogHeatScale& scale) {
    // Rejects NaN as black too: !(value > 1).
    if (!(value > 1.0)) return heat_colour(0.0);
    return heat_colour(std::log(value) / std::log(scale.top));
}

}  // namespace raystep
