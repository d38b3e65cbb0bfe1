#include "studies/sampling/noise_chart.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "studies/common/number_text.h"
#include "studies/common/svg_chart.h"

namespace raystep {

namespace {

// Sizes in SVG units: three panels side by side fit a page's width.
constexpr double kPlotWidth = 230.0;
constexpr double kPlotHeight = 200.0;
constexpr double kLeft = 60.0;
constexpr double kGap = 75.0;
constexpr double kTop = 56.0;
constexpr double kLegendLine = 16.0;

// Whole decades from below the least to above the greatest value.
struct DecadeRange {
    int low = 0;
    int high = 1;
    double fraction(double value) const {
        return (std::log10(value) - low) / static_cast<double>(high - low);
    }
};

DecadeRange decades_around(double least, double greatest) {
    DecadeRange range{static_cast<int>(std::floor(std::log10(least))),
                      static_cast<int>(std::ceil(std::log10(greatest)))};
    if (range.high <= range.low) range.high = range.low + 1;
    return range;
}

std::string decade_label(int decade) {
    if (decade >= -3 && decade <= 3) {
        char text[32];
        std::snprintf(text, sizeof text, "%g", std::pow(10.0, decade));
        return text;
    }
    return "1e" + std::to_string(decade);
}

const std::string& kind_colour(SamplingKind kind) {
    return series_colour(static_cast<std::size_t>(kind));
}

std::string line(double x1, double y1, double x2, double y2, const std::string& stroke) {
    return "<line x1=\"" + svg_number(x1) + "\" y1=\"" + svg_number(y1) + "\" x2=\"" +
           svg_number(x2) + "\" y2=\"" + svg_number(y2) + "\" stroke=\"" + stroke + "\"/>\n";
}

std::string scene_panel(const NoiseScene& scene, double left) {
    // The axes' ranges from every point of the scene
    double least_x = std::numeric_limits<double>::infinity();
    double greatest_x = 0.0;
    double least_y = std::numeric_limits<double>::infinity();
    double greatest_y = 0.0;
    for (const NoiseCurve& curve : scene.curves) {
        for (const NoisePoint& p : curve.points) {
            least_x = std::min(least_x, p.seconds);
            greatest_x = std::max(greatest_x, p.seconds);
            least_y = std::min(least_y, p.rmse);
            greatest_y = std::max(greatest_y, p.rmse + p.rmse_spread);
        }
    }
    const DecadeRange x_range = decades_around(least_x, greatest_x);
    const DecadeRange y_range = decades_around(least_y, greatest_y);
    const auto x_of = [&](double x) { return left + kPlotWidth * x_range.fraction(x); };
    // A whisker reaching zero or below stops at the frame's bottom
    const auto y_of = [&](double y) {
        const double fraction = y > 0.0 ? std::clamp(y_range.fraction(y), 0.0, 1.0) : 0.0;
        return kTop + kPlotHeight * (1.0 - fraction);
    };

    // Frame, decade grid and labels
    std::string svg = "<rect x=\"" + svg_number(left) + "\" y=\"" + svg_number(kTop) +
                      "\" width=\"" + svg_number(kPlotWidth) + "\" height=\"" +
                      svg_number(kPlotHeight) + "\" fill=\"none\" stroke=\"#999\"/>\n";
    svg += svg_text(left + kPlotWidth / 2, kTop - 8, "middle", scene.name + ": " + scene.sampled,
                    " font-weight=\"bold\"");
    for (int d = x_range.low; d <= x_range.high; ++d) {
        const double x = x_of(std::pow(10.0, d));
        svg += line(x, kTop, x, kTop + kPlotHeight, "#e5e5e5");
        svg += svg_text(x, kTop + kPlotHeight + 14, "middle", decade_label(d));
    }
    for (int d = y_range.low; d <= y_range.high; ++d) {
        const double y = y_of(std::pow(10.0, d));
        svg += line(left, y, left + kPlotWidth, y, "#e5e5e5");
        svg += svg_text(left - 6, y + 4, "end", decade_label(d));
    }
    svg += svg_text(left + kPlotWidth / 2, kTop + kPlotHeight + 30, "middle",
                    "processor seconds per render (log)");
    svg += svg_text(left - 40, kTop + kPlotHeight / 2, "middle", "RMSE (log)",
                    " transform=\"rotate(-90 " + svg_number(left - 40) + " " +
                        svg_number(kTop + kPlotHeight / 2) + ")\"");

    // Each curve: its line, a whisker of one spread either side, a dot per count
    double legend_y = kTop + kPlotHeight + 52;
    for (const NoiseCurve& curve : scene.curves) {
        const std::string& colour = kind_colour(curve.kind);
        std::string points;
        for (const NoisePoint& p : curve.points) {
            const double x = x_of(p.seconds);
            points += svg_number(x) + "," + svg_number(y_of(p.rmse)) + " ";
            if (p.rmse_spread > 0.0) {
                svg +=
                    line(x, y_of(p.rmse - p.rmse_spread), x, y_of(p.rmse + p.rmse_spread), colour);
            }
            svg += "<circle cx=\"" + svg_number(x) + "\" cy=\"" + svg_number(y_of(p.rmse)) +
                   "\" r=\"3\" fill=\"" + colour + "\"/>\n";
        }
        svg += "<polyline points=\"" + points + "\" fill=\"none\" stroke=\"" + colour + "\"/>\n";
        svg += svg_legend_entry(left + 8, legend_y, colour, ScatterPoint::Marker::filled,
                                curve.method + ": RMSE ~ N^" + fixed(noise_slope(curve), 2));
        legend_y += kLegendLine;
    }
    return svg;
}

}  // namespace

std::string noise_chart_svg(const std::vector<NoiseScene>& scenes) {
    std::size_t most_curves = 0;
    for (const NoiseScene& scene : scenes)
        most_curves = std::max(most_curves, scene.curves.size());
    const double width = kLeft + static_cast<double>(scenes.size()) * (kPlotWidth + kGap);
    const double height = kTop + kPlotHeight + 52 + static_cast<double>(most_curves) * kLegendLine;
    std::string svg = svg_start(width, height);
    svg += svg_text(width / 2, 20, "middle",
                    "Noise against time: RMSE against a converged render, a dot per sample count",
                    " font-size=\"14\"");
    for (std::size_t k = 0; k < scenes.size(); ++k) {
        svg += scene_panel(scenes[k], kLeft + static_cast<double>(k) * (kPlotWidth + kGap));
    }
    return svg + "</svg>\n";
}

}  // namespace raystep
