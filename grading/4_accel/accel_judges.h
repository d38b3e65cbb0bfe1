#pragma once

#include <optional>
#include <string>

#include <glm/vec3.hpp>

#include "app/protocol/probe_json.h"
#include "base/math/double_double.h"
#include "stages/3_intersect/intersect.h"

namespace raystep::grade {

// The judges of stage 4's answers (accel_judges.cpp): each function below writes the judge's
// data, {"judge": NAME, ...}, which build_judge (data_judge.h) turns back into the judge.

/// The exact interval of a ray's [t_min, t_max] inside a closed box, as the grader's oracle
/// worked it out with more bits than a double, and how near each end a double computation may
/// come out. Where neither `must_hit` nor `must_miss` holds, the ray passes within rounding of the
/// box and either answer is right.
struct SlabInterval {
    bool must_hit = false;
    bool must_miss = false;
    DoubleDouble enter;
    DoubleDouble exit;
    DoubleDouble enter_tolerance;  ///< 0 for an infinite end, which must come out exactly
    DoubleDouble exit_tolerance;
};

/// "slab_interval": intersect_aabb's answer, {"enter", "exit"} or null for a miss, against
/// `exact`. A miss passes unless the ray must hit; an interval fails where the ray must miss,
/// where it is empty (enter > exit, or a NaN), or where an end is farther than its tolerance from
/// the exact end, compared in double-double.
probe::Json slab_interval_judge(const SlabInterval& exact);

/// "grid_cells": grid_resolution's answer, three integers, exactly `expected`.
probe::Json grid_cells_judge(const glm::ivec3& expected);

/// "structure_hit": a structure's answer to a list of one ray against `expected`, what brute
/// force's closest_hit over the same spheres and triangles finds: the same miss, or a hit on the
/// same primitive (kind and index) with its t within `t_tolerance` of expected's (0: bit for bit);
/// a NaN fails.
probe::Json structure_hit_judge(const std::optional<PrimitiveHit>& expected, double t_tolerance);

/// A structure's answer as a report writes it: "a miss", or "triangle 3 at t = 2.5".
std::string primitive_hit_text(const std::optional<PrimitiveHit>& h);

/// "structure_occluded": a structure's occluded answer to a list of one ray, `expected`.
probe::Json structure_occluded_judge(bool expected);

}  // namespace raystep::grade
