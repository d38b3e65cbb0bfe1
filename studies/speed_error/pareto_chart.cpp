#include "studies/speed_error/pareto_chart.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "studies/common/number_text.h"
#include "studies/common/svg_chart.h"

namespace raystep {

namespace {

constexpr double kWidth = 820;
constexpr double kParetoTop = 60;
constexpr double kParetoPlotWidth = 300;
constexpr double kParetoPlotHeight = 220;
constexpr double kLefts[2] = {70, 470};
constexpr double kLegendColumn = 150;

bool in_study(const ParetoPoint& p) {
    return p.precision == "double" || p.precision == "float";
}

}  // namespace

std::string pareto_chart_svg(const ParetoFamily& family, const std::string& footnote) {
    // A colour per method label, in order of first appearance
    std::map<std::string, std::string> colour_of;
    std::vector<std::string> labels;
    for (const ParetoPoint& p : family.points) {
        if (!in_study(p) || colour_of.count(p.label)) continue;
        colour_of[p.label] = series_colour(labels.size());
        labels.push_back(p.label);
    }
    double fastest = 0.0;
    double largest_ulps = 1.0;
    for (const ParetoPoint& p : family.points) {
        fastest = std::max(fastest, p.mrays_per_second);
        largest_ulps = std::max(largest_ulps, p.t_ulps_p99);
    }

    ScatterPanel wrong;
    wrong.left = kLefts[0];
    wrong.top = kParetoTop;
    wrong.width = kParetoPlotWidth;
    wrong.height = kParetoPlotHeight;
    wrong.title = "wrong answers: false hits + false misses, % of cases";
    wrong.x_title = "Mrays/s, one thread (ray-primitive tests)";
    wrong.x_max = fastest > 0.0 ? fastest * 1.1 : 1.0;
    wrong.y = {-2, 2, "%"};
    ScatterPanel t_error = wrong;
    t_error.left = kLefts[1];
    t_error.title = "t error in double ulps: median, whisker to the 99th percentile";
    t_error.y = {0, std::max(1, static_cast<int>(std::ceil(std::log10(largest_ulps)))), ""};

    std::vector<ScatterPoint> wrong_points;
    std::vector<ScatterPoint> t_points;
    for (const ParetoPoint& p : family.points) {
        ScatterPoint point;
        point.x = p.mrays_per_second;
        point.colour = in_study(p) ? colour_of[p.label] : "black";
        point.marker = !in_study(p)              ? ScatterPoint::Marker::diamond
                       : p.precision == "double" ? ScatterPoint::Marker::filled
                                                 : ScatterPoint::Marker::open;
        point.label = p.label;
        point.y = 100.0 * p.wrong_share();
        wrong_points.push_back(point);
        point.y = p.t_ulps_median;
        point.whisker_to = p.t_ulps_p99;
        t_points.push_back(point);
    }

    // The legend wraps into rows under the panels; the height follows.
    const int per_row = static_cast<int>((kWidth - kLefts[0]) / kLegendColumn);
    const int rows = (static_cast<int>(labels.size()) + per_row - 1) / per_row;
    const double legend_top = kParetoTop + kParetoPlotHeight + 58;
    const double height = legend_top + 18.0 * rows + 50;

    std::string svg = svg_start(kWidth, height);
    svg += svg_text(kWidth / 2, 20, "middle",
                    family.name + ": " + grouped(family.cases) + " decided cases",
                    " font-weight=\"bold\" font-size=\"13\"");
    svg += svg_text(kWidth / 2, 38, "middle", family.description);
    svg += svg_scatter_panel(wrong, wrong_points);
    svg += svg_scatter_panel(t_error, t_points);
    for (std::size_t k = 0; k < labels.size(); ++k) {
        const double x = kLefts[0] + kLegendColumn * static_cast<double>(k % per_row);
        const double y = legend_top + 18.0 * static_cast<double>(k / per_row);
        svg +=
            svg_legend_entry(x, y, colour_of[labels[k]], ScatterPoint::Marker::filled, labels[k]);
    }
    const double y = legend_top + 18.0 * rows + 8;
    svg += svg_legend_entry(kLefts[0], y, "#555", ScatterPoint::Marker::filled, "double");
    svg += svg_legend_entry(kLefts[0] + 80, y, "#555", ScatterPoint::Marker::open,
                            "float: the ray and shapes rounded to float; its ulp is 2^29 "
                            "double ulps");
    svg += svg_text(kLefts[0], y + 20, "start", footnote, " fill=\"#555\"");
    svg += "</svg>\n";
    return svg;
}

}  // namespace raystep
