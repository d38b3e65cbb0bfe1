#pragma once

#include <cstdint>
#include <filesystem>

#include "base/scene/scene.h"
#include "renderer/view.h"

namespace raystep {

// What a student's `raystep compare` needs of the reference on a sampled view (stage 8's samples
// per pixel or a quad light): no two right renders of it agree pixel for pixel, so the release
// ships the reference's mean over several seeds as the reference image and, beside it, how much
// one render's tile means spread around it. A student's one render is then judged tile by tile in
// standard errors, as the grader judges its eight (app/compare/noisy_render_comparison.h).

/// The reference's renders behind a sampled view's shipped mean and spread: as many as the
/// grader's reference takes, so that the mean's own error is a quarter of one render's.
constexpr int kSampledReferenceRenders = 16;
/// The reference's seeds, kSampledReferenceSeeds + k: far above any seed a scene or a student
/// writes, so that a student's render shares no random numbers with the mean.
constexpr std::uint64_t kSampledReferenceSeeds = 0xFFFF'FFFF'0000'0000;
/// The grader's tiles, bound and share of tiles allowed apart (noisy_render_checks.cpp).
constexpr int kSampledTile = 8;
constexpr double kSampledTileBound = 4.0;
constexpr double kSampledTilesApartAllowed = 0.01;
/// The smallest spread a tile is given: one step of an 8-bit image over the bound. The student's
/// render and the shipped mean are PNGs, each pixel rounded to 8 bits, so two right images of a
/// tile with little noise (a background, a surface in full light) may differ by up to a step
/// from rounding alone, which must stay within the bound; the grader compares floats and needs
/// only 1e-4. A larger floor would hide biases in quiet tiles (a scene with many light samples).
constexpr double kSampledDeviationFloor = 1.0 / 255.0 / kSampledTileBound;

/// True when the view of the scene averages random samples: a view that averages samples
/// (render_pixel.h) of a scene with more than one sample per pixel or a quad light.
bool is_sampled_view(const Scene& scene, View view);

/// Where the release keeps a sampled view's spread: beside its reference image, `<name>.spread.exr`
/// for `<name>.png` (scenes/stage8/reference/soft-shadows.full.spread.exr).
std::filesystem::path tile_spread_path(const std::filesystem::path& reference_image);

}  // namespace raystep
