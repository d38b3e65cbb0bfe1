#include "studies/sampling/noise_command.h"

#include <cstdio>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "app/demo/source_tree.h"
#include "renderer/terminal.h"
#include "studies/common/figures_file.h"
#include "studies/common/machine_description.h"
#include "studies/sampling/noise_measure.h"

namespace raystep {

namespace {

std::string counts_text(const std::vector<int>& counts) {
    std::string text;
    for (const int count : counts)
        text += (text.empty() ? "" : ", ") + std::to_string(count);
    return text;
}

}  // namespace

int run_noise_study(bool quick, const std::string& json_path) {
    NoiseStudyOptions options = quick ? quick_noise_options() : NoiseStudyOptions{};
    const bool terminal = is_terminal(stderr);
    options.progress = [terminal](const std::string& what) {
        if (terminal) std::fprintf(stderr, "\r\033[K  measuring %s", what.c_str());
    };
    const std::string machine = machine_description();
    const std::string date = local_time();
    std::printf(
        "raystep bench --sampling: %s; %s\n"
        "Each render %d x %d pixels on %d thread(s), its processor time (std::clock) from the "
        "scene's preparation to its last pixel; samples %s; each point the mean over %d seeds (the "
        "regular grid: 1, it has "
        "no randomness); RMSE over every pixel and channel against a converged render of %d "
        "stratified samples.\n",
        machine.c_str(), date.c_str(), options.width, options.height, options.threads,
        counts_text(options.counts).c_str(), options.seeds, options.converged_samples);

    const std::vector<NoiseScene> scenes = measure_noise(source_tree() / "scenes/demos", options);
    if (terminal) std::fprintf(stderr, "\r\033[K");

    for (const NoiseScene& scene : scenes) {
        std::printf("\n### %s, %s: %s\n\n%s", scene.name.c_str(), scene.sampled.c_str(),
                    scene.description.c_str(), noise_table(scene).c_str());
    }
    bool all_hold = true;
    std::printf("\n");
    for (const NoiseFinding& finding : noise_findings(scenes)) {
        std::printf("- %s: %s\n", finding.text.c_str(), finding.holds ? "yes" : "NO");
        all_hold = all_hold && finding.holds;
    }
    if (!json_path.empty()) write_figures(json_path, noise_json(machine, date, scenes));
    return all_hold ? 0 : 1;
}

}  // namespace raystep
