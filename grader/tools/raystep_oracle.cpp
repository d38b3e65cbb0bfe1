// raystep-oracle: the instructor's tool for stage 3's cases.
//
//   raystep-oracle cases [--family NAME]... [--seed S] [--count N] --folder DIR
//       generates each family's cases, decides them with the exact oracle, and writes one case
//       file per family (DIR/NAME.cases), as `raystep check` reads them.
//   raystep-oracle study [--count N] [--watertight-count N] [--seed S] [--threads T]
//       runs every reference method (the lecture's three triangle tests, Möller-Trumbore, the
//       watertight test, three ray-sphere forms, the plane, closest_hit) on every family and
//       prints a Markdown table of what each gets right: docs/stage3.md's measurements.
//   raystep-oracle tolerances [--count N] [--seeds K] [--seed S] [--threads T]
//       decides each family from seeds S to S + K - 1 and prints, per family, how many
//       primitives are near a boundary, the largest normal tolerance and how many tolerances are
//       not finite: how tight the oracle is (docs/measurements/stage3-oracle.md).

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/check/case_file.h"
#include "app/check/case_scoring.h"
#include "app/check/check_report.h"
#include "app/check/stage3_methods.h"
#include "grading/3_intersect/decide_cases.h"
#include "grading/3_intersect/stage3_families.h"
#include "solutions/3_intersect/intersect_methods.h"

namespace raystep {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// The families to work on: the named ones, or all.
std::vector<const Stage3Family*> chosen_families(const std::vector<std::string>& names) {
    std::vector<const Stage3Family*> chosen;
    if (names.empty()) {
        for (const Stage3Family& family : stage3_families())
            chosen.push_back(&family);
        return chosen;
    }
    for (const std::string& name : names) {
        const Stage3Family* family = find_stage3_family(name);
        if (!family) throw std::invalid_argument("no family named '" + name + "'");
        chosen.push_back(family);
    }
    return chosen;
}

// Generates a family and decides it, the cases split over `threads` threads (each case's
// generator and the oracle depend on the case alone, so the result is the same for any count).
CaseFamily decided_family(const Stage3Family& family, std::uint64_t seed, std::size_t count,
                          unsigned threads) {
    CaseFamily cases = generate_cases(family, seed, count);
    std::vector<CaseFamily> parts(threads);
    const std::size_t chunk = (count + threads - 1) / threads;
    for (unsigned t = 0; t < threads; ++t) {
        const std::size_t begin = std::min(count, t * chunk);
        const std::size_t end = std::min(count, begin + chunk);
        parts[t].cases.assign(
            std::make_move_iterator(cases.cases.begin() + static_cast<long>(begin)),
            std::make_move_iterator(cases.cases.begin() + static_cast<long>(end)));
    }
    std::vector<std::thread> workers;
    for (CaseFamily& part : parts) {
        workers.emplace_back([&part, &family] { decide_cases(part, family.t_ulps); });
    }
    for (std::thread& worker : workers)
        worker.join();
    cases.cases.clear();
    for (CaseFamily& part : parts) {
        for (RayCase& ray_case : part.cases)
            cases.cases.push_back(std::move(ray_case));
    }
    return cases;
}

// Every reference method: the student API's, and the solutions' extras.
std::vector<Stage3Method> study_methods() {
    std::vector<Stage3Method> methods = stage3_methods();
    Stage3Method moller_trumbore{"moller_trumbore", Stage3Method::Kind::triangle};
    moller_trumbore.triangle = intersect_triangle_moller_trumbore;
    Stage3Method textbook{"sphere_textbook", Stage3Method::Kind::sphere};
    textbook.sphere = intersect_sphere_textbook;
    Stage3Method stable_roots{"sphere_stable_roots", Stage3Method::Kind::sphere};
    stable_roots.sphere = intersect_sphere_stable_roots;
    // The reference intersect_triangle is the watertight test: name it so in the table.
    for (Stage3Method& method : methods) {
        if (method.name == "intersect_triangle") method.name = "watertight (intersect_triangle)";
        if (method.name == "intersect_sphere") method.name = "sphere reference (intersect_sphere)";
    }
    methods.insert(methods.begin() + 5, moller_trumbore);
    methods.insert(methods.end() - 1, {textbook, stable_roots});
    return methods;
}

std::string percent(std::size_t part, std::size_t whole) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f%%", whole ? 100.0 * part / whole : 0.0);
    return text;
}

std::string ulps(double value) {
    char text[32];
    if (value < 1e6) {
        std::snprintf(text, sizeof text, "%.0f", value);
    } else {
        std::snprintf(text, sizeof text, "%.1e", value);
    }
    return text;
}

int run_cases(const std::vector<std::string>& names, std::uint64_t seed, std::size_t count,
              const std::string& folder, unsigned threads) {
    std::filesystem::create_directories(folder);
    for (const Stage3Family* family : chosen_families(names)) {
        const CaseFamily cases = decided_family(*family, seed, count, threads);
        const std::filesystem::path file = std::filesystem::path(folder) / (cases.name + ".cases");
        std::ofstream out(file);
        out << "# Stage 3 ray cases, decided by the exact oracle. Made by\n"
            << "#   raystep-oracle cases --family " << cases.name << " --seed " << seed
            << " --count " << count << " --folder FOLDER\n"
            << "# The format: docs/case-files.md.\n";
        write_case_file(out, {cases});
        if (!out) throw std::runtime_error("cannot write " + file.string());
        std::printf("wrote %s (%zu cases)\n", file.string().c_str(), cases.cases.size());
    }
    return 0;
}

int run_study(std::uint64_t seed, std::size_t count, std::size_t watertight_count,
              unsigned threads) {
    const std::vector<Stage3Method> methods = study_methods();
    std::size_t checks = 0;
    double oracle_seconds = 0.0;
    std::size_t watertight_rays = 0;
    std::size_t watertight_leaks = 0;

    std::printf(
        "| family | method | cases | pass | false hits | false misses | leaks | wrong t | "
        "other | t ulps median | p99 | max |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    for (const Stage3Family& family : stage3_families()) {
        const bool shared = std::string(family.name).rfind("shared-", 0) == 0;
        const std::size_t n = shared ? watertight_count : count;
        const Clock::time_point start = Clock::now();
        const CaseFamily cases = decided_family(family, seed, n, threads);
        oracle_seconds += seconds_since(start);
        for (const RayCase& ray_case : cases.cases)
            checks += ray_case.primitives.size();

        for (const Stage3Method& method : methods) {
            std::vector<CaseAnswer> answers;
            answers.reserve(cases.cases.size());
            for (const RayCase& ray_case : cases.cases)
                answers.push_back(run_method(method, ray_case));
            const MethodScore score = score_family(method, cases, answers, 0);
            if (score.cases == 0) continue;
            std::size_t other = 0;
            for (const Verdict v :
                 {Verdict::not_finite, Verdict::wrong_normal, Verdict::wrong_barycentrics,
                  Verdict::wrong_primitive, Verdict::threw}) {
                other += score.count(v);
            }
            const UlpSummary u = summarize_ulps(score.t_ulps);
            std::printf("| %s | %s | %zu | %s | %zu | %zu | %zu | %zu | %zu | %s | %s | %s |\n",
                        family.name, method.name.c_str(), score.cases,
                        percent(score.passed, score.cases).c_str(), score.count(Verdict::false_hit),
                        score.count(Verdict::false_miss), score.count(Verdict::leak),
                        score.count(Verdict::wrong_t), other, ulps(u.median).c_str(),
                        ulps(u.p99).c_str(), ulps(u.max).c_str());
            if (shared && method.name.rfind("watertight", 0) == 0) {
                watertight_rays += score.cases;
                watertight_leaks += score.count(Verdict::leak) + score.count(Verdict::false_miss);
            }
        }
        std::fflush(stdout);
    }
    std::printf(
        "\noracle: %zu primitive checks in %.1f s on %u threads (%.0f per second per "
        "thread)\n",
        checks, oracle_seconds, threads, checks / oracle_seconds / threads);
    std::printf(
        "watertight test: %zu rays through shared edges and vertices, %zu false misses "
        "or leaks\n",
        watertight_rays, watertight_leaks);
    return watertight_leaks == 0 ? 0 : 1;
}

// The oracle's tolerances over many seeds: a non-finite one is a bug (docs/stage3.md, "How
// tight the oracle is").
int run_tolerances(std::uint64_t seed, std::size_t seeds, std::size_t count, unsigned threads) {
    std::printf(
        "| family | primitives | near boundary | max normal tolerance | max barycentric "
        "tolerance | max t tolerance / \\|t\\| | not finite |\n");
    std::printf("|---|---|---|---|---|---|---|\n");
    std::size_t not_finite_total = 0;
    for (const Stage3Family& family : stage3_families()) {
        std::size_t primitives = 0;
        std::size_t near = 0;
        std::size_t not_finite = 0;
        double normal = 0.0;
        double barycentric = 0.0;
        double relative_t = 0.0;
        for (std::size_t k = 0; k < seeds; ++k) {
            const CaseFamily cases = decided_family(family, seed + k, count, threads);
            for (const RayCase& ray_case : cases.cases) {
                for (const CasePrimitive& primitive : ray_case.primitives) {
                    const Expectation& e = primitive.expected;
                    ++primitives;
                    near += e.near_boundary ? 1 : 0;
                    if (std::isnan(e.t)) continue;
                    const bool finite = std::isfinite(e.t_tolerance) &&
                                        std::isfinite(e.normal_tolerance) &&
                                        std::isfinite(e.barycentric_tolerance);
                    not_finite += finite ? 0 : 1;
                    normal = std::max(normal, e.normal_tolerance);
                    barycentric = std::max(barycentric, e.barycentric_tolerance);
                    if (e.t != 0.0)
                        relative_t = std::max(relative_t, e.t_tolerance / std::abs(e.t));
                }
            }
        }
        not_finite_total += not_finite;
        std::printf("| %s | %zu | %zu | %.3g | %.3g | %.3g | %zu |\n", family.name, primitives,
                    near, normal, barycentric, relative_t, not_finite);
        std::fflush(stdout);
    }
    return not_finite_total == 0 ? 0 : 1;
}

}  // namespace

}  // namespace raystep

int main(int argc, char** argv) {
    using namespace raystep;
    CLI::App app{"raystep-oracle: exact stage-3 cases, and the study of every reference method",
                 "raystep-oracle"};
    app.require_subcommand(1);
    std::vector<std::string> families;
    std::uint64_t seed = 2026;
    std::size_t count = 100;
    std::size_t watertight_count = 250000;
    std::string folder;
    unsigned threads = std::max(1u, std::thread::hardware_concurrency());

    CLI::App* cases = app.add_subcommand("cases", "Write decided case files, one per family");
    cases->add_option("--family", families, "A family to write (default: all)");
    cases->add_option("--seed", seed, "The families' seed");
    cases->add_option("--count", count, "Cases per family")->check(CLI::Range(1, 10000000));
    cases->add_option("--folder", folder, "Where to write NAME.cases")->required();
    cases->add_option("--threads", threads, "Threads for the oracle")->check(CLI::Range(1, 256));

    CLI::App* study = app.add_subcommand("study", "Measure every reference method on every family");
    study->add_option("--seed", seed, "The families' seed");
    study->add_option("--count", count, "Cases per family")->check(CLI::Range(1, 10000000));
    study
        ->add_option("--watertight-count", watertight_count,
                     "Cases per shared-edge and shared-vertex family")
        ->check(CLI::Range(1, 10000000));
    study->add_option("--threads", threads, "Threads for the oracle")->check(CLI::Range(1, 256));

    std::size_t seeds = 10;
    CLI::App* tolerances =
        app.add_subcommand("tolerances", "Statistics of the oracle's tolerances over many seeds");
    tolerances->add_option("--seed", seed, "The first seed");
    tolerances->add_option("--seeds", seeds, "How many seeds")->check(CLI::Range(1, 100000));
    tolerances->add_option("--count", count, "Cases per family and seed")
        ->check(CLI::Range(1, 10000000));
    tolerances->add_option("--threads", threads, "Threads for the oracle")
        ->check(CLI::Range(1, 256));

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        return app.exit(error) == 0 ? 0 : 2;
    }
    try {
        if (cases->parsed()) return run_cases(families, seed, count, folder, threads);
        if (tolerances->parsed()) return run_tolerances(seed, seeds, count, threads);
        return run_study(seed, count, watertight_count, threads);
    } catch (const std::exception& error) {
        std::fprintf(stderr, "raystep-oracle: %s\n", error.what());
        return 1;
    }
}
