#include "studies/epsilon/epsilon_study.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "studies/common/markdown_table.h"
#include "studies/common/number_text.h"

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

nlohmann::json epsilon_json(const std::vector<EpsilonSceneResult>& results) {
    const auto errors_json = [](const OffsetErrors& errors) {
        return nlohmann::json{{"acne", errors.acne}, {"leaks", errors.leaks}};
    };
    nlohmann::json scenes = nlohmann::json::array();
    for (const EpsilonSceneResult& r : results) {
        nlohmann::json along_ray = nlohmann::json::array();
        nlohmann::json along_normal = nlohmann::json::array();
        for (std::size_t k = 0; k < r.epsilons.size(); ++k) {
            along_ray.push_back(errors_json(r.along_ray[k]));
            along_normal.push_back(errors_json(r.along_normal[k]));
        }
        scenes.push_back({{"scene", scene_name(r.scene)},
                          {"lit", r.lit},
                          {"shadowed", r.shadowed},
                          {"undecided", r.undecided},
                          {"other_hit", r.other_hit},
                          {"epsilons", r.epsilons},
                          {"along_ray", along_ray},
                          {"along_normal", along_normal},
                          {"error_bound", errors_json(r.error_bound)},
                          {"stopped", r.stopped}});
    }
    return {{"study", "epsilon"}, {"scenes", scenes}};
}

}  // namespace raystep
