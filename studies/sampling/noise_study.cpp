#include "studies/sampling/noise_study.h"

#include <algorithm>

#include <nlohmann/json.hpp>

#include "studies/common/markdown_table.h"
#include "studies/common/number_text.h"
#include "studies/sampling/noise_statistics.h"

namespace raystep {

namespace {

const NoiseCurve* curve_of_kind(const NoiseScene& scene, SamplingKind kind) {
    const auto found = std::find_if(scene.curves.begin(), scene.curves.end(),
                                    [&](const NoiseCurve& c) { return c.kind == kind; });
    return found == scene.curves.end() ? nullptr : &*found;
}

bool falls_at_every_step(const NoiseCurve& curve) {
    for (std::size_t k = 1; k < curve.points.size(); ++k) {
        // !(a < b) also fails a NaN
        if (!(curve.points[k].rmse < curve.points[k - 1].rmse)) return false;
    }
    return curve.points.size() >= 2;
}

}  // namespace

double noise_slope(const NoiseCurve& curve) {
    std::vector<double> samples;
    std::vector<double> rmse;
    for (const NoisePoint& point : curve.points) {
        samples.push_back(point.samples);
        rmse.push_back(point.rmse);
    }
    return log_log_slope(samples, rmse);
}

std::string noise_table(const NoiseScene& scene) {
    MarkdownTable table({"method", "samples", "runs", "CPU ms per render", "RMSE", "spread"});
    for (const NoiseCurve& curve : scene.curves) {
        for (const NoisePoint& point : curve.points) {
            table.add_row({curve.method, std::to_string(point.samples), std::to_string(point.runs),
                           three_digits(1e3 * point.seconds), three_digits(point.rmse),
                           point.runs > 1 ? three_digits(point.rmse_spread) : "-"});
        }
    }
    std::string text = table.text() + "\nslope of log RMSE against log samples:";
    for (const NoiseCurve& curve : scene.curves) {
        text += " " + curve.method + " " + fixed(noise_slope(curve), 2) +
                (&curve == &scene.curves.back() ? "" : ",");
    }
    return text + "\n";
}

std::vector<NoiseFinding> noise_findings(const std::vector<NoiseScene>& scenes) {
    std::vector<NoiseFinding> findings;
    for (const NoiseScene& scene : scenes) {
        const NoiseCurve* random = curve_of_kind(scene, SamplingKind::random);
        const NoiseCurve* stratified = curve_of_kind(scene, SamplingKind::stratified);
        if (!random || random->points.empty()) continue;
        findings.push_back(
            {"random " + scene.sampled + ": the RMSE falls at every larger count on " + scene.name,
             falls_at_every_step(*random)});
        if (!stratified || stratified->points.empty()) continue;
        const NoisePoint& strata = stratified->points.back();
        const NoisePoint& independent = random->points.back();
        findings.push_back(
            {stratified->method + " below random at " + std::to_string(strata.samples) + " " +
                 scene.sampled + " on " + scene.name + " (RMSE " + three_digits(strata.rmse) +
                 " against " + three_digits(independent.rmse) + ")",
             strata.samples == independent.samples && strata.rmse < independent.rmse});
    }
    return findings;
}

const char* sampling_kind_name(SamplingKind kind) {
    switch (kind) {
        case SamplingKind::stratified:
            return "stratified";
        case SamplingKind::regular:
            return "regular";
        case SamplingKind::random:
            return "random";
    }
    return "random";
}

nlohmann::json noise_json(const std::string& machine, const std::string& date,
                          const std::vector<NoiseScene>& scenes) {
    nlohmann::json scenes_json = nlohmann::json::array();
    for (const NoiseScene& scene : scenes) {
        nlohmann::json curves = nlohmann::json::array();
        for (const NoiseCurve& curve : scene.curves) {
            nlohmann::json points = nlohmann::json::array();
            for (const NoisePoint& p : curve.points) {
                points.push_back({{"samples", p.samples},
                                  {"runs", p.runs},
                                  {"seconds", p.seconds},
                                  {"rmse", p.rmse},
                                  {"rmse_spread", p.rmse_spread}});
            }
            curves.push_back({{"method", curve.method},
                              {"kind", sampling_kind_name(curve.kind)},
                              {"slope", noise_slope(curve)},
                              {"points", points}});
        }
        scenes_json.push_back({{"name", scene.name},
                               {"sampled", scene.sampled},
                               {"description", scene.description},
                               {"curves", curves}});
    }
    return {
        {"study", "sampling-noise"}, {"machine", machine}, {"date", date}, {"scenes", scenes_json}};
}

}  // namespace raystep
