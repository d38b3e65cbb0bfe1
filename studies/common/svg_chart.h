#pragma once

#include <string>
#include <vector>

namespace raystep {

// The pieces of the bench's SVG charts: the document, text and numbers (the epsilon study's line
// chart, the speed-against-error scatter charts), and a scatter panel with a linear x axis from 0
// and a logarithmic y axis with 0 on its bottom line, points in three markers.

/// A y axis from 10^low to 10^high, with 0 on the bottom line: half a decade below 10^low is
/// left free so that zero stands apart from the smallest nonzero value.
struct LogAxis {
    int low = 0;
    int high = 1;
    std::string unit;  ///< after each decade's number: "%", or empty
    /// 0 at the bottom line, 1 at 10^high; values beyond the axis are drawn at its ends.
    double level(double value) const;
};

struct ScatterPoint {
    enum class Marker { filled, open, diamond };
    double x = 0.0;
    double y = 0.0;
    double whisker_to = -1.0;  ///< a vertical line from y to this value; none when negative
    std::string colour;
    Marker marker = Marker::filled;
    std::string label;  ///< drawn beside diamonds only: the others are named by the legend
};

struct ScatterPanel {
    double left = 0.0;  ///< the plot area's corner and size, in SVG units
    double top = 0.0;
    double width = 300.0;
    double height = 220.0;
    std::string title;    ///< above the plot
    std::string x_title;  ///< under the x axis
    double x_max = 1.0;   ///< the right end of the x axis; it starts at 0
    LogAxis y;
};

/// The panel's frame, axes, labels and points.
std::string svg_scatter_panel(const ScatterPanel& panel, const std::vector<ScatterPoint>& points);

/// A coordinate or length in SVG units, to a tenth.
std::string svg_number(double x);

/// `<svg ...>` with a white background; end it with "</svg>\n".
std::string svg_start(double width, double height);

/// A text element; the text is escaped. `extra` is more attributes, starting with a space.
std::string svg_text(double x, double y, const std::string& anchor, const std::string& text,
                     const std::string& extra = "");

/// A legend entry: the marker, then the text; returns its SVG.
std::string svg_legend_entry(double x, double y, const std::string& colour,
                             ScatterPoint::Marker marker, const std::string& text);

/// Colours for up to eight series, in order; they repeat after that.
const std::string& series_colour(std::size_t index);

}  // namespace raystep
