#include "studies/sampling/noise_measure.h"

#include <ctime>

#include "app/demo/sampled_image.h"
#include "base/scene/scene_loader.h"
#include "renderer/tile_renderer.h"
#include "studies/sampling/noise_statistics.h"

namespace raystep {

namespace {

// The converged render's seed, apart from the runs' seeds 1, 2, ...: its noise must not be the
// noise of any run it is compared with.
constexpr std::uint64_t kConvergedSeed = 0x5eed0c0ffeeull;

// Processor time, not wall time: the machine the study runs on is shared, and wall time under
// someone else's load measures the load. std::clock counts the whole process, so every thread of
// a render.
template <class Function>
double processor_seconds_of(Function&& fn) {
    const std::clock_t start = std::clock();
    fn();
    return static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
}

// Which samples a curve varies, and how it places them.
struct Placement {
    bool pixel;  ///< pixel samples; else light samples at one ray per pixel
    SamplePattern pattern;
    int count;
};

Scene study_scene(const std::filesystem::path& file, const NoiseStudyOptions& options) {
    Scene scene = load_scene(file);
    // The study's sizes keep the scenes' 4:3, so that the view is the scene's, in fewer pixels
    scene.width = options.width;
    scene.height = options.height;
    return scene;
}

Image render_placed(Scene scene, const Placement& placement, std::uint64_t seed, int threads) {
    scene.seed = seed;
    if (placement.pixel) {
        return sampled_image(prepare_render_scene(scene), placement.pattern, placement.count,
                             threads);
    }
    scene.samples_per_pixel = 1;
    scene.light_samples = placement.count;
    scene.light_stratify = placement.pattern == SamplePattern::jittered;
    RenderOptions render;
    render.threads = threads;
    return render_image(prepare_render_scene(scene), render);
}

struct CurveSpec {
    const char* method;
    SamplingKind kind;
    SamplePattern pattern;
};

NoiseScene measure_scene(const std::filesystem::path& file, const char* name, bool pixel,
                         const std::vector<CurveSpec>& specs, const NoiseStudyOptions& options) {
    const Scene scene = study_scene(file, options);
    NoiseScene result;
    result.name = name;
    result.sampled = pixel ? "pixel samples" : "light samples";

    if (options.progress) options.progress(std::string(name) + ": the converged render");
    const Image converged = render_placed(
        scene, {pixel, SamplePattern::jittered, options.converged_samples}, kConvergedSeed, 0);

    for (const CurveSpec& spec : specs) {
        NoiseCurve curve{spec.method, spec.kind, {}};
        // The regular grid draws no random number: every seed gives the same image
        const int runs = spec.kind == SamplingKind::regular ? 1 : options.seeds;
        for (const int count : options.counts) {
            if (options.progress) {
                options.progress(std::string(name) + ": " + spec.method + " " +
                                 std::to_string(count));
            }
            std::vector<double> rmse;
            double seconds = 0.0;
            for (int run = 0; run < runs; ++run) {
                Image image;
                seconds += processor_seconds_of([&] {
                    image = render_placed(scene, {pixel, spec.pattern, count},
                                          static_cast<std::uint64_t>(run + 1), options.threads);
                });
                rmse.push_back(image_rmse(image, converged));
            }
            const MeanSpread error = mean_and_spread(rmse);
            curve.points.push_back({count, runs, seconds / runs, error.mean, error.spread});
        }
        result.curves.push_back(std::move(curve));
    }
    return result;
}

}  // namespace

NoiseStudyOptions quick_noise_options() {
    NoiseStudyOptions options;
    options.width = 48;
    options.height = 36;
    options.counts = {1, 4, 16};
    options.seeds = 3;
    options.converged_samples = 256;
    return options;
}

std::vector<NoiseScene> measure_noise(const std::filesystem::path& scenes_folder,
                                      const NoiseStudyOptions& options) {
    const std::vector<CurveSpec> pixel_curves = {
        {"jittered", SamplingKind::stratified, SamplePattern::jittered},
        {"regular", SamplingKind::regular, SamplePattern::regular},
        {"random", SamplingKind::random, SamplePattern::random},
    };
    const std::vector<CurveSpec> light_curves = {
        {"stratified", SamplingKind::stratified, SamplePattern::jittered},
        {"random", SamplingKind::random, SamplePattern::random},
    };
    std::vector<NoiseScene> scenes;
    scenes.push_back(
        measure_scene(scenes_folder / "aliasing.test", "stripes", true, pixel_curves, options));
    scenes.back().description =
        "aliasing.test: white bands receding to the horizon, flat colours: edges at every scale";
    scenes.push_back(measure_scene(scenes_folder / "glass-cube.test", "glass-cube", true,
                                   pixel_curves, options));
    scenes.back().description =
        "glass-cube.test at index 1.5: checker edges, seen directly and through refraction";
    scenes.push_back(measure_scene(scenes_folder / "soft-shadows.test", "soft-shadows", false,
                                   light_curves, options));
    scenes.back().description =
        "soft-shadows.test: penumbrae of a square light, one ray through each pixel's centre";
    return scenes;
}

}  // namespace raystep
