#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

namespace raystep {

// The epsilon study of docs/stage6.md, "Measuring acne": on each acne scene, every pixel's light
// as the exact answer has it (studies/epsilon/exact_visibility.h) against what the renderer's
// shadow ray says, for each ray offset rule and epsilon. The measuring is in epsilon_measure.h (it
// runs the stages); this is the data and how it is printed.

/// Shadow rays that got it wrong, of the pixels where the exact answer is decided.
struct OffsetErrors {
    std::size_t acne = 0;   ///< lit, but the shadow ray says blocked
    std::size_t leaks = 0;  ///< in shadow, but the shadow ray reaches the light
};

struct EpsilonSceneResult {
    std::string scene;          ///< the file, as given
    std::size_t lit = 0;        ///< pixels (and point lights) the light exactly reaches
    std::size_t shadowed = 0;   ///< pixels the light exactly does not reach
    std::size_t undecided = 0;  ///< left out: within 1e-12 of a silhouette or shadow edge
    std::size_t other_hit = 0;  ///< left out: the renderer's eye ray found another primitive
    std::vector<double> epsilons;
    std::vector<OffsetErrors> along_ray;     ///< one per epsilon
    std::vector<OffsetErrors> along_normal;  ///< one per epsilon
    OffsetErrors error_bound;
    std::string stopped;  ///< not empty when a stub or an error ended the measurement
};

/// The epsilons of the study: every power of ten from 1e-14 to 1e-1. The lecture's range, 1e-8
/// to 1e-1, and below it far enough to reach the acne of a double-precision renderer.
std::vector<double> study_epsilons();

/// The scene's table: a row per epsilon with acne and leaks for along-ray and along-normal, then
/// error-bound's row; Markdown, as the bench prints it.
std::string epsilon_table(const EpsilonSceneResult& result);

/// A line under the table: how many pixels were lit and shadowed, and how many were left out.
std::string epsilon_notes(const EpsilonSceneResult& result);

/// The study's figures as the JSON `bench --epsilon --json FILE` writes, which
/// scripts/draw-charts.py draws: {"study": "epsilon", "scenes": [{"scene" (the file's stem), "lit",
/// "shadowed", "undecided", "other_hit", "epsilons", "along_ray" and "along_normal" (an {"acne",
/// "leaks"} per epsilon), "error_bound": {"acne", "leaks"}, "stopped"}]}.
nlohmann::json epsilon_json(const std::vector<EpsilonSceneResult>& results);

}  // namespace raystep
