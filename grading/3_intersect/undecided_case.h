#pragma once

#include <vector>

#include "app/check/ray_case.h"

namespace raystep {

// The hand-picked cases of stage 3's contract families (stage3_contract_cases.cpp,
// stage3_contract_edges.cpp) are written with nothing expected: grader/oracle decides them.

/// A case of `shape` alone.
inline RayCase undecided_case(const Ray& ray, const CaseShape& shape) {
    return RayCase{0, ray, {CasePrimitive{shape, {}}}, false};
}

/// A case of every one of `shapes`, in order.
inline RayCase undecided_case_of_all(const Ray& ray, const std::vector<CaseShape>& shapes) {
    RayCase c{0, ray, {}, false};
    for (const CaseShape& shape : shapes)
        c.primitives.push_back({shape, {}});
    return c;
}

}  // namespace raystep
