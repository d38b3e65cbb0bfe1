#pragma once

#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace raystep {

// The sampling noise study (`raystep bench --sampling`, docs/measurements/sampling-noise.md): the
// RMSE of a render against a converged render of the same scene, against the samples it took and
// the time they cost, for each way of placing them. This file holds the results and what is
// printed from them; studies/sampling/noise_measure.h renders.

/// How a curve places its samples: the finding it takes part in depends on it.
enum class SamplingKind {
    stratified,  ///< one random point per stratum: jittered pixels, `lightstratify on`
    regular,     ///< the strata's centres: no randomness, one run says it all
    random,      ///< independent uniform points: the 1/sqrt(N) baseline
};

/// One sample count of a curve, over its runs (one per seed).
struct NoisePoint {
    int samples = 0;           ///< per pixel, or per light at each pixel
    int runs = 0;              ///< renders measured, each with its own seed
    double seconds = 0.0;      ///< mean processor time of one render
    double rmse = 0.0;         ///< mean RMSE against the converged render
    double rmse_spread = 0.0;  ///< the sample standard deviation of the RMSE over the runs
};

/// One way of placing samples on one scene, at increasing sample counts.
struct NoiseCurve {
    std::string method;  ///< "jittered", "regular", "random", "stratified"
    SamplingKind kind = SamplingKind::random;
    std::vector<NoisePoint> points;  ///< by increasing samples
};

/// The curves of one scene.
struct NoiseScene {
    std::string name;     ///< "stripes", "glass-cube", "soft-shadows"
    std::string sampled;  ///< what the samples are: "pixel samples" or "light samples"
    std::string description;
    std::vector<NoiseCurve> curves;
};

/// The exponent p of RMSE ~ N^p over the curve's points (log_log_slope): -0.5 for independent
/// samples. Throws std::invalid_argument for fewer than two points or an RMSE of 0.
double noise_slope(const NoiseCurve& curve);

/// The scene's curves as one Markdown table: method, samples, runs, processor milliseconds per
/// render, mean RMSE and its spread, a row per point; then the slope of each curve.
std::string noise_table(const NoiseScene& scene);

/// A claim the study checks on its own results, and whether the results bear it out.
struct NoiseFinding {
    std::string text;
    bool holds = false;
};

/// What the study expects of correct sampling code, on every scene: the random curve's mean RMSE
/// falls at each larger sample count, and at the largest count the stratified curve's mean RMSE is
/// below the random one's. A scene without a random or a stratified curve adds no finding.
std::vector<NoiseFinding> noise_findings(const std::vector<NoiseScene>& scenes);

/// The kind's name in the study's JSON: "stratified", "regular", "random".
const char* sampling_kind_name(SamplingKind kind);

/// The study's figures as the JSON `bench --sampling --json FILE` writes, which
/// scripts/draw-charts.py draws: {"study": "sampling-noise", "machine", "date", "scenes": [{"name",
/// "sampled", "description", "curves": [{"method", "kind", "slope" (noise_slope), "points":
/// [{"samples", "runs", "seconds", "rmse", "rmse_spread"}]}]}]}.
nlohmann::json noise_json(const std::string& machine, const std::string& date,
                          const std::vector<NoiseScene>& scenes);

}  // namespace raystep
