#pragma once

#include <optional>
#include <string>
#include <vector>

#include "app/demo/demo_size.h"
#include "app/demo/label_text.h"
#include "base/image/image.h"

namespace raystep {

// A demo's result before it becomes one image: a title, one to eight panels each with a caption,
// and for heat maps the colour scale. The demos render their panels at panel_size; draw_figure
// lays everything out and writes the labels, their strips and text in proportion to the image's
// height, so that a figure for a 1080-line projector has captions as legible as a 480-line one's.

/// One image of a figure and the line under it that says what it shows.
struct DemoPanel {
    std::string caption;
    Image image;
};

/// A logarithmic colour scale from 1 to `top`: a value v is heat_colour(log v / log top), so
/// that costs of 10 and 10,000 both show, and the bar under the panels has a number at each power
/// of ten.
struct LogHeatScale {
    double top;
    std::string quantity;  ///< what the colours measure, written beside the bar
};

struct DemoFigure {
    std::string title;
    std::vector<DemoPanel> panels;  ///< 1 to 8, all of panel_size
    std::optional<LogHeatScale> scale;
};

struct PanelSize {
    int width;
    int height;
};

/// The size of each panel of a figure of `panels` panels on an image of `size`: one panel fills
/// the width, two stand side by side, three or four make two rows of two, five or six two rows
/// of three, seven or eight two rows of four; the title, the captions and, when `scale`, the
/// colour bar take the rest (figure_text_sizes). Throws std::invalid_argument for no panels, more
/// than eight, or an image too small to hold them.
PanelSize panel_size(const DemoSize& size, int panels, bool scale);

/// The heights in pixels of a figure's strips and of the text in them.
struct FigureTextSizes {
    int title_strip;
    int title_text;
    int caption_strip;
    int caption_text;  ///< the font's size (its em), as draw_text takes it
    int scale_strip;
    int scale_text;
    double unit;  ///< one pixel of the 480-line layout the rest is drawn to: height / 480
};
/// The text sizes of a figure `height` pixels high, each in proportion to it: captions at a 26th of
/// the height, the title at a 20th, for the back row of a lecture hall (demo_figure.cpp).
FigureTextSizes figure_text_sizes(int height);

/// The figure as one image of `size`. Without a font the strips for the title, captions and
/// numbers stay blank.
Image draw_figure(const DemoFigure& figure, const DemoSize& size,
                  const std::optional<LabelFont>& font);

/// The colour of `value` on the scale: black at 1 or less, white at `top` or more.
Color log_heat_colour(double value, const LogHeatScale& scale);

}  // namespace raystep
