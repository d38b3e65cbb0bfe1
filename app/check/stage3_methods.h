#pragma once

#include <string>
#include <vector>

#include "app/check/case_answer.h"
#include "app/check/ray_case.h"
#include "stages/3_intersect/intersect.h"

namespace raystep {

/// A stage-3 function as the checks call it: a test of one kind of primitive, or closest_hit.
struct Stage3Method {
    std::string name;  ///< as in intersect.h: "intersect_triangle_cramer", "closest_hit"
    enum class Kind { sphere, triangle, plane, closest } kind;
    std::optional<Hit> (*sphere)(const Ray&, const Sphere&) = nullptr;
    std::optional<Hit> (*triangle)(const Ray&, const Triangle&) = nullptr;
    std::optional<Hit> (*plane)(const Ray&, const Plane&) = nullptr;
};

/// The functions of intersect.h, from whichever build this is (the student's or the solution).
std::vector<Stage3Method> stage3_methods();

/// Runs the method on every primitive of the case it applies to (or, for closest_hit, on all of
/// them at once, gathered into a PrimitiveList), catching what it throws.
CaseAnswer run_method(const Stage3Method& method, const RayCase& ray_case);

/// True when the method tests this kind of primitive (closest_hit: every kind).
bool applies_to(const Stage3Method& method, const CaseShape& shape);

}  // namespace raystep
