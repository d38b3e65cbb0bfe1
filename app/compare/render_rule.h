#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "app/compare/image_diff.h"
#include "base/image/image.h"

namespace raystep {

/// A channel differing from the reference's by more than this makes a differing pixel: 8-bit
/// images round at 1/255, and a right renderer's colours differ from the reference's by far less.
constexpr float kPixelThreshold = 0.02f;

/// A render passes with at most this share of its pixels differing: a right method may decide
/// pixels exactly on an edge or a shadow boundary the other way. The grader's rubric gives a
/// render check full marks from 1 - kDifferingShareAllowed of its pixels matching; a grader test
/// holds grader/rubric/rubric.json to this number, so that a student release, which has no
/// rubric, judges a render by the number the grader scores it with.
constexpr double kDifferingShareAllowed = 0.005;

/// The difference at which the heat map turns white.
constexpr float kHeatMapFullScale = 0.25f;

/// A render judged against the reference's by the grader's rule.
struct RenderVerdict {
    ImageDiff diff;
    double share_over = 1.0;  ///< pixels_over / pixels; 1 for an empty image or a wrong size
    bool passed = false;      ///< share_over <= kDifferingShareAllowed
};

/// Judges `student` against `reference` by the grader's rule: a different size fails.
RenderVerdict judge_render(const Image& reference, const Image& student);

/// A render and its reference as read from their files, and the verdict on them.
struct RenderFileVerdict {
    Image image;
    Image reference;
    RenderVerdict verdict;
};

/// Reads both images (any format OpenImageIO reads; a PNG as written, rounded to 8 bits) and
/// judges the first against the second. Throws std::runtime_error naming the file that cannot be
/// read.
RenderFileVerdict judge_render_files(const std::filesystem::path& image,
                                     const std::filesystem::path& reference);

/// The verdict's metrics by the names the grader's report gives them, in the order a reader
/// wants them: mean absolute error, rmse, psnr (dB), pixels over threshold, visibly different
/// pixels, pixels.
std::vector<std::pair<std::string, double>> render_metrics(const ImageDiff& diff);

/// One line, as the grader's report summarises a render check: "12 of 3072 pixels differ by more
/// than 0.02 (0.39%); RMSE 0.0101", or that the image has the wrong size.
std::string render_summary(const RenderVerdict& verdict);

/// The heat map of the difference, as the grader writes it beside a render check.
Image render_heat_map(const Image& reference, const Image& student);

}  // namespace raystep
