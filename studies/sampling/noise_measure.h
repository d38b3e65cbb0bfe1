#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "studies/sampling/noise_study.h"

namespace raystep {

/// How much the sampling noise study measures.
struct NoiseStudyOptions {
    int width = 96;  ///< every render's size, in pixels
    int height = 72;
    std::vector<int> counts{1, 4, 16, 64, 256};        ///< samples, each a square for the strata
    int seeds = 4;                                     ///< runs per point of a random curve
    int converged_samples = 4096;                      ///< the converged render's, jittered
    int threads = 1;                                   ///< per render; the times are per render
    std::function<void(const std::string&)> progress;  ///< told what is being measured
};

/// The options of `bench --sampling --quick`: a few seconds in all, counts 1 to 16.
NoiseStudyOptions quick_noise_options();

/// The study on the scenes of `scenes_folder` (this repository's scenes/demos/), through this
/// program's stages: pixel sampling (jittered, regular, random) on the stripes of aliasing.test
/// and the glass cube of glass-cube.test, each sample through stage 8's pixel_colour, and light
/// sampling (stratified, random) on the area light of soft-shadows.test with one ray through each
/// pixel's centre. Each point is the mean over `seeds` renders (one for regular), each against
/// the converged render: jittered pixel samples, or stratified light samples, at
/// `converged_samples`. A stub stops it with its NotImplemented; a missing scene throws
/// InputError.
std::vector<NoiseScene> measure_noise(const std::filesystem::path& scenes_folder,
                                      const NoiseStudyOptions& options);

}  // namespace raystep
