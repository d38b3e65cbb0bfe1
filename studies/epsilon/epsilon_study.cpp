#include "studies/epsilon/epsilon_study.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "studies/common/markdown_table.h"
#include "studies/common/number_text.h"
#include "studies/common/svg_chart.h"

namespace raystep {

namespace {

// 1e-14 for a power of ten, else the shortest %g.
std::string epsilon_text(double epsilon) {
    const double exponent = std::round(std::log10(epsilon));
    if (std::pow(10.0, exponent) == epsilon) {
        return "1e" + std::to_string(static_cast<int>(exponent));
    }
    char text[32];
    std::snprintf(text, sizeof text, "%g", epsilon);
    return text;
}

std::string scene_name(const std::string& path) {
    return std::filesystem::path(path).stem().string();
}

// One panel of the chart: a line per series of pixel counts over the epsilons.
struct Series {
    const char* label;
    const char* colour;
    const char* dash;  ///< SVG stroke-dasharray, empty for a solid line
    std::vector<double> counts;
};

}  // namespace

std::vector<double> study_epsilons() {
    std::vector<double> epsilons;
    for (int exponent = -14; exponent <= -1; ++exponent)
        epsilons.push_back(std::pow(10.0, exponent));
    return epsilons;
}

std::string epsilon_table(const EpsilonSceneResult& result) {
    MarkdownTable table({"epsilon", "along-ray acne", "along-ray leaks", "along-normal acne",
                         "along-normal leaks"});
    for (std::size_t k = 0; k < result.epsilons.size(); ++k) {
        table.add_row({epsilon_text(result.epsilons[k]), grouped(result.along_ray[k].acne),
                       grouped(result.along_ray[k].leaks), grouped(result.along_normal[k].acne),
                       grouped(result.along_normal[k].leaks)});
    }
    table.add_row({"error-bound", grouped(result.error_bound.acne),
                   grouped(result.error_bound.leaks), "(no epsilon)"});
    return table.text();
}

std::string epsilon_notes(const EpsilonSceneResult& result) {
    if (!result.stopped.empty()) return "stopped: " + result.stopped;
    return grouped(result.lit) + " pixels exactly lit, " + grouped(result.shadowed) +
           " exactly in shadow; left out: " + grouped(result.undecided) +
           " within 1e-12 of an edge, " + grouped(result.other_hit) +
           " where the eye ray's primitive differs from the exact one";
}

std::string epsilon_chart_svg(const std::vector<EpsilonSceneResult>& results) {
    constexpr double kPanelWidth = 330;
    constexpr double kPanelHeight = 230;
    constexpr double kLeft = 60;
    constexpr double kTop = 30;
    constexpr double kPlotWidth = 250;
    constexpr double kPlotHeight = 150;
    constexpr int kDecades = 5;  // up to 100,000 pixels
    const double width =
        kPanelWidth * static_cast<double>(std::max<std::size_t>(results.size(), 1));
    const double height = kPanelHeight + 40;

    std::string svg = svg_start(width, height);
    for (std::size_t panel = 0; panel < results.size(); ++panel) {
        const EpsilonSceneResult& r = results[panel];
        if (r.epsilons.empty()) continue;
        const double x0 = kPanelWidth * static_cast<double>(panel) + kLeft;
        const double y0 = kTop;
        const double low = std::log10(r.epsilons.front());
        const double high = std::log10(r.epsilons.back());
        const auto x_of = [&](double epsilon) {
            return x0 + (std::log10(epsilon) - low) / (high - low) * kPlotWidth;
        };
        // Pixel counts on a log scale from 1 to 10^kDecades, with 0 on the bottom line.
        const auto y_of = [&](double count) {
            const double level = count < 1.0 ? 0.0 : (std::log10(count) + 0.5) / (kDecades + 0.5);
            return y0 + kPlotHeight * (1.0 - level);
        };
        svg += svg_text(x0 + kPlotWidth / 2, y0 - 12, "middle", scene_name(r.scene),
                        " font-weight=\"bold\"");
        svg += "<rect x=\"" + svg_number(x0) + "\" y=\"" + svg_number(y0) + "\" width=\"" +
               svg_number(kPlotWidth) + "\" height=\"" + svg_number(kPlotHeight) +
               "\" fill=\"none\" stroke=\"#999\"/>\n";
        for (int decade = -1; decade <= kDecades; ++decade) {
            const double count = decade < 0 ? 0.0 : std::pow(10.0, decade);
            svg +=
                svg_text(x0 - 6, y_of(count) + 4, "end", grouped(static_cast<std::size_t>(count)));
        }
        for (std::size_t k = 0; k < r.epsilons.size(); k += 3) {
            svg += svg_text(x_of(r.epsilons[k]), y0 + kPlotHeight + 14, "middle",
                            epsilon_text(r.epsilons[k]));
        }
        svg += svg_text(x0 + kPlotWidth / 2, y0 + kPlotHeight + 30, "middle", "epsilon");

        std::vector<Series> series = {
            {"along-ray acne", "#c0392b", "", {}},
            {"along-ray leaks", "#c0392b", "5,3", {}},
            {"along-normal acne", "#2471a3", "", {}},
            {"along-normal leaks", "#2471a3", "5,3", {}},
        };
        for (std::size_t k = 0; k < r.epsilons.size(); ++k) {
            series[0].counts.push_back(static_cast<double>(r.along_ray[k].acne));
            series[1].counts.push_back(static_cast<double>(r.along_ray[k].leaks));
            series[2].counts.push_back(static_cast<double>(r.along_normal[k].acne));
            series[3].counts.push_back(static_cast<double>(r.along_normal[k].leaks));
        }
        for (const Series& s : series) {
            std::string points;
            for (std::size_t k = 0; k < r.epsilons.size(); ++k) {
                points +=
                    svg_number(x_of(r.epsilons[k])) + "," + svg_number(y_of(s.counts[k])) + " ";
            }
            svg += "<polyline fill=\"none\" stroke=\"" + std::string(s.colour) +
                   "\" stroke-width=\"2\"" +
                   (*s.dash ? " stroke-dasharray=\"" + std::string(s.dash) + "\"" : "") +
                   " points=\"" + points + "\"/>\n";
        }
        svg += "<text x=\"" + svg_number(x0) + "\" y=\"" + svg_number(y0 + kPlotHeight + 46) +
               "\">error-bound: " + grouped(r.error_bound.acne) + " acne, " +
               grouped(r.error_bound.leaks) + " leaks</text>\n";
    }
    // The legend, once, under the panels: colour for the rule, dashes for the kind of error.
    const struct {
        const char* label;
        const char* colour;
        const char* dash;
        double width;
    } legend[] = {{"along-ray", "#c0392b", "", 140},
                  {"along-normal", "#2471a3", "", 160},
                  {"acne: pixels wrongly in shadow", "#333", "", 250},
                  {"leaks: pixels wrongly lit", "#333", "5,3", 0}};
    double x = kLeft;
    for (const auto& entry : legend) {
        svg += "<line x1=\"" + svg_number(x) + "\" y1=\"" + svg_number(height - 14) + "\" x2=\"" +
               svg_number(x + 24) + "\" y2=\"" + svg_number(height - 14) + "\" stroke=\"" +
               entry.colour + "\" stroke-width=\"2\"" +
               (*entry.dash ? " stroke-dasharray=\"" + std::string(entry.dash) + "\"" : "") +
               "/>\n";
        svg += "<text x=\"" + svg_number(x + 30) + "\" y=\"" + svg_number(height - 10) + "\">" +
               entry.label + "</text>\n";
        x += entry.width;
    }
    svg += "</svg>\n";
    return svg;
}

}  // namespace raystep
