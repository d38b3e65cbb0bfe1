// Render checks of sampled scenes (stage 8): the submission renders the view at several seeds,
// the grader renders the reference at others, and each tile's mean over the submission's renders
// is held to the reference's in standard errors that the renders' own spread gives
// (app/compare/noisy_render_comparison.h). A right submission passes whatever its seeds; a biased
// one (a light without its cosine, area or 1/pi, a shadow that ignores occlusion, a pixel off by
// half) leaves its tiles many standard errors away.

#include <array>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/compare/noisy_render_comparison.h"
#include "app/compare/render_rule.h"
#include "app/grade/value_text.h"
#include "app/probe/render_calls.h"
#include "app/protocol/image_json.h"
#include "base/image/image_io.h"
#include "base/scene/scene_files.h"
#include "base/scene/scene_loader.h"
#include "grader/grade/checks/judging.h"
#include "grader/grade/checks/kept_renders.h"
#include "grader/grade/checks/moved_eye.h"
#include "grader/grade/checks/stage_checks.h"
#include "grader/grade/checks/statistics_seed.h"
#include "renderer/tile_renderer.h"

namespace raystep::grade {

namespace {

namespace fs = std::filesystem;

// The submission's renders and the reference's. Eight give each tile's mean over renders a
// standard error of a third of one render's spread; the reference's sixteen make its own error the
// smaller part of the difference's.
constexpr int kStudentRenders = 8;
constexpr int kReferenceRenders = 16;
// The reference's seeds: far above any student's, (statistics seed << 8) + k.
constexpr std::uint64_t kReferenceSeeds = 0xFFFF'FFFF'0000'0000;

// Tiles of 8 x 8 pixels: a tile's mean over 64 pixels is close to normal even where single
// pixels are not (an edge's pixel is one colour or another), and a penumbra spans several tiles.
constexpr int kTile = 8;
// Four standard errors per tile and channel: under a normal law 6e-5 of them lie beyond it, some
// 0.06 of the 900 tests of a 160 x 120 view.
constexpr double kTileBound = 4.0;
// A tile with no noise (all ambient, or a background) differs only by float rounding: 1e-4 of
// the colour's unit keeps such a tile from failing on rounding alone.
constexpr double kDeviationFloor = 1e-4;
// The share of tiles that may be apart with the check still passed, as the rubric's full mark:
// 1% of the tiles, three of a 160 x 120 view; a bias that shows only in a penumbra moves a tenth
// of them or more. Measured: docs/measurements/stage8-checks.md.
constexpr double kTilesApartPassed = 0.01;

// The scene at the check's size, seed, eye and samples per pixel (0: the scene's own).
Scene seeded_scaled_scene(const fs::path& path, std::uint64_t seed, const Vec3& eye,
                          int samples_per_pixel) {
    Scene scene = load_scene(path);
    if (samples_per_pixel > 0) scene.samples_per_pixel = samples_per_pixel;
    if (scene.width > kRenderCheckWidth) {
        const double scale = static_cast<double>(kRenderCheckWidth) / scene.width;
        scene.width = kRenderCheckWidth;
        scene.height = std::max(1, static_cast<int>(std::lround(scene.height * scale)));
    }
    scene.seed = seed;
    scene.camera.lookfrom = eye;
    return scene;
}

// The reference's kReferenceRenders renders of a view from `eye`, from kReferenceSeeds on, one
// thread each: a grade makes the noisy checks' views side by side.
std::vector<Image> render_reference(const fs::path& path, View view, const Vec3& eye,
                                    int samples_per_pixel) {
    std::vector<Image> renders;
    for (int k = 0; k < kReferenceRenders; ++k) {
        const Scene scene = seeded_scaled_scene(
            path, kReferenceSeeds + static_cast<std::uint64_t>(k), eye, samples_per_pixel);
        RenderOptions options;
        options.view = view;
        options.threads = 1;
        renders.push_back(render_image(prepare_render_scene(scene), options));
    }
    return renders;
}

// What the reference's renders of a view depend on, as kept_renders.h keys them; empty where the
// scene's files or the grader's program cannot be read, and then nothing is kept. The eye in
// hexadecimal floating point: exact, so that only the same eye finds the renders.
std::string reference_renders_key(const fs::path& path, View view, const Vec3& eye,
                                  int samples_per_pixel) {
    const std::string scene = scene_digest(load_scene(path));
    const std::string grader = grader_identity();
    if (scene.empty() || grader.empty()) return "";
    char eye_text[96];
    std::snprintf(eye_text, sizeof eye_text, "%a %a %a", eye.x, eye.y, eye.z);
    return "reference renders\nscene " + scene + "\nview " + std::string(view_name(view)) +
           "\nwidth " + std::to_string(kRenderCheckWidth) + "\nspp " +
           std::to_string(samples_per_pixel) + "\neye " + eye_text + "\nrenders " +
           std::to_string(kReferenceRenders) + " from seed " + std::to_string(kReferenceSeeds) +
           "\ngrader " + grader + "\n";
}

// The reference's renders of a view from `eye`: from where an earlier grade from the same eyes
// kept them (GradingContext::kept_renders), or made here and kept there for the next.
std::vector<Image> reference_renders(const GradingContext& context, const fs::path& path, View view,
                                     const Vec3& eye, int samples_per_pixel) {
    const std::string key = reference_renders_key(path, view, eye, samples_per_pixel);
    const fs::path kept = key.empty() ? fs::path() : context.kept_renders;
    if (!kept.empty()) {
        if (std::optional<std::vector<Image>> found = kept_renders(kept, key)) return *found;
    }
    std::vector<Image> renders = render_reference(path, view, eye, samples_per_pixel);
    if (!kept.empty()) keep_renders(kept, key, renders);
    return renders;
}

struct NoisyRenderCheck {
    int stage = 8;
    std::string scene;
    View view = View::full;
    /// The samples per pixel of every render, student's and reference's; 0: the scene's `spp`.
    int samples_per_pixel = 0;

    std::string id() const {
        return "stage" + std::to_string(stage) + ".render." + fs::path(scene).stem().string() +
               "." + std::string(view_name(view));
    }
};

CheckMeasure measure_noisy_render(const GradingContext& context, const BuiltProbe& probe,
                                  const NoisyRenderCheck& check) {
    const fs::path path = context.source / "scenes" / check.scene;
    const std::string id = check.id();
    const Vec3 eye = moved_eye(load_scene(path).camera, context.eye_seed, id);
    std::vector<std::optional<Image>> student(kStudentRenders);
    std::vector<ProbeCase> cases;
    for (int k = 0; k < kStudentRenders; ++k) {
        const std::uint64_t seed = (statistics_seed() << 8) + static_cast<std::uint64_t>(k);
        probe::RenderQuestion question{path.string(),
                                       std::string(view_name(check.view)),
                                       kRenderCheckWidth,
                                       seed,
                                       {},
                                       {},
                                       eye,
                                       {}};
        if (check.samples_per_pixel > 0) question.samples_per_pixel = check.samples_per_pixel;
        cases.push_back(
            {check.scene + ", " + std::string(view_name(check.view)) + " view, " +
                 moved_eye_text(eye) + ", seed " + std::to_string(seed),
             probe::query(probe::render_call, question),
             [&student, k](const ProbeAnswer& answer) {
                 if (answer.kind != ProbeAnswer::Kind::result) return wrong("an image", "");
                 student[static_cast<std::size_t>(k)] =
                     probe::image_from(answer.value, static_cast<std::size_t>(kRenderCheckWidth) *
                                                         kRenderCheckWidth * 4);
                 return right();
             },
             std::string(kStudentRaystep) + " render scenes/" + check.scene + " --view " +
                 std::string(view_name(check.view)) + lookfrom_arguments(eye) +
                 (check.samples_per_pixel > 0 ? " --spp " + std::to_string(check.samples_per_pixel)
                                              : std::string())});
    }
    ProbeRunLimits limits = scene_reading_limits(context);
    // Eight renders in one run: the time of eight single renders.
    limits.cpu_seconds = 60.0;
    limits.wall = std::chrono::seconds(120);
    CheckMeasure measure = run_cases(context, id, probe, cases, limits);
    std::vector<Image> renders;
    for (const std::optional<Image>& image : student) {
        if (!image) return measure;
        renders.push_back(*image);
    }

    const std::vector<Image> reference =
        reference_renders(context, path, check.view, eye, check.samples_per_pixel);
    NoisyComparison comparison;
    try {
        comparison = compare_noisy_renders(renders, reference, kTile, kTileBound, kDeviationFloor);
    } catch (const std::invalid_argument&) {
        measure.outcome = Outcome::failed;
        measure.fraction = 0.0;
        measure.summary = "the renders are not the reference's size, " +
                          std::to_string(reference.front().width()) + " x " +
                          std::to_string(reference.front().height()) + " pixels";
        return measure;
    }
    const Image student_mean = mean_image(renders);
    const Image reference_mean = mean_image(reference);
    const fs::path folder = context.report_folder / "renders" / id;
    write_image(reference_mean, folder / "reference.png");
    write_image(student_mean, folder / "student.png");
    write_image(render_heat_map(reference_mean, student_mean), folder / "difference.png");
    measure.images = {"renders/" + id + "/reference.png", "renders/" + id + "/student.png",
                      "renders/" + id + "/difference.png"};
    const double share_apart =
        static_cast<double>(comparison.tiles_apart) / static_cast<double>(comparison.tiles);
    measure.fraction = 1.0 - share_apart;
    measure.metrics = {{"tiles", comparison.tiles},
                       {"tiles apart", comparison.tiles_apart},
                       {"worst z", comparison.worst_z}};
    measure.outcome = share_apart <= kTilesApartPassed ? Outcome::passed : Outcome::failed;
    measure.summary = std::to_string(comparison.tiles_apart) + " of " +
                      std::to_string(comparison.tiles) + " tiles beyond " + full_text(kTileBound) +
                      " standard errors of the reference's mean";
    if (measure.outcome == Outcome::failed) {
        measure.counterexamples = {
            {"the " + std::to_string(kTile) + " x " + std::to_string(kTile) + " tile at pixel (" +
                 std::to_string(comparison.worst_i) + ", " + std::to_string(comparison.worst_j) +
                 ") of " + check.scene + " at " + std::to_string(kRenderCheckWidth) +
                 " pixels wide, " + moved_eye_text(eye) + ", its mean over " +
                 std::to_string(kStudentRenders) + " seeds",
             full_text(comparison.worst_reference),
             full_text(comparison.worst_student) + ", " + full_text(comparison.worst_z) +
                 " standard errors away",
             context.reproduce + " --check " + id, cases.front().student_reproduce}};
    }
    return measure;
}

std::vector<NoisyRenderCheck> noisy_render_check_list() {
    return {
        // Soft shadows: the quad light's cosine, area, 1/pi, sample count and occlusion.
        {8, "stage8/soft-shadows.test", View::full},
        // Antialiasing: the film points of 16 jittered samples per pixel, where a shift or a
        // flip moves every edge of the checkerboard.
        {8, "stage8/aliasing.test", View::full},
        // Path tracing: every estimator of the Cornell box's paths, at 4 paths per pixel (the
        // scene's 64 would cost each grade a minute; the tiles' noise is measured either way).
        {10, "stage10/cornell-box.test", View::full, 4},
    };
}

}  // namespace

std::vector<CheckDefinition> noisy_render_checks() {
    std::vector<CheckDefinition> checks;
    for (const NoisyRenderCheck& check : noisy_render_check_list()) {
        checks.push_back({check.id(), check.stage, "render",
                          "the " + std::string(view_name(check.view)) + " view of scenes/" +
                              check.scene + " from an eye moved for each grade, at " +
                              std::to_string(kStudentRenders) +
                              " seeds, tile by tile against the reference's mean",
                          [check](const GradingContext& context, const BuiltProbe& probe) {
                              return measure_noisy_render(with_eye_seed(context), probe, check);
                          }});
    }
    return checks;
}

}  // namespace raystep::grade
