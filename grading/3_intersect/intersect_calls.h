#pragma once

// Stage 3 calls: one stage-3 function, named by the question, over a list of ray cases
// (questions only: the probe never sees the oracle's expectations), answered as app/check answers
// them for `raystep check`; and a triangle test's workload, timed by the grader from outside, as
// the stage-4 workloads are.

#include <cstdint>
#include <string>
#include <vector>

#include "app/check/stage3_methods.h"
#include "app/probe/probe_call.h"

namespace raystep::probe {

struct Stage3CasesQuestion {
    std::string method;  ///< a stage-3 function by its name in intersect.h (stage3_methods.h)
    std::vector<RayCase> cases;
};

/// rays[k] against primitives.triangles[k], every pair `repeat` times.
struct TriangleWorkloadQuestion {
    std::string method;
    std::vector<Ray> rays;
    PrimitiveList primitives;
    int repeat = 0;
};

template <>
struct JsonFields<Stage3CasesQuestion> {
    static constexpr auto list = std::make_tuple(json_field("method", &Stage3CasesQuestion::method),
                                                 json_field("cases", &Stage3CasesQuestion::cases));
};

template <>
struct JsonFields<TriangleWorkloadQuestion> {
    using Q = TriangleWorkloadQuestion;
    static constexpr auto list =
        std::make_tuple(json_field("method", &Q::method), json_field("rays", &Q::rays),
                        json_field("primitives", &Q::primitives), json_field("repeat", &Q::repeat));
};

std::vector<CaseAnswer> answer_stage3_cases(const Stage3CasesQuestion& question);

/// The hits counted over every pass, so that no test can be optimized away.
std::uint64_t run_triangle_workload(const TriangleWorkloadQuestion& question);

inline constexpr ProbeCall<Stage3CasesQuestion, std::vector<CaseAnswer>> stage3_cases_call{
    "stage3_cases", &answer_stage3_cases};
inline constexpr ProbeCall<TriangleWorkloadQuestion, std::uint64_t> triangle_workload_call{
    "triangle_workload", &run_triangle_workload};

inline constexpr auto intersect_calls = std::make_tuple(stage3_cases_call, triangle_workload_call);

}  // namespace raystep::probe
