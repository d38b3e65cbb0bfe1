#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

#include "app/check/ray_case.h"
#include "base/math/portable_random.h"

namespace raystep {

/// A named family of stage-3 cases, each made from its own seeded generator. The cases come
/// without expectations: grader/oracle decides them. docs/stage3.md lists the families and what
/// each probes.
struct Stage3Family {
    const char* name;
    const char* description;
    /// When above 0, a hit's t passes only within this many ulps of the exact t, instead of the
    /// rounding budget: for a family that checks one accuracy requirement (the stable roots).
    double t_ulps = 0.0;
    RayCase (*make)(PortableRandom& random);
};

/// Every stage-3 family, in the order reports list them.
const std::vector<Stage3Family>& stage3_families();

/// The family with that name, or nullptr.
const Stage3Family* find_stage3_family(std::string_view name);

/// Cases 0 to count - 1 of the family from `seed`, without expectations. Case k depends only on
/// (seed, k).
CaseFamily generate_cases(const Stage3Family& family, std::uint64_t seed, std::size_t count);

}  // namespace raystep
