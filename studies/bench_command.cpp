#include "studies/bench_command.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <thread>

#include <nlohmann/json.hpp>

#include "app/cli/command_registry.h"
#include "app/demo/source_tree.h"
#include "renderer/terminal.h"
#include "studies/common/figures_file.h"
#include "studies/common/machine_description.h"
#include "studies/common/number_text.h"
#include "studies/epsilon/epsilon_measure.h"
#include "studies/epsilon/epsilon_study.h"
#include "studies/sampling/noise_command.h"
#include "studies/scale/scene_scale.h"
#include "studies/speed_error/pareto_registry.h"
#include "studies/structures/baseline_registry.h"
#include "studies/structures/bench_scenes.h"
#include "studies/structures/growth.h"
#include "studies/structures/our_structures.h"
#include "studies/structures/speed_bar.h"
#include "studies/structures/threshold.h"
#include "studies/structures/workload_table.h"

namespace raystep {

namespace {

// --quick runs this fraction of every ray count.
constexpr double kQuickFraction = 1.0 / 8.0;

// The growth table's incoherent rays per mesh: about a second per structure at 1M triangles.
constexpr std::size_t kGrowthRays = std::size_t{1} << 16;

void print_header(int threads, const std::vector<BenchCandidate>& candidates) {
    const std::string machine = machine_description();
    const std::string load = load_average();
    std::printf("raystep bench: %s; all-threads columns use %d; %s build; %s%s\n", machine.c_str(),
                threads, RAYSTEP_BUILD_TYPE, local_time().c_str(),
                load.empty() ? "" : ("; load average " + load + " at the start").c_str());
    std::printf(
        "Every time is the best of 3 runs, the structures taking turns in each run; each ray set "
        "first gets one untimed pass that warms up and counts nodes and tests per ray. Mrays/s: "
        "millions of rays per second.\n");

    const auto baseline = std::find_if(candidates.begin(), candidates.end(),
                                       [](const BenchCandidate& c) { return c.baseline; });
    if (baseline == candidates.end()) {
        std::printf(
            "No Embree columns: the Embree baseline is linked only into raystep-reference, and "
            "only where libembree-dev is installed.\n");
    } else {
        const std::string name = baseline->name.substr(0, baseline->name.find(' '));
        std::printf(
            "x %s: ours divided by %s's, the column to its left (throughput above 1: faster "
            "than %s; build above 1: slower). %s is timed, not checked: it works in float.\n",
            name.c_str(), name.c_str(), name.c_str(), name.c_str());
    }
}

// Adds the registered baselines to `candidates`, each held to the instruction set `isa` unless it
// is empty; false when `isa` is given and no baseline can be held to it.
bool add_baselines(const std::string& isa, std::vector<BenchCandidate>& candidates) {
    bool held = false;
    for (const BenchCandidate& baseline : BaselineRegistry::entries()) {
        if (isa.empty()) {
            candidates.push_back(baseline);
        } else if (baseline.held_to) {
            candidates.push_back(baseline.held_to(isa));
            candidates.back().baseline = true;
            held = true;
        }
    }
    return isa.empty() || held;
}

// A progress line on stderr, redrawn in place, when stderr is a terminal.
class ProgressLine {
  public:
    ProgressLine() : enabled_(is_terminal(stderr)) {}
    void show(const std::string& what) const {
        if (enabled_) std::fprintf(stderr, "\r\033[K  measuring %s", what.c_str());
    }
    void clear() const {
        if (enabled_) std::fprintf(stderr, "\r\033[K");
    }

  private:
    bool enabled_;
};

// The ray sets of `scene` that the --workload names select: both for the scene's own name.
std::vector<RaySet> selected_ray_sets(const BenchScene& scene,
                                      const std::vector<std::string>& workloads) {
    std::vector<RaySet> sets;
    for (const RaySet& set : scene.ray_sets) {
        const bool wanted =
            workloads.empty() ||
            std::find(workloads.begin(), workloads.end(), scene.name) != workloads.end() ||
            std::find(workloads.begin(), workloads.end(), set.name) != workloads.end();
        if (wanted) sets.push_back(set);
    }
    return sets;
}

bool scene_selected(const std::string& name, const std::vector<std::string>& workloads) {
    if (workloads.empty()) return true;
    return std::any_of(workloads.begin(), workloads.end(), [&](const std::string& workload) {
        return workload == name || workload.rfind(name + "-", 0) == 0;
    });
}

// Measures and prints the selected workloads of one scene; false when a cross-check failed.
bool run_scene(const std::string& name, const BenchArguments& arguments,
               const std::vector<BenchCandidate>& candidates, const MeasureOptions& options) {
    const std::filesystem::path meshes = RAYSTEP_BENCH_MESHES;
    if (const auto missing = bench_scene_unavailable(name, meshes)) {
        std::printf("\n%s workloads skipped: %s\n", name.c_str(), missing->c_str());
        return true;
    }
    const BenchScene scene = make_bench_scene(name, meshes, arguments.quick ? kQuickFraction : 1.0);
    const std::vector<RaySet> ray_sets = selected_ray_sets(scene, arguments.workloads);

    const std::vector<StructureMeasurement> measurements =
        measure_candidates(candidates, scene.primitives, ray_sets, options);
    ProgressLine().clear();

    bool agreed = true;
    for (std::size_t k = 0; k < ray_sets.size(); ++k) {
        std::printf("\n### %s: %s; %s\n\n%s\n", ray_sets[k].name.c_str(), scene.description.c_str(),
                    ray_sets[k].description.c_str(),
                    workload_table(measurements, k, options.threads).c_str());
        for (const std::string& note : workload_notes(measurements, k, ray_sets[k].rays.size())) {
            std::printf("- %s\n", note.c_str());
            if (note.rfind("WARNING", 0) == 0) agreed = false;
        }
    }
    const std::vector<std::string> bar = speed_bar_lines(name, measurements, ray_sets);
    if (!bar.empty()) std::printf("\n");
    for (const std::string& line : bar)
        std::printf("- %s\n", line.c_str());
    return agreed;
}

void run_growth(const BenchArguments& arguments, const std::vector<BenchCandidate>& candidates,
                const MeasureOptions& options) {
    const auto rays = static_cast<std::size_t>(static_cast<double>(kGrowthRays) *
                                               (arguments.quick ? kQuickFraction : 1.0));
    const std::vector<GrowthRow> rows = measure_growth(candidates, rays, options);
    ProgressLine().clear();
    std::printf(
        "\n### growth: bumpy tori of 1,024 to 1,048,576 triangles; %s incoherent rays; one "
        "thread\n\n%s",
        grouped(rays).c_str(), growth_table(rows).c_str());
}

void run_threshold(const BenchArguments& arguments) {
    ThresholdOptions options;
    if (arguments.quick) {
        const double side = std::sqrt(kQuickFraction);
        options.timed_width = static_cast<int>(std::lround(options.timed_width * side));
        options.timed_height = static_cast<int>(std::lround(options.timed_height * side));
    }
    ProgressLine().show("the threshold");
    const std::vector<ThresholdCurve> curves =
        measure_threshold(brute_force_candidate(), bvh_candidate(BvhSplit::sah), options);
    ProgressLine().clear();
    std::printf(
        "\n### threshold: brute force against BVH SAH on n random primitives; %d x %d primary "
        "rays timed on one thread, the build spread over a %d x %d image's rays\n%s",
        options.timed_width, options.timed_height, options.image_width, options.image_height,
        threshold_report(curves, options).c_str());
}

// The acne scenes of stage 6, at the three scales the study compares.
std::vector<std::filesystem::path> acne_scenes() {
    const std::filesystem::path folder = source_tree() / "scenes/stage6";
    return {folder / "acne-scale-1e-3.test", folder / "acne-scale-1.test",
            folder / "acne-scale-1e4.test"};
}

void run_epsilon(const BenchArguments& arguments) {
    const std::vector<double> epsilons = study_epsilons();
    std::printf(
        "\n### epsilon: acne (lit pixels whose shadow ray says blocked) and leaks (shadowed pixels "
        "whose shadow ray reaches the light) of each ray offset rule, against the exact answer\n");
    std::vector<EpsilonSceneResult> results;
    for (const std::filesystem::path& scene : acne_scenes()) {
        ProgressLine().show("the epsilon study: " + scene.filename().string());
        results.push_back(measure_epsilon_scene(scene, epsilons));
        ProgressLine().clear();
        std::printf("\n#### %s\n\n%s\n- %s\n", scene.filename().string().c_str(),
                    epsilon_table(results.back()).c_str(), epsilon_notes(results.back()).c_str());
    }
    if (arguments.json.empty()) return;
    std::printf("\n");
    write_figures(arguments.json, epsilon_json(results));
}

}  // namespace

CLI::App* add_bench_command(CLI::App& app, BenchArguments& arguments) {
    CLI::App* command = app.add_subcommand(
        "bench",
        "Measure the acceleration structures: build time, Mrays/s, nodes and tests per ray "
        "(docs/measurements/stage4-bench.md)");
    command
        ->add_option("--workload", arguments.workloads,
                     "Run only this scene (both its ray sets) or workload; may be repeated")
        ->check(CLI::IsMember(bench_workload_names()));
    command->add_flag("--growth", arguments.growth,
                      "The growth table: build and query cost from 1k to 1M triangles");
    command->add_flag("--threshold", arguments.threshold,
                      "The scene size from which a BVH pays for its build, against brute force");
    CLI::Option* epsilon = command->add_flag(
        "--epsilon", arguments.epsilon,
        "The epsilon study: acne and light leaks of each ray offset rule on the acne scenes "
        "(docs/stage6.md)");
    command->add_option("--json", arguments.json,
                        "With --epsilon or --sampling: also write the study's figures into this "
                        "JSON file, which scripts/draw-charts.py draws");
    command->add_flag("--scale", arguments.scale,
                      "The scale bars on scenes/scale/: a thousand transformed spheres against a "
                      "127,408-triangle scene, a thousand instanced bunnies against one "
                      "(docs/measurements/scale.md)");
    CLI::Option* pareto = command->add_flag(
        "--pareto", arguments.pareto,
        "The speed-against-error study: every triangle, sphere and plane test in double and "
        "float on decided ray cases, and the cost of each ray offset rule (docs/stage3.md; "
        "raystep-reference only)");
    command
        ->add_flag("--sampling", arguments.sampling,
                   "The sampling noise study: RMSE against a converged render and time, for "
                   "jittered, regular and random pixel samples and stratified and random light "
                   "samples (docs/measurements/sampling-noise.md)")
        ->excludes("--workload")
        ->excludes("--growth")
        ->excludes("--threshold")
        ->excludes("--scale")
        ->excludes(epsilon)
        ->excludes(pareto);
    pareto->excludes("--workload")
        ->excludes("--growth")
        ->excludes("--threshold")
        ->excludes("--scale")
        ->excludes(epsilon);
    command
        ->add_option("--cases", arguments.cases,
                     "With --pareto: case files, or folders of *.cases files (default: stage 3's "
                     "own cases)")
        ->needs(pareto);
    command
        ->add_option("--out", arguments.out,
                     "With --pareto: the folder for pareto.json, which scripts/draw-charts.py "
                     "draws (default: pareto)")
        ->needs(pareto);
    command
        ->add_option("--threads", arguments.threads,
                     "Threads of the all-threads columns (default: every hardware thread)")
        ->check(CLI::Range(1, 1024));
    command
        ->add_option("--embree-isa", arguments.embree_isa,
                     "Hold Embree to this instruction set (its device option max_isa), to compare "
                     "like with like: the reference is compiled for the compiler's default, SSE2 "
                     "on x86-64. The speed bar is then not judged (raystep-reference only)")
        ->check(CLI::IsMember({"sse2", "sse4.2", "avx", "avx2", "avx512"}))
        ->excludes(pareto);
    command->add_flag("--quick", arguments.quick,
                      "An eighth of the rays, for a smoke test (with --pareto: short timing "
                      "samples and one acne scene; with --sampling: 48 x 36 pixels, 1 to 16 "
                      "samples, 3 seeds)");
    return command;
}

int run_bench(const BenchArguments& arguments) {
    if (!arguments.json.empty() && !arguments.epsilon && !arguments.sampling) {
        std::fprintf(stderr, "raystep bench: --json requires --epsilon or --sampling\n");
        return 2;
    }
    if (arguments.sampling) return run_noise_study(arguments.quick, arguments.json);
    if (arguments.pareto) {
        const std::vector<ParetoStudy>& studies = ParetoStudyRegistry::entries();
        if (studies.empty()) {
            std::fprintf(stderr,
                         "raystep bench --pareto: the study measures the reference's tests in "
                         "double and float, which only raystep-reference links: run "
                         "raystep-reference bench --pareto\n");
            return 1;
        }
        return studies.front()({arguments.cases, arguments.out, arguments.quick});
    }
    std::vector<BenchCandidate> candidates = our_structures();
    if (!add_baselines(arguments.embree_isa, candidates)) {
        std::fprintf(stderr,
                     "raystep bench --embree-isa: this build has no Embree to hold to %s; Embree "
                     "is linked only into raystep-reference, where libembree-dev is installed\n",
                     arguments.embree_isa.c_str());
        return 1;
    }

    MeasureOptions options;
    options.threads = arguments.threads > 0
                          ? arguments.threads
                          : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    if (arguments.quick) options.test_budget *= kQuickFraction;
    const ProgressLine progress;
    options.progress = [&](const std::string& what) { progress.show(what); };
    print_header(options.threads, candidates);

    // Nothing named: every workload, the growth table and the threshold
    const bool everything = arguments.workloads.empty() && !arguments.growth &&
                            !arguments.threshold && !arguments.epsilon && !arguments.scale;
    bool agreed = true;
    if (everything || !arguments.workloads.empty()) {
        for (const std::string& name : bench_scene_names()) {
            if (!scene_selected(name, arguments.workloads)) continue;
            options.progress = [&](const std::string& what) { progress.show(name + ": " + what); };
            agreed = run_scene(name, arguments, candidates, options) && agreed;
        }
    }
    if (everything || arguments.growth) {
        options.progress = [&](const std::string& what) { progress.show("growth: " + what); };
        run_growth(arguments, candidates, options);
    }
    if (everything || arguments.threshold) run_threshold(arguments);
    if (everything || arguments.epsilon) run_epsilon(arguments);
    if (everything || arguments.scale) {
        ProgressLine().show("the scale bars");
        run_scale_bars(source_tree() / "scenes/scale", options.threads, arguments.quick);
        ProgressLine().clear();
    }

    if (!agreed) {
        std::printf("\nStructures disagree (the WARNING lines above): one of them has a bug.\n");
        return 1;
    }
    return 0;
}

namespace {

// `raystep bench`, added to whichever program links this file: both `raystep` and
// raystep-reference in the instructor's repository, neither in a student release.
AddedCommand add_bench(CLI::App& app) {
    auto arguments = std::make_shared<BenchArguments>();
    CLI::App* command = add_bench_command(app, *arguments);
    return {command, [arguments] { return run_bench(*arguments); }};
}

const CommandRegistry::Registration kRegistration(add_bench);

}  // namespace

}  // namespace raystep
