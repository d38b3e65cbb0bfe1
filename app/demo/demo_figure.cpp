#include "app/demo/demo_figure.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "renderer/heat_map.h"

namespace raystep {

namespace {

// Text for the back row of a lecture hall. Screen-sizing rules put the farthest seat about six
// image heights from the screen for presentation graphics; from there a caption whose font size
// (its em) is a 26th of the image's height has capitals (0.73 em in DejaVu Sans) of 16 minutes of
// arc, the smallest that human-factors guides give for reading a label (NUREG-0700), and a title
// at a 20th has them at 21 minutes, those guides' preferred size. On a 640 x 480 image that is 18
// and 24 pixels; on 1920 x 1080, 42 and 54. app/demo/tests/demo_size_test.py measures the
// captions' height in a written figure.
constexpr double kCaptionTextPerHeight = 1.0 / 26;
constexpr double kTitleTextPerHeight = 1.0 / 20;
// A strip is its line of text and three tenths of it above and below.
constexpr double kStripPerText = 1.6;
// The margins and the colour bar are drawn to a 480-line layout and scaled with the image: in its
// pixels (FigureTextSizes::unit). The bar's strip is the bar, its ticks, and a line of numbers
// at the captions' size with a quarter of it above and below. The bar ends short of the right
// edge by half the widest number, "100,000".
constexpr double kMargin = 8;
constexpr double kScaleLabelWidth = 150;
constexpr double kBarTop = 6;
constexpr double kBarHeight = 14;
constexpr double kTickHeight = 4;
constexpr double kNumberWidth = 100;
constexpr double kNumberLinePerText = 1.5;

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

int pixels(double length, double unit) {
    return static_cast<int>(std::lround(length * unit));
}

// The bar of the scale across the strip at y0, a tick and a number at each power of ten.
void draw_scale(Image& image, const LogHeatScale& scale, int y0, const FigureTextSizes& sizes,
                const std::optional<LabelFont>& font) {
    const double u = sizes.unit;
    const int margin = pixels(kMargin, u);
    const int label_width = pixels(kScaleLabelWidth, u);
    const int bar_x0 = margin + label_width;
    const int bar_x1 = image.width() - pixels(kNumberWidth / 2 + kMargin, u);
    const int bar_y0 = y0 + pixels(kBarTop, u);
    const int bar_height = pixels(kBarHeight, u);
    const int number_line = static_cast<int>(std::lround(kNumberLinePerText * sizes.scale_text));
    if (bar_x1 <= bar_x0) return;  // an image too narrow for a bar: the caption says the range
    const double log_top = std::log10(scale.top);
    for (int i = bar_x0; i < bar_x1; ++i) {
        const double fraction = static_cast<double>(i - bar_x0) / (bar_x1 - 1 - bar_x0);
        fill(image, i, bar_y0, 1, bar_height, heat_colour(fraction));
    }
    for (int exponent = 0; exponent <= static_cast<int>(std::floor(log_top)); ++exponent) {
        const int x =
            bar_x0 + static_cast<int>(std::lround(exponent / log_top * (bar_x1 - 1 - bar_x0)));
        fill(image, x, bar_y0 + bar_height, std::max(1, pixels(1, u)), pixels(kTickHeight, u),
             kCaptionTextColour);
        if (font) {
            draw_text(image, *font, thousands(static_cast<std::uint64_t>(std::pow(10.0, exponent))),
                      x, bar_y0 + bar_height + pixels(kTickHeight, u) + number_line / 2,
                      sizes.scale_text, pixels(kNumberWidth, u), TextAlign::centre,
                      kCaptionTextColour);
        }
    }
    if (font) {
        draw_text(image, *font, scale.quantity, margin, y0 + sizes.scale_strip / 2,
                  sizes.scale_text, label_width - margin, TextAlign::left, kCaptionTextColour);
    }
}

}  // namespace

FigureTextSizes figure_text_sizes(int height) {
    FigureTextSizes sizes{};
    sizes.unit = height / 480.0;
    sizes.caption_text = static_cast<int>(std::lround(height * kCaptionTextPerHeight));
    sizes.title_text = static_cast<int>(std::lround(height * kTitleTextPerHeight));
    sizes.caption_strip = static_cast<int>(std::lround(sizes.caption_text * kStripPerText));
    sizes.title_strip = static_cast<int>(std::lround(sizes.title_text * kStripPerText));
    sizes.scale_text = sizes.caption_text;
    sizes.scale_strip = pixels(kBarTop + kBarHeight + kTickHeight, sizes.unit) +
                        static_cast<int>(std::lround(kNumberLinePerText * sizes.scale_text));
    return sizes;
}

PanelSize panel_size(const DemoSize& size, int panels, bool scale) {
    if (panels < 1 || panels > 8) {
        throw std::invalid_argument("a demo figure holds 1 to 8 panels, not " +
                                    std::to_string(panels));
    }
    const int rows = rows_for(panels);
    const FigureTextSizes sizes = figure_text_sizes(size.height);
    const int free_height = size.height - sizes.title_strip - (scale ? sizes.scale_strip : 0);
    const PanelSize panel{size.width / columns_for(panels),
                          free_height / rows - sizes.caption_strip};
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
    const FigureTextSizes sizes = figure_text_sizes(size.height);
    const int margin = pixels(kMargin, sizes.unit);
    Image image(size.width, size.height);
    fill(image, 0, 0, size.width, size.height, kStripColour);

    // The title across the top
    if (font) {
        draw_text(image, *font, figure.title, size.width / 2, sizes.title_strip / 2,
                  sizes.title_text, size.width - 2 * margin, TextAlign::centre);
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
        const int y0 = sizes.title_strip + (k / columns) * (panel.height + sizes.caption_strip);
        paste(image, p.image, x0, y0);
        if (font) {
            draw_text(image, *font, p.caption, x0 + panel.width / 2,
                      y0 + panel.height + sizes.caption_strip / 2, sizes.caption_text,
                      panel.width - 2 * margin, TextAlign::centre, kCaptionTextColour);
        }
    }

    // The colour scale along the bottom
    if (figure.scale) {
        draw_scale(image, *figure.scale, size.height - sizes.scale_strip, sizes, font);
    }
    return image;
}

Color log_heat_colour(double value, const LogHeatScale& scale) {
    // Rejects NaN as black too: !(value > 1).
    if (!(value > 1.0)) return heat_colour(0.0);
    return heat_colour(std::log(value) / std::log(scale.top));
}

}  // namespace raystep
