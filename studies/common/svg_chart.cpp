#include "studies/common/svg_chart.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "studies/common/number_text.h"

namespace raystep {

namespace {

// Text as SVG character data: labels come from case files and function names.
std::string escaped(const std::string& text) {
    std::string out;
    for (const char c : text) {
        if (c == '&') {
            out += "&amp;";
        } else if (c == '<') {
            out += "&lt;";
        } else if (c == '>') {
            out += "&gt;";
        } else {
            out += c;
        }
    }
    return out;
}

// A decade's label: plain from 0.01 to 1000, 1e-5 beyond.
std::string decade_text(int decade, const std::string& unit) {
    if (decade >= -2 && decade <= 3) {
        char text[32];
        std::snprintf(text, sizeof text, "%g", std::pow(10.0, decade));
        return text + unit;
    }
    return "1e" + std::to_string(decade) + unit;
}

std::string marker_svg(double x, double y, const std::string& colour, ScatterPoint::Marker marker) {
    if (marker == ScatterPoint::Marker::diamond) {
        return "<path d=\"M" + svg_number(x) + "," + svg_number(y - 7) +
               " l7,7 l-7,7 l-7,-7 z\" fill=\"" + colour + "\"/>\n";
    }
    const bool filled = marker == ScatterPoint::Marker::filled;
    return "<circle cx=\"" + svg_number(x) + "\" cy=\"" + svg_number(y) + "\" r=\"5\" fill=\"" +
           (filled ? colour : "white") + "\" stroke=\"" + colour + "\" stroke-width=\"2\"/>\n";
}

}  // namespace

std::string svg_number(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f", x);
    return text;
}

double LogAxis::level(double value) const {
    if (!(value > 0.0)) return 0.0;
    const double clamped =
        std::clamp(std::log10(value), static_cast<double>(low), static_cast<double>(high));
    return (clamped - low + 0.5) / (high - low + 0.5);
}

std::string svg_scatter_panel(const ScatterPanel& panel, const std::vector<ScatterPoint>& points) {
    const auto x_of = [&](double x) { return panel.left + x / panel.x_max * panel.width; };
    const auto y_of = [&](double y) { return panel.top + panel.height * (1.0 - panel.y.level(y)); };
    std::string svg = "<rect x=\"" + svg_number(panel.left) + "\" y=\"" + svg_number(panel.top) +
                      "\" width=\"" + svg_number(panel.width) + "\" height=\"" +
                      svg_number(panel.height) + "\" fill=\"none\" stroke=\"#999\"/>\n";
    svg += svg_text(panel.left + panel.width / 2, panel.top - 6, "middle", panel.title);
    svg += svg_text(panel.left - 6, y_of(0.0) + 4, "end", "0");
    for (int decade = panel.y.low; decade <= panel.y.high; ++decade) {
        svg += svg_text(panel.left - 6, y_of(std::pow(10.0, decade)) + 4, "end",
                        decade_text(decade, panel.y.unit));
    }
    for (int tick = 0; tick <= 4; ++tick) {
        const double x = panel.x_max * tick / 4.0;
        svg += svg_text(x_of(x), panel.top + panel.height + 14, "middle", three_digits(x));
    }
    svg += svg_text(panel.left + panel.width / 2, panel.top + panel.height + 30, "middle",
                    panel.x_title);
    for (const ScatterPoint& p : points) {
        const double x = x_of(p.x);
        const double y = y_of(p.y);
        if (p.whisker_to >= 0.0) {
            svg += "<line x1=\"" + svg_number(x) + "\" y1=\"" + svg_number(y) + "\" x2=\"" +
                   svg_number(x) + "\" y2=\"" + svg_number(y_of(p.whisker_to)) + "\" stroke=\"" +
                   p.colour + "\"/>\n";
        }
        svg += marker_svg(x, y, p.colour, p.marker);
        if (p.marker == ScatterPoint::Marker::diamond) {
            svg += svg_text(x + 9, y - 6, "start", p.label, " font-weight=\"bold\"");
        }
    }
    return svg;
}

std::string svg_start(double width, double height) {
    return "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + svg_number(width) +
           "\" height=\"" + svg_number(height) +
           "\" font-family=\"sans-serif\" font-size=\"11\">\n"
           "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
}

std::string svg_text(double x, double y, const std::string& anchor, const std::string& text,
                     const std::string& extra) {
    return "<text x=\"" + svg_number(x) + "\" y=\"" + svg_number(y) + "\" text-anchor=\"" + anchor +
           "\"" + extra + ">" + escaped(text) + "</text>\n";
}

std::string svg_legend_entry(double x, double y, const std::string& colour,
                             ScatterPoint::Marker marker, const std::string& text) {
    return marker_svg(x, y - 4, colour, marker) + svg_text(x + 10, y, "start", text);
}

const std::string& series_colour(std::size_t index) {
    static const std::string palette[] = {"#c0392b", "#2471a3", "#27ae60", "#8e44ad",
                                          "#d35400", "#16a085", "#7f8c8d", "#b7950b"};
    return palette[index % std::size(palette)];
}

}  // namespace raystep
