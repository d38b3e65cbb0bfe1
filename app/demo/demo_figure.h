#pragma once

#include <optional>
#include <string>
#include <vector>

#include "app/demo/label_text.h"
#include "base/image/image.h"

namespace raystep {

// A demo's result before it becomes one image: a title, one to eight panels each with a caption,
// and for heat maps the colour scale. The demos render their panels at panel_size; draw_figure
// lays everything out and writes the labels.

/// The whole image a demo writes, in pixels.
struct DemoSize {
    int width = 640;
    int height = 480;
};

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
/// colour bar take the rest. Throws std::invalid_argument for no panels, more than eight, or an
/// image too small to hold them.
PanelSize panel_size(const DemoSize& size, int panels, bool scale);

/// The figure as one image of `size`. Without a font the strips for the title, captions and
/// numbers stay blank.
Image draw_figure(const DemoFigure& figure, const DemoSize& size,
                  const std::optional<LabelFont>& font);

/// The colour of `value` on the scale: black at 1 or less, white at `top` or more.
Color log_heat_colour(double value, const LogHeatScale& scale);

}  // namespace raystep
