#pragma once

#include <functional>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

#include "base/math/portable_random.h"
#include "grader/grade/check_definition.h"

namespace raystep::grade {

// Judges shared by the stages' checks: a probe's answer against the grader's expectation.

/// The student release's raystep, as the handouts run it from the repository's root: the
/// program a student's reproduce line calls.
inline constexpr const char* kStudentRaystep = "build/release/bin/raystep";

/// A check that sends the probe of `stage` the cases `make_cases` writes and judges each answer
/// (run_cases); the cases are made when the check runs, not when the checks are listed.
CheckDefinition case_check(std::string id, int stage, std::string kind, std::string name,
                           std::function<std::vector<ProbeCase>()> make_cases);

// Expectations are worked out in long double (64-bit mantissa on x86-64): 11 more bits than a
// double, so that the expectation's own rounding is far below the tolerances a check allows.
using Wide = long double;
using WideVec = glm::vec<3, Wide>;

WideVec widen(const Vec3& v);
Vec3 narrow(const WideVec& v);

/// A workload timed from outside the probe: the best of three runs minus the same run with no
/// passes (starting, reading the input, building), and the checksum the passes answered.
struct WorkloadTime {
    double seconds = 0.0;
    probe::Json checksum;
    bool answered = true;  ///< false when a run ended without an answer (a stub, crash or timeout)
    std::string not_implemented;  ///< a stub's message, when a stub was why
};

/// Asks `program` the `call` with `args` and "repeat" set to `repeat` passes, and to 0.
WorkloadTime timed_workload(const std::filesystem::path& program, const std::string& call,
                            const probe::Json& args, int repeat);

/// One program of a timed comparison, and the arguments its call gets (programs compared on the
/// same work may still be asked for it differently, as stage 3 asks for two triangle tests).
struct WorkloadRun {
    std::filesystem::path program;
    probe::Json args;
};

/// The same for several programs, timed in turn: each of the three rounds runs every program
/// once, so that a load that comes and goes (another job on the machine) slows them alike and
/// their ratio holds; timed one after the other, a load during one program's runs alone skews it.
std::vector<WorkloadTime> timed_workloads(const std::vector<WorkloadRun>& runs,
                                          const std::string& call, int repeat);

/// A random point from a case's own generator, the same on every platform: each component
/// uniform in [low, high), drawn x, y, z in that order.
Vec3 uniform(PortableRandom& random, double low, double high);

/// The result as a number, vector or ray; throws (an unreadable answer) when it is not one.
double result_number(const ProbeAnswer& answer);
Vec3 result_vec3(const ProbeAnswer& answer);

/// Within `tolerance` of the expected number (absolute).
Judgement near_number(const ProbeAnswer& answer, double expected, double tolerance);

/// Every component within `tolerance` of the expected vector's (absolute).
Judgement near_vec3(const ProbeAnswer& answer, const Vec3& expected, double tolerance);

/// The call threw the named standard exception ("domain_error", ...), as the contract says.
Judgement threw(const ProbeAnswer& answer, const std::string& type);

/// A number or vector with every digit (17 significant), so that a counterexample shows the
/// difference, however small, and can be typed back in.
std::string full_text(double x);
std::string full_text(const Vec3& v);
std::string ray_text(const Ray& r);

/// The case's vectors written out for a report.
std::string vectors_text(std::initializer_list<Vec3> vectors);

}  // namespace raystep::grade
