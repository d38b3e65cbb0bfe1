#include "app/compare/render_rule.h"

#include <cstdio>

#include "base/image/image_io.h"

namespace raystep {

RenderVerdict judge_render(const Image& reference, const Image& student) {
    RenderVerdict verdict;
    verdict.diff = compare_images(reference, student, kPixelThreshold);
    verdict.share_over = verdict.diff.pixels == 0
                             ? 1.0
                             : static_cast<double>(verdict.diff.pixels_over) / verdict.diff.pixels;
    verdict.passed = verdict.share_over <= kDifferingShareAllowed;
    return verdict;
}

RenderFileVerdict judge_render_files(const std::filesystem::path& image,
                                     const std::filesystem::path& reference) {
    RenderFileVerdict result{read_image(image), read_image(reference), {}};
    result.verdict = judge_render(result.reference, result.image);
    return result;
}

std::vector<std::pair<std::string, double>> render_metrics(const ImageDiff& diff) {
    return {{"mean absolute error", diff.mean_error},
            {"rmse", diff.rms_error},
            {"psnr", diff.psnr},
            {"pixels over threshold", static_cast<double>(diff.pixels_over)},
            {"visibly different pixels", static_cast<double>(diff.pixels_visibly_different)},
            {"pixels", static_cast<double>(diff.pixels)}};
}

std::string render_summary(const RenderVerdict& verdict) {
    if (!verdict.diff.same_size) return "the image has the wrong size";
    char text[160];
    std::snprintf(
        text, sizeof text, "%zu of %zu pixels differ by more than %.2f (%.2f%%); RMSE %.4f",
        verdict.diff.pixels_over, verdict.diff.pixels, static_cast<double>(kPixelThreshold),
        100.0 * verdict.share_over, verdict.diff.rms_error);
    return text;
}

Image render_heat_map(const Image& reference, const Image& student) {
    return difference_heat_map(reference, student, kHeatMapFullScale);
}

}  // namespace raystep
