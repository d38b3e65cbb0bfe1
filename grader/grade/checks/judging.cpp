#include "grader/grade/checks/judging.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>

namespace raystep::grade {

namespace {

// The timed comparison's rounds. Each round's ratio of a program's time to the first program's is
// a measurement of the ratio the score reads; on an idle machine two rounds agree within a few
// per cent and a third adds nothing but time, while under a changing load they disagree and more
// rounds give the best times a chance to be the quiet ones. So: two rounds, then more until two in
// a row agree within kRoundAgreement, five at most. The figures behind the choice, and the command
// that re-measures them: docs/measurements/speed-rounds.md.
constexpr int kFewestTimedRounds = 2;
constexpr int kMostTimedRounds = 5;
constexpr double kRoundAgreement = 0.10;

bool rounds_agree(const std::vector<double>& previous, const std::vector<double>& current) {
    if (previous.empty()) return false;
    for (std::size_t p = 1; p < current.size(); ++p) {
        const double a = current[p] / current[0];
        const double b = previous[p] / previous[0];
        if (!(std::abs(a - b) <= kRoundAgreement * std::max(a, b))) return false;
    }
    return true;
}

}  // namespace

CheckDefinition case_check(std::string id, int stage, std::string kind, std::string name,
                           std::function<std::vector<ProbeCase>()> make_cases) {
    return {id, stage, std::move(kind), std::move(name),
            [id, make_cases = std::move(make_cases)](const GradingContext& context,
                                                     const BuiltProbe& probe) {
                return run_cases(context, id, probe, make_cases());
            }};
}

ProbeRunLimits scene_reading_limits(const GradingContext& context) {
    ProbeRunLimits limits;
    limits.readable = {context.source / "scenes"};
    if (context.probes) limits.image_library = context.probes->image_library;
    return limits;
}

std::vector<CheckDefinition> stage_case_checks(const StageCases& cases) {
    const std::string stage = "stage" + std::to_string(cases.stage);
    return {
        case_check(stage + ".unit", cases.stage, "unit", cases.public_name, cases.public_cases),
        case_check(stage + ".hidden", cases.stage, "unit", cases.hidden_name, cases.hidden_cases),
        case_check(stage + ".oracle", cases.stage, "oracle", cases.oracle_name,
                   cases.oracle_cases)};
}

std::vector<WorkloadTime> timed_workloads(const std::vector<WorkloadRun>& runs, int repeat,
                                          int most_rounds) {
    std::vector<WorkloadTime> timed(runs.size());
    // Each program's query made once, only its pass count set for a run: the arguments may hold
    // a mesh, and copying them for every run cost more than the runs.
    std::vector<std::vector<ProbeQuery>> queries;
    for (const WorkloadRun& run : runs)
        queries.push_back({run.query});
    const auto run_once = [&](std::size_t p, int passes) {
        queries[p].front().args["repeat"] = passes;
        ProbeRunLimits limits;
        limits.cpu_seconds = 60;
        limits.wall = std::chrono::seconds(90);
        const ProbeSession session = ask_probe(runs[p].program, queries[p], limits);
        if (session.answers[0].kind != ProbeAnswer::Kind::result) {
            timed[p].answered = false;
            if (session.answers[0].kind == ProbeAnswer::Kind::not_implemented) {
                timed[p].not_implemented = session.answers[0].message;
            }
        } else if (passes > 0) {
            if (!timed[p].checksum.is_null() && timed[p].checksum != session.answers[0].value) {
                timed[p].same_answers = false;
            }
            timed[p].checksum = session.answers[0].value;
        }
        return session.run.cpu_seconds;
    };
    std::vector<double> best(runs.size(), HUGE_VAL);
    std::vector<double> setup(runs.size(), HUGE_VAL);
    std::vector<double> previous;
    int rounds = 0;
    while (rounds < std::min(most_rounds, kMostTimedRounds)) {
        std::vector<double> current(runs.size(), 1.0);
        for (std::size_t p = 0; p < runs.size(); ++p) {
            if (!timed[p].answered) continue;
            const double start = run_once(p, 0);
            const double passes = run_once(p, runs[p].repeat >= 0 ? runs[p].repeat : repeat);
            setup[p] = std::min(setup[p], start);
            best[p] = std::min(best[p], passes);
            current[p] = std::max(1e-6, passes - start);
        }
        ++rounds;
        const bool answered = std::all_of(timed.begin(), timed.end(),
                                          [](const WorkloadTime& t) { return t.answered; });
        // A program that did not answer has no time to agree on: nothing more to measure.
        if (!answered) break;
        if (rounds >= kFewestTimedRounds && rounds_agree(previous, current)) break;
        previous = current;
    }
    for (std::size_t p = 0; p < runs.size(); ++p) {
        timed[p].seconds = std::max(1e-6, best[p] - setup[p]);
        timed[p].rounds = rounds;
    }
    return timed;
}

WorkloadTime timed_workload(const std::filesystem::path& program, const ProbeQuery& query,
                            int repeat) {
    return timed_workloads({{program, query}}, repeat).front();
}

void add_seeded_cases(std::vector<ProbeCase>& cases, std::uint64_t seed, int count,
                      const std::function<ProbeCase(PortableRandom&, int)>& make) {
    for (int k = 0; k < count; ++k) {
        PortableRandom random(seed, cases.size());
        cases.push_back(make(random, k));
    }
}

void add_seeded_case_groups(
    std::vector<ProbeCase>& cases, std::uint64_t seed, int count,
    const std::function<std::vector<ProbeCase>(PortableRandom&, int)>& make) {
    for (int k = 0; k < count; ++k) {
        PortableRandom random(seed, cases.size());
        for (ProbeCase& c : make(random, k))
            cases.push_back(std::move(c));
    }
}

Vec3 uniform(PortableRandom& random, double low, double high) {
    const double x = random.uniform(low, high);
    const double y = random.uniform(low, high);
    return {x, y, random.uniform(low, high)};
}

double result_number(const ProbeAnswer& answer) {
    if (answer.kind != ProbeAnswer::Kind::result) throw std::invalid_argument("no result");
    return probe::number_from(answer.value);
}

Vec3 result_vec3(const ProbeAnswer& answer) {
    if (answer.kind != ProbeAnswer::Kind::result) throw std::invalid_argument("no result");
    return probe::vec3_from(answer.value);
}

Judgement near_number(const ProbeAnswer& answer, double expected, double tolerance) {
    if (answer.kind != ProbeAnswer::Kind::result) return wrong(full_text(expected), "");
    const double got = result_number(answer);
    if (std::abs(got - expected) <= tolerance) return right();
    return wrong(full_text(expected) + " (within " + full_text(tolerance) + ")", full_text(got));
}

Judgement near_vec3(const ProbeAnswer& answer, const Vec3& expected, double tolerance) {
    if (answer.kind != ProbeAnswer::Kind::result) return wrong(full_text(expected), "");
    const Vec3 got = result_vec3(answer);
    for (int k = 0; k < 3; ++k) {
        if (!(std::abs(got[k] - expected[k]) <= tolerance)) {
            return wrong(full_text(expected) + " (within " + full_text(tolerance) + ")",
                         full_text(got));
        }
    }
    return right();
}

Judgement threw(const ProbeAnswer& answer, const std::string& type) {
    if (answer.kind == ProbeAnswer::Kind::threw && answer.exception_type == type) return right();
    return wrong("std::" + type + " thrown", "");
}

}  // namespace raystep::grade
