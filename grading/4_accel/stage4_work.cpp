// A structure earns its points by doing less work than brute force, and nothing that runs in the
// probe's process can say how much work that is: a submission's code runs there before, during and
// after the protocol, and can write any counter (docs/instructor.md, "What student code can
// touch"). So the work is measured twice, from outside:
//
// 1. The structure, handed back as data (Bvh::nodes, UniformGrid::cells), is checked here against
//    the primitives (stage4_structure.h) and walked here by the lecture's traversal: the nodes and
//    primitive tests per ray are the grader's count, on the strewn scene below, against the
//    reference structure's walked the same way. The allowance: kWorkAllowance times the
//    reference's count, or one per kBruteForceShare primitives per ray, whichever is more; the
//    second is room for a right structure of a plainer design (a median split, larger leaves, a
//    coarser grid). A single leaf of everything, a grid of one cell, or a tree that is not one
//    fails here.
// 2. The submission's own walk, timed by the kernel (the probe's CPU time, every thread of it,
//    taken by the sandbox when the probe ends) on rays that change every pass, through kWalls
//    walls that no ray crosses without a hit, from above and from below, against its own walk of
//    such rays through one wall. A walk that visits the nearer node first and stops at the
//    nearest hit takes about as long (a tree a few levels deeper, a finer grid); one that goes on
//    past the hit visits every wall behind it; one that visits children in a fixed order takes the
//    far half of every node first for rays from one side; and one that tests every primitive, or
//    sorts every box for every ray, takes time in proportion to the walls. The ratio is the walk's
//    own, whatever its constant costs. Allowed: kDepthAllowance. And since a program that can
//    tell the one-wall runs from the others could slow those on purpose, the walk through the
//    walls also against the reference's walk of such rays, timed in the grader, which nothing in
//    the probe can slow: there are enough walls that every wrong walk above takes over a hundred
//    times it, however the runs compare, and a right one a few. Allowed: kBruteForceAllowance. A
//    scene whose timed runs spent under a quarter of the time asked, its passes set by a run a load
//    had slowed, is timed again with more passes, once. A grid without a mailbox is not caught
//    here: with this course's primitives a test costs about what a mailbox's lookup does, so no
//    time can tell (docs/measurements/stage4-work.md).
//
// Both are measured once per structure (the BVH with each split, the grid) and shared by the checks
// that ask: the closest hit, occluded and speed checks of one structure stand on the same work.
// docs/measurements/stage4-work.md has the counts and times behind the allowances.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <optional>
#include <string>
#include <vector>

#include "grader/grade/checks/cpp_literal.h"
#include "grader/grade/checks/judging.h"
#include "grader/grade/checks/made_once.h"
#include "grading/4_accel/accel_workloads.h"
#include "grading/4_accel/stage4_cases.h"
#include "grading/4_accel/stage4_structure.h"
#include "grading/4_accel/stage4_work_scenes.h"
#include "grading/4_accel/structure_json.h"
#include "grading/4_accel/timed_walk.h"

namespace raystep::grade {

namespace {

using probe::Json;

constexpr double kWorkAllowance = 4.0;
constexpr double kBruteForceShare = 16.0;
constexpr double kDepthAllowance = 10.0;
constexpr double kBruteForceAllowance = 40.0;
// The walls the walk is timed through: enough that a walk past the nearest hit costs a hundred
// times the reference's walk, so that the reference's time alone tells it from a right one.
constexpr int kWalls = 768;
// The timed runs' length: long enough that the CPU time of a start (a few ms, which the run with
// no passes takes away) varies by a few per cent of it; the first run's passes; the rounds, whose
// best is taken, since a loaded machine (a CI runner grading two submissions at once) inflates a
// run's CPU time now and then, by up to five times here; and a bound on the passes of a walk so
// cheap that even these take no time. docs/measurements/stage4-work.md has the runs.
constexpr double kTimedSeconds = 0.1;
constexpr int kCalibrationPasses = 4;
constexpr int kTimedRounds = 3;
constexpr int kMostPasses = 1000;
// How many times the rounds may run: again once, where a scene's passes took too little time.
constexpr int kTimings = 2;
// The shortest walk of the reference's that its time per pass is taken from (timed in the grader,
// in nanoseconds of the thread's CPU time).
constexpr double kReferenceSeconds = 0.02;
// The processor time one structure's timed runs may take in all. A right walk's some fifty runs
// take about 2 s of it (each at most kTimedSeconds of passes and a start), a loaded machine's up
// to five times that; a program that spends its time elsewhere, burning the processor in its runs
// of no passes (which the calibration answers with a hundred times the passes), would otherwise
// hold its grade, and a class's batch, for minutes. docs/measurements/stage4-work.md has the runs.
constexpr double kWalkBudgetSeconds = 20.0;

// What is left of kWalkBudgetSeconds for one structure's timed runs, and what the last run of no
// passes (the query read, the scene and the structure built) took.
struct WalkBudget {
    double seconds = kWalkBudgetSeconds;
    double start = 0.0;
};

CheckMeasure failed(std::string summary) {
    CheckMeasure measure;
    measure.outcome = Outcome::failed;
    measure.summary = std::move(summary);
    return measure;
}

// Why a run gave no readable answer, in a few words.
std::string why_unanswered(const ProbeSession& session, const ProbeAnswer& answer) {
    if (!answer.message.empty()) return answer.message;
    if (session.run.timed_out) return "it ran out of time";
    if (session.run.signal != 0) {
        const std::string limit = limit_of_signal(session.run.signal);
        return "it died of signal " + std::to_string(session.run.signal) +
               (limit.empty() ? "" : ": " + limit);
    }
    return "no readable answer";
}

double mean(const std::vector<std::uint64_t>& counts) {
    double sum = 0.0;
    for (const std::uint64_t count : counts)
        sum += double(count);
    return counts.empty() ? 0.0 : sum / double(counts.size());
}

// 1. The structure as data, checked and walked here, against the reference structure's walk.
CheckMeasure measure_structure_data(const GradingContext& context, const BuiltProbe& probe,
                                    const WorkQuery& query) {
    const WorkScene scene = strewn_scene();
    const bool bvh = query.call == "bvh";
    const probe::StructureBuildQuestion question{
        scene.primitives,
        query.split.empty() ? std::nullopt : std::optional<std::string>(query.split)};
    ProbeRunLimits limits;
    limits.cpu_seconds = 30;
    limits.wall = std::chrono::seconds(60);
    const ProbeSession session =
        ask_probe(*probe.program,
                  {bvh ? probe::query(probe::bvh_structure_call, question)
                       : probe::query(probe::grid_structure_call, question)},
                  limits);
    const ProbeAnswer& answer = session.answers[0];
    if (answer.kind == ProbeAnswer::Kind::not_implemented) {
        CheckMeasure measure;
        measure.outcome = Outcome::not_implemented;
        measure.summary = answer.message;
        return measure;
    }
    const std::string what = bvh ? "Bvh::nodes()" : "UniformGrid::cells()";
    if (answer.kind != ProbeAnswer::Kind::result) {
        return failed("the structure could not be read as data from " + what + " (" +
                      why_unanswered(session, answer) + ")");
    }

    // Checked, then walked here; the reference's structure walked the same way
    const BvhSplit split = query.split == "median" ? BvhSplit::median : BvhSplit::sah;
    std::optional<std::string> problem;
    WalkCost cost;
    WalkCost reference;
    try {
        if (bvh) {
            const std::vector<BvhNodeData> nodes = probe::bvh_nodes_from(answer.value);
            problem = bvh_problem(nodes, scene.primitives);
            if (!problem) cost = walk_bvh(nodes, scene.primitives, scene.rays);
            reference =
                walk_bvh(Bvh(scene.primitives, split).nodes(), scene.primitives, scene.rays);
        } else {
            const UniformGridData grid = probe::uniform_grid_data_from(answer.value);
            problem = grid_problem(grid, scene.primitives);
            if (!problem) cost = walk_grid(grid, scene.primitives, scene.rays);
            reference =
                walk_grid(UniformGrid(scene.primitives).cells(), scene.primitives, scene.rays);
        }
    } catch (const std::exception& error) {
        problem = std::string("its data cannot be read: ") + error.what();
    }
    if (problem) {
        CheckMeasure measure = failed("the structure that " + what + " hands over is not a " +
                                      (bvh ? "BVH" : "grid") + " over its primitives: " + *problem);
        measure.counterexamples.push_back(
            {scene.name,
             bvh ? "a tree whose boxes hold every primitive"
                 : "a grid whose cells list every "
                   "primitive they overlap",
             *problem, context.reproduce + " --check " + query.check_id,
             "// build the structure over the grader's scene and check " + what});
        return measure;
    }

    // Against the reference's walk and brute force's
    const double brute_force =
        double(scene.primitives.spheres.size() + scene.primitives.triangles.size());
    const double floor = brute_force / kBruteForceShare;
    const double tests = mean(cost.tests);
    const double nodes = mean(cost.nodes);
    const double reference_tests = mean(reference.tests);
    const double reference_nodes = mean(reference.nodes);
    const double allowed_tests = std::max(kWorkAllowance * reference_tests, floor);
    const double allowed_nodes = std::max(kWorkAllowance * reference_nodes, floor);
    char text[320];
    std::snprintf(text, sizeof text,
                  "walked by the grader, the structure costs %.1f primitive tests and %.1f %s per "
                  "ray through %.0f primitives, where the reference's costs %.1f and %.1f",
                  tests, nodes, bvh ? "nodes" : "cells", brute_force, reference_tests,
                  reference_nodes);
    CheckMeasure measure;
    measure.metrics = {{"primitive tests per ray (grader's walk)", tests},
                       {std::string(bvh ? "nodes" : "cells") + " per ray (grader's walk)", nodes},
                       {"reference's primitive tests per ray", reference_tests}};
    measure.summary = text;
    if (tests <= allowed_tests && nodes <= allowed_nodes) {
        measure.outcome = Outcome::passed;
        measure.fraction = 1.0;
        return measure;
    }
    char allowance[160];
    std::snprintf(allowance, sizeof allowance,
                  ": more than the %.1f tests and %.1f %s a structure may cost", allowed_tests,
                  allowed_nodes, bvh ? "nodes" : "cells");
    measure.outcome = Outcome::failed;
    measure.summary += allowance;
    return measure;
}

// The query of a timed walk of the walls scene `walls` through the structure `call` (the BVH by
// the SAH), which the probe makes itself: a query of a few bytes, where the scene as data, 1.4 MB,
// took most of every run's start to write here and parse there. Each run sets its passes.
ProbeQuery walk_query(const probe::WallsScene& walls, const std::string& call,
                      const probe::Jitter& jitter) {
    const bool bvh = call == "bvh";
    probe::WorkloadQuestion walk;
    walk.split = bvh ? std::optional<std::string>("sah") : std::nullopt;
    walk.walls = walls;
    walk.jitter = jitter;
    return bvh ? probe::query(probe::bvh_workload_call, walk)
               : probe::query(probe::grid_workload_call, walk);
}

// The CPU time of the calling thread, in seconds.
double thread_seconds() {
    timespec now{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
    return double(now.tv_sec) + 1e-9 * double(now.tv_nsec);
}

// The reference structure for `call` over the scene, built once, and its timed walk: what the
// probe's walk must answer, and how long the reference's took, timed here in the grader (its
// thread's CPU time). The grader is the reference's own program, so no probe need run for it.
class ReferenceWalk {
  public:
    ReferenceWalk(const WorkScene& scene, const std::string& call, const probe::Jitter& jitter)
        : scene_(scene), shadows_(shadow_rays(scene)), jitter_(jitter) {
        if (call == "bvh") {
            bvh_.emplace(scene.primitives, BvhSplit::sah);
        } else {
            grid_.emplace(scene.primitives);
        }
    }

    // The digest of `passes` passes, and their CPU time in `seconds`.
    std::uint64_t digest(int passes, double& seconds) const {
        const double before = thread_seconds();
        const std::uint64_t digest =
            bvh_ ? probe::timed_walk(*bvh_, scene_.rays, shadows_, jitter_, passes)
                 : probe::timed_walk(*grid_, scene_.rays, shadows_, jitter_, passes);
        seconds = thread_seconds() - before;
        return digest;
    }

  private:
    const WorkScene& scene_;
    std::vector<Ray> shadows_;
    probe::Jitter jitter_;
    std::optional<Bvh> bvh_;
    std::optional<UniformGrid> grid_;
};

// The CPU time of one run of the probe on `walk` (one workload query) with `passes` passes, as the
// kernel accounts it for the single-process probe; nullopt when the run gave no result (a stub, a
// crash, a timeout), with the answer kept in `answer`. The query is made once; each run sets its
// pass count.
std::optional<double> cpu_seconds(const BuiltProbe& probe, std::vector<ProbeQuery>& walk,
                                  int passes, WalkBudget& budget, ProbeAnswer& answer) {
    if (budget.seconds <= 0.0) return std::nullopt;
    walk.front().args["repeat"] = passes;
    ProbeRunLimits limits;
    // The sandbox counts whole seconds of processor, at least one.
    limits.cpu_seconds = std::max(1.0, std::min(30.0, std::ceil(budget.seconds)));
    limits.wall = std::chrono::seconds(60);
    const ProbeSession session = ask_probe(*probe.program, walk, limits);
    budget.seconds -= session.run.cpu_seconds;
    if (passes == 0) budget.start = session.run.cpu_seconds;
    answer = session.answers[0];
    if (answer.kind != ProbeAnswer::Kind::result || budget.seconds <= 0.0) return std::nullopt;
    return session.run.cpu_seconds;
}

// How many passes of `walk` take about kTimedSeconds, from runs of kCalibrationPasses passes and
// more, eightfold each time, until a run spends a tenth of that beyond the run with no passes;
// nullopt, with the answer, when a run gave no result.
std::optional<int> calibrated_passes(const BuiltProbe& probe, std::vector<ProbeQuery>& walk,
                                     WalkBudget& budget, ProbeAnswer& answer) {
    const std::optional<double> start = cpu_seconds(probe, walk, 0, budget, answer);
    if (!start) return std::nullopt;
    for (int passes = kCalibrationPasses;; passes = std::min(8 * passes, kMostPasses)) {
        const std::optional<double> run = cpu_seconds(probe, walk, passes, budget, answer);
        if (!run) return std::nullopt;
        const double spent = *run - *start;
        if (spent >= 0.1 * kTimedSeconds || passes >= kMostPasses) {
            const double per_pass = std::max(spent, 1e-6) / passes;
            return static_cast<int>(
                std::clamp(std::ceil(kTimedSeconds / per_pass), 1.0, double(kMostPasses)));
        }
    }
}

// 2. The submission's own walk, timed by the kernel through the walls, from above and from below,
// against its own walk through one wall.
CheckMeasure measure_traversal_time(const BuiltProbe& probe, const std::string& call,
                                    const probe::Jitter& jitter) {
    const probe::WallsScene walls[] = {
        {kWalls, Side::above}, {kWalls, Side::below}, {1, Side::both}};
    const WorkScene above = walls_scene(walls[0].layers, walls[0].side);
    const WorkScene below = walls_scene(walls[1].layers, walls[1].side);
    const WorkScene wall = walls_scene(walls[2].layers, walls[2].side);
    const WorkScene* const scenes[] = {&above, &below, &wall};
    const ReferenceWalk references[] = {
        {above, call, jitter}, {below, call, jitter}, {wall, call, jitter}};
    std::vector<ProbeQuery> walks[3];
    int passes[3];
    WalkBudget budget;
    ProbeAnswer answer;
    const auto unanswered = [&](const WorkScene& scene) {
        if (budget.seconds <= 0.0) {
            char text[300];
            std::snprintf(text, sizeof text,
                          "its timed runs took more than the %.0f s of processor they are given "
                          "in all, before the rays of %s were timed (its last run of no passes, "
                          "which builds the structure, %.2f s)",
                          kWalkBudgetSeconds, scene.name.c_str(), budget.start);
            return failed(std::string(text) +
                          ": a right walk's take a few seconds; a walk that tests every "
                          "primitive, or a program that spends its time outside the walk, can "
                          "take that long");
        }
        if (answer.kind == ProbeAnswer::Kind::not_implemented) {
            CheckMeasure stub;
            stub.outcome = Outcome::not_implemented;
            stub.summary = answer.message;
            return stub;
        }
        return failed("its own walk did not finish the timed rays of " + scene.name + " (" +
                      answer_text(answer) +
                      "): a walk that does not stop at the nearest hit, or tests every primitive, "
                      "can be that slow");
    };
    for (int k = 0; k < 3; ++k) {
        walks[k] = {walk_query(walls[k], call, jitter)};
        const std::optional<int> calibrated = calibrated_passes(probe, walks[k], budget, answer);
        if (!calibrated) return unanswered(*scenes[k]);
        passes[k] = *calibrated;
    }

    // The scenes in turn, round after round, each time with its run of no passes: a load that
    // comes and goes slows them alike, and the best of the rounds is the quietest. Every answer,
    // the digest of every hit of every pass, must be the reference's.
    std::uint64_t expected[3];
    double reference_seconds[3];
    double start[3];
    double run[3];
    for (int timing = 0; timing < kTimings; ++timing) {
        for (int k = 0; k < 3; ++k) {
            expected[k] = references[k].digest(passes[k], reference_seconds[k]);
            start[k] = run[k] = HUGE_VAL;
        }
        for (int round = 0; round < kTimedRounds; ++round) {
            for (int k = 0; k < 3; ++k) {
                for (const int asked : {0, passes[k]}) {
                    const std::optional<double> seconds =
                        cpu_seconds(probe, walks[k], asked, budget, answer);
                    if (!seconds) return unanswered(*scenes[k]);
                    const std::uint64_t digest = asked == 0 ? probe::kEmptyDigest : expected[k];
                    if (answer.value != Json(digest)) {
                        return failed("its own walk answered the timed rays of " + scenes[k]->name +
                                      " otherwise than the reference: the digest of its " +
                                      std::to_string(asked) + " passes' answers is " +
                                      answer_text(answer) + ", the reference's " +
                                      std::to_string(digest));
                    }
                    (asked == 0 ? start[k] : run[k]) =
                        std::min(asked == 0 ? start[k] : run[k], *seconds);
                }
            }
        }
        // A scene whose passes spent under a quarter of kTimedSeconds was calibrated on a run
        // that a load slowed: too few passes, whose time the start's noise can swamp (a right
        // walk then measures 15, or 12,000, times its one wall). Its passes are set again from
        // these rounds, up to a hundredfold, and every scene is timed again. Not at half: the
        // grader's own second job slows the calibration that much, and timing again then costs
        // a loaded grading seconds (docs/measurements/stage4-work.md).
        bool timed_again = false;
        for (int k = 0; k < 3 && timing + 1 < kTimings; ++k) {
            const double spent = run[k] - start[k];
            if (spent >= 0.25 * kTimedSeconds || passes[k] >= kMostPasses) continue;
            const double per_pass = std::max(spent, 0.01 * kTimedSeconds) / passes[k];
            passes[k] = static_cast<int>(
                std::clamp(std::ceil(kTimedSeconds / per_pass), 1.0, double(kMostPasses)));
            timed_again = true;
        }
        if (!timed_again) break;
    }
    double per_pass[3];
    for (int k = 0; k < 3; ++k)
        per_pass[k] = std::max(run[k] - start[k], 1e-6) / passes[k];

    const double depth = std::max(per_pass[0], per_pass[1]) / per_pass[2];
    // Against the reference with nothing taken away: a program that slowed its runs of no passes
    // on purpose could shrink the difference above, never its whole time. The reference's time is
    // its walk of the same passes, the one that gave the expected digest, or, where that took
    // under kReferenceSeconds (a slow walk asked few passes, whose time a pass's fixed costs
    // would swell), a walk of as many more as fill it. A load can only lengthen it, which lowers
    // the ratio; brute force's stays far above the allowance even so
    // (docs/measurements/stage4-work.md).
    double reference_per_pass = reference_seconds[0] / passes[0];
    if (reference_seconds[0] < kReferenceSeconds) {
        const int more = static_cast<int>(
            std::clamp(std::ceil(kReferenceSeconds / std::max(reference_per_pass, 1e-9)), 1.0,
                       double(kMostPasses)));
        double seconds = 0.0;
        references[0].digest(more, seconds);
        reference_per_pass = seconds / more;
    }
    const double against_reference = run[0] / passes[0] / std::max(reference_per_pass, 1e-12);
    CheckMeasure measure;
    measure.metrics = {{"walk CPU time, " + std::to_string(kWalls) + " walls against 1", depth},
                       {"walk CPU time, from above against from below", per_pass[0] / per_pass[1]},
                       {"walk CPU time against the reference's, in the grader", against_reference},
                       {"timed runs' CPU seconds in all", kWalkBudgetSeconds - budget.seconds}};
    char text[300];
    std::snprintf(text, sizeof text,
                  "its own walk (%zu rays a pass, new every pass, CPU time per pass) took %.2f "
                  "times as long through %d walls, from the dearer side, as through one, and "
                  "%.1f times the reference's",
                  above.rays.size(), depth, kWalls, against_reference);
    measure.summary = text;
    std::string broken;
    if (depth > kDepthAllowance) {
        broken = ": more than the " + std::to_string(int(kDepthAllowance)) +
                 " times a walk that visits the nearer node first and stops at the nearest hit "
                 "may take for the walls behind it";
    } else if (against_reference > kBruteForceAllowance) {
        broken = ": more than the " + std::to_string(int(kBruteForceAllowance)) +
                 " times the reference's that any structure's walk takes (one that goes on past "
                 "the nearest hit, or tests every primitive, takes over a hundred)";
    }
    measure.outcome = broken.empty() ? Outcome::passed : Outcome::failed;
    measure.fraction = broken.empty() ? 1.0 : 0.0;
    measure.summary += broken;
    return measure;
}

// `measure()`, once per `key` in this grader: checks that stand on the same measurement share it,
// and may ask for it at once from several threads.
template <class Measure>
CheckMeasure measured_once(const std::string& key, Measure measure) {
    static MadeOnce<CheckMeasure> measured;
    return measured.get(key, measure);
}

}  // namespace

probe::Jitter timed_walk_jitter(const GradingContext& context) {
    return {context.timed_walk_seed, 1e-3, 1e-4};
}

CheckMeasure measure_work(const GradingContext& context, const BuiltProbe& probe,
                          const WorkQuery& query) {
    if (!probe.program) return not_compiled(probe);
    // The structure of each split on its own; the walk, which both splits share, once
    const std::string program = probe.program->string() + "\n" + query.call;
    const CheckMeasure data = measured_once(program + "\n" + query.split, [&] {
        return measure_structure_data(context, probe, query);
    });
    if (data.outcome != Outcome::passed) return data;
    CheckMeasure time = measured_once(program, [&] {
        return measure_traversal_time(probe, query.call, timed_walk_jitter(context));
    });
    for (const auto& [name, value] : data.metrics)
        time.metrics[name] = value;
    time.summary = data.summary + "; " + time.summary;
    return time;
}

}  // namespace raystep::grade
