// `raystep-reference bench --pareto`: the speed-against-error study of docs/stage3.md and the
// cost of the ray offset rules of docs/stage6.md. Registered with the bench command from here
// (pareto_registry.h), and linked only into raystep-reference.

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "app/check/case_file.h"
#include "app/demo/source_tree.h"
#include "studies/common/figures_file.h"
#include "studies/common/machine_description.h"
#include "studies/common/markdown_table.h"
#include "studies/common/number_text.h"
#include "studies/epsilon/epsilon_measure.h"
#include "studies/epsilon/offset_cost.h"
#include "studies/speed_error/pareto_json.h"
#include "studies/speed_error/pareto_reference_methods.h"
#include "studies/speed_error/pareto_registry.h"

namespace raystep {

namespace {

namespace fs = std::filesystem;

// The epsilons at which the fixed offset rules are compared: the lecture's range and below.
const std::vector<double> kOffsetEpsilons = {1e-10, 1e-8, 1e-6, 1e-4, 1e-2};

// The case files named, a folder standing for its *.cases files in name order; stage 3's own
// cases when none is named.
std::vector<fs::path> case_files(const std::vector<std::string>& named) {
    std::vector<fs::path> paths;
    if (named.empty()) {
        return case_files({(source_tree() / "stages/3_intersect/cases").string()});
    }
    for (const std::string& name : named) {
        if (!fs::is_directory(name)) {
            paths.emplace_back(name);
            continue;
        }
        const std::vector<fs::path> in_folder = case_files_in(name);
        paths.insert(paths.end(), in_folder.begin(), in_folder.end());
    }
    return paths;
}

// The errors of `offset` among the epsilon study's counts.
OffsetErrors errors_of(const EpsilonSceneResult& study, const RayOffset& offset) {
    if (offset.rule == OffsetRule::error_bound) return study.error_bound;
    const auto k = static_cast<std::size_t>(
        std::find(study.epsilons.begin(), study.epsilons.end(), offset.epsilon) -
        study.epsilons.begin());
    return offset.rule == OffsetRule::along_ray ? study.along_ray[k] : study.along_normal[k];
}

// Each acne scene (with `quick`, the largest scale's alone): the epsilon study's acne and leaks
// beside the time of each rule's shadow rays.
std::vector<OffsetRuleResult> measure_offset_rules(bool quick, std::string& notes) {
    const fs::path folder = source_tree() / "scenes/stage6";
    std::vector<RayOffset> offsets;
    for (const double epsilon : kOffsetEpsilons)
        offsets.push_back({OffsetRule::along_ray, epsilon});
    for (const double epsilon : kOffsetEpsilons) {
        offsets.push_back({OffsetRule::along_normal, epsilon});
    }
    offsets.push_back({OffsetRule::error_bound, 0.0});

    std::vector<OffsetRuleResult> results;
    std::vector<const char*> scenes = {"acne-scale-1e-3.test", "acne-scale-1.test",
                                       "acne-scale-1e4.test"};
    if (quick) scenes.erase(scenes.begin(), scenes.end() - 1);
    for (const char* name : scenes) {
        const fs::path scene = folder / name;
        std::fprintf(stderr, "  measuring the offset rules on %s\n", name);
        const EpsilonSceneResult study = measure_epsilon_scene(scene, kOffsetEpsilons);
        if (!study.stopped.empty()) throw std::runtime_error(name + (": " + study.stopped));
        double surface_nanoseconds = 0.0;
        const std::vector<OffsetRuleCost> costs =
            measure_offset_costs(scene, offsets, surface_nanoseconds);
        notes += "- " + std::string(name) + ": rebuilding each hit's surface point and its error " +
                 "bound, which every rule starts from, costs " + fixed(surface_nanoseconds, 0) +
                 " ns per primary hit\n";
        for (const OffsetRuleCost& cost : costs) {
            const OffsetErrors errors = errors_of(study, cost.offset);
            results.push_back({fs::path(name).stem().string(),
                               std::string(offset_rule_name(cost.offset.rule)), cost.offset.epsilon,
                               cost.nanoseconds_per_ray, errors.acne, errors.leaks,
                               study.lit + study.shadowed});
        }
    }
    return results;
}

std::string offset_table(const std::vector<OffsetRuleResult>& rows) {
    MarkdownTable table(
        {"scene", "rule", "epsilon", "ns per shadow ray", "acne", "leaks", "decided pixel-lights"});
    for (const OffsetRuleResult& r : rows) {
        char epsilon[32];
        std::snprintf(epsilon, sizeof epsilon, "%g", r.epsilon);
        table.add_row({r.scene, r.rule, r.rule == "error-bound" ? "-" : epsilon,
                       fixed(r.nanoseconds_per_ray, 0), grouped(r.acne), grouped(r.leaks),
                       grouped(r.decided)});
    }
    return table.text();
}

int run_pareto_study(const ParetoOptions& options) {
    const std::string machine = machine_description();
    const std::string date = local_time();
    ParetoTiming timing;
    if (options.quick) {
        timing.sample_seconds = 0.002;
        timing.samples = 2;
    }
    std::printf(
        "raystep bench --pareto: %s; %s\nEvery intersection test in double and in float on the "
        "same decided ray cases: wrong answers against the exact oracle's, t error in double "
        "ulps, and ray-primitive tests per second on one thread (the best of %d samples of %g "
        "s).\n",
        machine.c_str(), date.c_str(), timing.samples, timing.sample_seconds);

    const std::vector<ParetoMethod> methods = reference_pareto_methods();
    std::vector<ParetoFamily> families;
    for (const fs::path& file : case_files(options.cases)) {
        for (const CaseFamily& family : read_case_file(file)) {
            std::fprintf(stderr, "  measuring %s\n", family.name.c_str());
            ParetoFamily measured = measure_pareto_family(family, methods, timing);
            if (measured.points.empty()) {
                std::printf("- %s: no test of the study applies: left out\n", family.name.c_str());
                continue;
            }
            families.push_back(std::move(measured));
        }
    }
    std::printf("\n### speed against error, per family\n\n%s", pareto_table(families).c_str());

    std::string notes;
    const std::vector<OffsetRuleResult> offset_rules = measure_offset_rules(options.quick, notes);
    std::printf("\n### ray offset rules: cost against acne and leaks\n\n%s\n%s",
                offset_table(offset_rules).c_str(), notes.c_str());

    const fs::path out =
        options.out_folder.empty() ? fs::path("pareto") : fs::path(options.out_folder);
    fs::create_directories(out);
    std::printf("\n");
    write_figures(out / "pareto.json", pareto_json(machine, date, families, offset_rules));
    return 0;
}

const ParetoStudyRegistry::Registration kRegistration(run_pareto_study);

}  // namespace

}  // namespace raystep
