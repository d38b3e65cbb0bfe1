#include "grader/grade/checks/judging.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>

namespace raystep::grade {

CheckDefinition case_check(std::string id, int stage, std::string kind, std::string name,
                           std::function<std::vector<ProbeCase>()> make_cases) {
    return {id, stage, std::move(kind), std::move(name),
            [id, make_cases = std::move(make_cases)](const GradingContext& context,
                                                     const BuiltProbe& probe) {
                return run_cases(context, id, probe, make_cases());
            }};
}

std::vector<CheckDefinition> stage_case_checks(const StageCases& cases) {
    const std::string stage = "stage" + std::to_string(cases.stage);
    return {
        case_check(stage + ".unit", cases.stage, "unit", cases.public_name, cases.public_cases),
        case_check(stage + ".hidden", cases.stage, "unit", cases.hidden_name, cases.hidden_cases),
        case_check(stage + ".oracle", cases.stage, "oracle", cases.oracle_name,
                   cases.oracle_cases)};
}

std::vector<WorkloadTime> timed_workloads(const std::vector<WorkloadRun>& runs,
                                          const std::string& call, int repeat) {
    std::vector<WorkloadTime> timed(runs.size());
    const auto run_once = [&](std::size_t p, int passes) {
        probe::Json a = runs[p].args;
        a["repeat"] = passes;
        ProbeRunLimits limits;
        limits.cpu_seconds = 60;
        limits.wall = std::chrono::seconds(90);
        const ProbeSession session = ask_probe(runs[p].program, {{call, a}}, limits);
        if (session.answers[0].kind != ProbeAnswer::Kind::result) {
            timed[p].answered = false;
            if (session.answers[0].kind == ProbeAnswer::Kind::not_implemented) {
                timed[p].not_implemented = session.answers[0].message;
            }
        } else if (passes > 0) {
            timed[p].checksum = session.answers[0].value;
        }
        return session.run.wall_seconds;
    };
    std::vector<double> best(runs.size(), HUGE_VAL);
    std::vector<double> setup(runs.size(), HUGE_VAL);
    for (int round = 0; round < 3; ++round) {
        for (std::size_t p = 0; p < runs.size(); ++p) {
            if (!timed[p].answered) continue;
            setup[p] = std::min(setup[p], run_once(p, 0));
            best[p] = std::min(best[p], run_once(p, repeat));
        }
    }
    for (std::size_t p = 0; p < runs.size(); ++p)
        timed[p].seconds = std::max(1e-6, best[p] - setup[p]);
    return timed;
}

WorkloadTime timed_workload(const std::filesystem::path& program, const std::string& call,
                            const probe::Json& args, int repeat) {
    return timed_workloads({{program, args}}, call, repeat).front();
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

bool near(const Vec3& got, const WideVec& expected, const WideVec& tolerance) {
    for (int k = 0; k < 3; ++k) {
        if (!(std::abs(got[k] - expected[k]) <= tolerance[k])) return false;
    }
    return true;
}

Judgement threw(const ProbeAnswer& answer, const std::string& type) {
    if (answer.kind == ProbeAnswer::Kind::threw && answer.exception_type == type) return right();
    return wrong("std::" + type + " thrown", "");
}

}  // namespace raystep::grade
