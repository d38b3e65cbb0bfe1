#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "base/math/portable_random.h"
#include "grader/grade/check_definition.h"
#include "grader/grade/checks/case_text.h"

namespace raystep::grade {

// Judges shared by the stages' checks: a probe's answer against the grader's expectation.

/// The student release's raystep, as the handouts run it from the repository's root: the
/// program a student's reproduce line calls.
inline constexpr const char* kStudentRaystep = "build/student/bin/raystep";

/// What a render's probe reads: the work copy of scenes/, and the image library its textures load
/// through (ProbeSet::image_library, where the context has probes).
ProbeRunLimits scene_reading_limits(const GradingContext& context);

/// A check that sends the probe of `stage` the cases `make_cases` writes and judges each answer
/// (run_cases); the cases are made when the check runs, not when the checks are listed.
CheckDefinition case_check(std::string id, int stage, std::string kind, std::string name,
                           std::function<std::vector<ProbeCase>()> make_cases);

/// A stage's cases as the three checks every case-checked stage has, and the names the report
/// gives them: the public hand-worked cases, the hidden ones (the contract's edges) and the
/// generated ones judged against an oracle.
struct StageCases {
    int stage = 0;
    std::string public_name;
    std::function<std::vector<ProbeCase>()> public_cases;
    std::string hidden_name;
    std::function<std::vector<ProbeCase>()> hidden_cases;
    std::string oracle_name;
    std::function<std::vector<ProbeCase>()> oracle_cases;
};

/// The three checks, "stageN.unit" and "stageN.hidden" of kind "unit" and "stageN.oracle" of
/// kind "oracle", each a case_check.
std::vector<CheckDefinition> stage_case_checks(const StageCases& cases);

/// A workload timed from outside the probe, in CPU time as the kernel accounted it for the probe's
/// whole run (every thread; a probe may start no process): the best of its rounds' runs minus the
/// same run with no passes (starting, reading the input, building), and the checksum the passes
/// answered.
struct WorkloadTime {
    double seconds = 0.0;
    int rounds = 0;  ///< the rounds timed_workloads ran, all programs alike
    probe::Json checksum;
    bool answered = true;  ///< false when a run ended without an answer (a stub, crash or timeout)
    /// false when the runs with passes did not all answer the same: the checksum is then none of
    /// them, and the time not one of a right walk's
    bool same_answers = true;
    std::string not_implemented;  ///< a stub's message, when a stub was why
};

/// Asks `program` the `call` with `args` and "repeat" set to `repeat` passes, and to 0.
WorkloadTime timed_workload(const std::filesystem::path& program, const ProbeQuery& query,
                            int repeat);

/// One program of a timed comparison, and its query of a workload call, whose `repeat` each run
/// sets (programs compared on the same work may still be asked for it differently, as stage 3
/// asks for two triangle tests).
struct WorkloadRun {
    std::filesystem::path program;
    ProbeQuery query;
    int repeat = -1;  ///< the passes this program runs; -1 for the call's `repeat`
};

/// The same for several programs, timed in turn: each round runs every program once, so that a
/// load that comes and goes (another job on the machine) slows them alike and their ratio holds;
/// timed one after the other, a load during one program's runs alone skews it. Two rounds at
/// least; then another, up to `most_rounds` (kMostTimedRounds, 5, by default), until two rounds in
/// a row give every program's
/// time against the first's within kRoundAgreement of each other (judging.cpp says why).
std::vector<WorkloadTime> timed_workloads(const std::vector<WorkloadRun>& runs, int repeat,
                                          int most_rounds = 5);

/// Appends `count` generated cases, the k-th (k from 0) made by `make(random, k)` from a
/// generator of its own, PortableRandom(seed, i) with i the index the case gets in `cases`, so
/// that `--case i` rebuilds that case alone on any platform.
void add_seeded_cases(std::vector<ProbeCase>& cases, std::uint64_t seed, int count,
                      const std::function<ProbeCase(PortableRandom&, int)>& make);

/// The same for makers of several cases at a time (a ray, a point and a normal under one
/// transform): each group is drawn from the generator of its first case's index.
void add_seeded_case_groups(
    std::vector<ProbeCase>& cases, std::uint64_t seed, int count,
    const std::function<std::vector<ProbeCase>(PortableRandom&, int)>& make);

/// A random point from a case's own generator, the same on every platform: each component
/// uniform in [low, high), drawn x, y, z in that order.
Vec3 uniform(PortableRandom& random, double low, double high);

/// The result as a number, vector or ray; throws (an unreadable answer) when it is not one.
double result_number(const ProbeAnswer& answer);
Vec3 result_vec3(const ProbeAnswer& answer);

/// Within `tolerance` of the expected number (absolute).
Judgement near_number(const ProbeAnswer& answer, double expected, double tolerance);

/// Every component within `tolerance` of the expected vector's (absolute); written so that a
/// NaN fails.
Judgement near_vec3(const ProbeAnswer& answer, const Vec3& expected, double tolerance);

/// The judge of a call whose answer is one value: wrong, with nothing got, when the call gave no
/// result; else the result read by `read` (probe::vec3_from, probe::ray_from, ...), right when
/// `accept` takes it, else wrong with it written by `describe`. `expected` says what was wanted.
template <typename Read, typename Accept, typename Describe>
Judgement judge_result(const ProbeAnswer& answer, const std::string& expected, Read read,
                       Accept accept, Describe describe) {
    if (answer.kind != ProbeAnswer::Kind::result) return wrong(expected, "");
    const auto got = read(answer.value);
    return accept(got) ? right() : wrong(expected, describe(got));
}

/// The call threw the named standard exception ("domain_error", ...), as the contract says.
Judgement threw(const ProbeAnswer& answer, const std::string& type);

}  // namespace raystep::grade
