#include "app/cli/compare_command.h"

#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/cli/output_path.h"
#include "app/cli/render_command.h"
#include "app/compare/noisy_render_comparison.h"
#include "app/compare/reference_image.h"
#include "app/compare/render_rule.h"
#include "app/compare/sampled_reference.h"
#include "base/errors/input_error.h"
#include "base/image/image_io.h"
#include "renderer/view.h"

namespace raystep {

namespace fs = std::filesystem;

namespace {

std::string size_text(const Image& image) {
    return std::to_string(image.width()) + " x " + std::to_string(image.height());
}

// `name.png` -> `name.difference.png`, in the image's folder.
fs::path heat_map_beside(const fs::path& image) {
    return image.parent_path() / (image.stem().string() + ".difference.png");
}

// The view of a scene that has one reference view; a scene with several needs --view.
std::string only_view(const fs::path& scene) {
    const std::vector<std::string> views = reference_views(scene);
    if (views.size() == 1) return views.front();
    std::string names;
    for (const std::string& view : views)
        names += (names.empty() ? "" : ", ") + view;
    throw InputError(scene.string(), 0,
                     "the reference has the views " + names + ": pick one with --view");
}

// A sampled view (a reference shipped with its tile spread): the render's tiles against the
// reference's mean in standard errors, the grader's rule for noisy renders on one render.
int compare_sampled(const fs::path& image_path, const fs::path& reference_path,
                    const fs::path& spread_path, const fs::path& heat_map_path) {
    const Image image = read_image(image_path);
    const Image reference = read_image(reference_path);
    const Image spread = read_image(spread_path);
    std::printf(
        "image      %s\nreference  %s (the reference's mean over %d seeds)\nspread     %s\n",
        image_path.string().c_str(), reference_path.string().c_str(), kSampledReferenceRenders,
        spread_path.string().c_str());
    if (image.width() != reference.width() || image.height() != reference.height()) {
        std::fprintf(stderr,
                     "raystep compare: %s is %s pixels but the reference %s is %s: render the "
                     "scene at its own size\n",
                     image_path.string().c_str(), size_text(image).c_str(),
                     reference_path.string().c_str(), size_text(reference).c_str());
        std::printf("fail: the images differ in size\n");
        return 1;
    }
    NoisyComparison comparison;
    try {
        comparison =
            compare_render_with_spread(image, reference, spread, kSampledReferenceRenders,
                                       kSampledTile, kSampledTileBound, kSampledDeviationFloor);
    } catch (const std::invalid_argument&) {
        throw InputError(spread_path.string(), 0,
                         "holds " + size_text(spread) + " tiles, not one per " +
                             std::to_string(kSampledTile) + " x " + std::to_string(kSampledTile) +
                             " tile of the " + size_text(reference) + " reference");
    }
    const double share =
        static_cast<double>(comparison.tiles_apart) / static_cast<double>(comparison.tiles);
    const bool passed = share <= kSampledTilesApartAllowed;
    std::printf(
        "sampled scene: compared tile means in standard errors, not pixels: each %d x %d tile's "
        "mean against the reference's, in units of the spread one render's tile has over its "
        "seeds; a tile is apart beyond %.0f\n",
        kSampledTile, kSampledTile, kSampledTileBound);
    std::printf("  %-26s %d of %d (%.2f%%)\n", "tiles apart", comparison.tiles_apart,
                comparison.tiles, 100.0 * share);
    std::printf(
        "  %-26s %.3g at pixel (%d, %d): %.4g %.4g %.4g here, %.4g %.4g %.4g in the "
        "reference\n",
        "worst tile, standard errors", comparison.worst_z, comparison.worst_i, comparison.worst_j,
        comparison.worst_student.r, comparison.worst_student.g, comparison.worst_student.b,
        comparison.worst_reference.r, comparison.worst_reference.g, comparison.worst_reference.b);
    write_image(render_heat_map(reference, image), heat_map_path);
    std::printf(
        "heat map   %s (pixel by pixel: noise shows everywhere; look for tiles that stand out)\n",
        heat_map_path.string().c_str());
    std::printf(
        "%s: %.2f%% of tiles apart; the grader passes at most %.2f%%, on the mean of 8 renders "
        "of yours\n",
        passed ? "pass" : "fail", 100.0 * share, 100.0 * kSampledTilesApartAllowed);
    return passed ? 0 : 1;
}

int compare_files(const fs::path& image_path, const fs::path& reference_path,
                  const fs::path& heat_map_path) {
    const fs::path spread_path = tile_spread_path(reference_path);
    if (fs::is_regular_file(spread_path))
        return compare_sampled(image_path, reference_path, spread_path, heat_map_path);
    const RenderFileVerdict judged = judge_render_files(image_path, reference_path);
    const Image& image = judged.image;
    const Image& reference = judged.reference;
    const RenderVerdict& verdict = judged.verdict;
    std::printf("image      %s\nreference  %s\n", image_path.string().c_str(),
                reference_path.string().c_str());
    if (!verdict.diff.same_size) {
        std::fprintf(stderr,
                     "raystep compare: %s is %s pixels but the reference %s is %s: render the "
                     "scene at its own size\n",
                     image_path.string().c_str(), size_text(image).c_str(),
                     reference_path.string().c_str(), size_text(reference).c_str());
        std::printf("fail: %s\n", render_summary(verdict).c_str());
        return 1;
    }
    for (const auto& [name, value] : render_metrics(verdict.diff))
        std::printf("  %-26s %.6g\n", name.c_str(), value);
    write_image(render_heat_map(reference, image), heat_map_path);
    std::printf(
        "heat map   %s (black where they agree, through red and yellow to white at a "
        "difference of %.2f)\n",
        heat_map_path.string().c_str(), static_cast<double>(kHeatMapFullScale));
    std::printf("%s: %s; the grader passes at most %.2f%%\n", verdict.passed ? "pass" : "fail",
                render_summary(verdict).c_str(), 100.0 * kDifferingShareAllowed);
    return verdict.passed ? 0 : 1;
}

}  // namespace

CLI::App* add_compare_command(CLI::App& app, CompareArguments& arguments) {
    CLI::App* command = app.add_subcommand(
        "compare",
        "Compare a render with the reference's by the grader's rule: metrics, a verdict and a "
        "heat map. Exit 0 when it passes, 1 when it does not, 2 when it cannot compare");
    CLI::Option* image = command->add_option("image", arguments.image, "Your render");
    command->add_option("reference", arguments.reference,
                        "The reference image. Default: the shipped one of the same name "
                        "(scenes/<stage>/reference/<scene>.<view>.png)");
    command
        ->add_option("--scene", arguments.scene,
                     "Render this scene's view with this build's stages, then compare it")
        ->check(CLI::ExistingFile)
        ->excludes(image);
    command
        ->add_option(
            "--view", arguments.view,
            "The view: IMAGE's reference is <IMAGE's name>.<VIEW>.png; with --scene, needed when "
            "the scene's reference has several views")
        ->check(CLI::IsMember(view_names()));
    command->add_option("-o,--output", arguments.heat_map,
                        "Heat-map image. Default: IMAGE's name with .difference.png");
    return command;
}

int run_compare(const CompareArguments& arguments) {
    if (arguments.scene.empty() && arguments.image.empty())
        throw std::runtime_error("compare: give an IMAGE, or --scene SCENE");
    if (!arguments.scene.empty()) {
        // The render is written as render writes it, out/<stage>/<scene>.<view>.png, and held
        // against the reference of the same name in the reference/ folder beside the scene.
        const fs::path scene = arguments.scene;
        const std::string view = arguments.view.empty() ? only_view(scene) : arguments.view;
        const std::string file_name = scene.stem().string() + "." + view + ".png";
        // Found before rendering, so that a missing reference costs no render.
        const fs::path reference = find_reference_image(scene.parent_path() / file_name, "");
        const fs::path image = default_output(scene_output_folder(scene), file_name);
        RenderArguments render;
        render.scene = arguments.scene;
        render.output = image.string();
        render.view = view;
        run_render(render);
        return compare_files(
            image, reference,
            arguments.heat_map.empty() ? heat_map_beside(image) : fs::path(arguments.heat_map));
    }
    const fs::path image = arguments.image;
    if (!fs::is_regular_file(image)) throw std::runtime_error(image.string() + ": no such file");
    const fs::path reference = arguments.reference.empty()
                                   ? find_reference_image(image, arguments.view)
                                   : fs::path(arguments.reference);
    if (!fs::is_regular_file(reference))
        throw std::runtime_error(reference.string() + ": no such file");
    return compare_files(
        image, reference,
        arguments.heat_map.empty() ? heat_map_beside(image) : fs::path(arguments.heat_map));
}

}  // namespace raystep
