#pragma once

// Stage 4 calls that a structure answers on its own: build a BVH or a grid over the primitives
// given and answer every ray, closest hit or occluded; the slab test on boxes; the grid's
// resolution. `raystep grade` answers a release's public stage-4 cases with them. What a query
// costs in primitive tests is the grader's probe's to count (grading/4_accel/accel_workloads.h).

#include <cstdint>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "app/probe/probe_call.h"
#include "stages/4_accel/aabb.h"
#include "stages/4_accel/bvh.h"

namespace raystep::probe {

/// The BVH split a stage-4 question names, "sah" or "median"; throws std::invalid_argument for
/// anything else, or for none.
BvhSplit bvh_split_from(const std::optional<std::string>& name);

/// A structure over the primitives, asked about every ray: its closest hit, or with `occluded`
/// whether anything blocks the ray. The BVH's split is named; the grid has none.
struct StructureQuestion {
    PrimitiveList primitives;
    std::vector<Ray> rays;
    std::optional<std::string> split;
    std::optional<bool> occluded;
};

/// Per ray a primitive hit or null, or, for occluded, true or false.
struct StructureAnswers {
    std::vector<std::optional<PrimitiveHit>> hits;
    std::optional<std::vector<bool>> occluded;
};

struct AabbQuestion {
    Ray ray;
    Vec3 min, max;
};

struct GridResolutionQuestion {
    Vec3 min, max;
    std::uint64_t n = 0;
};

template <>
struct JsonFields<StructureQuestion> {
    using Q = StructureQuestion;
    static constexpr auto list =
        std::make_tuple(json_field("primitives", &Q::primitives), json_field("rays", &Q::rays),
                        json_field("split", &Q::split), json_field("occluded", &Q::occluded));
};

/// An answer only: the grader judges each ray's answer as JSON.
template <>
struct JsonCodec<StructureAnswers> {
    static Json write(const StructureAnswers& answers) {
        if (answers.occluded) return JsonCodec<std::vector<bool>>::write(*answers.occluded);
        return JsonCodec<std::vector<std::optional<PrimitiveHit>>>::write(answers.hits);
    }
};

template <>
struct JsonFields<AabbQuestion> {
    static constexpr auto list = std::make_tuple(json_field("ray", &AabbQuestion::ray),
                                                 json_field("min", &AabbQuestion::min),
                                                 json_field("max", &AabbQuestion::max));
};

template <>
struct JsonFields<Interval> {
    static constexpr auto list =
        std::make_tuple(json_field("enter", &Interval::enter), json_field("exit", &Interval::exit));
};

template <>
struct JsonFields<GridResolutionQuestion> {
    using Q = GridResolutionQuestion;
    static constexpr auto list = std::make_tuple(
        json_field("min", &Q::min), json_field("max", &Q::max), json_field("n", &Q::n));
};

StructureAnswers bvh_answers(const StructureQuestion& question);
StructureAnswers grid_answers(const StructureQuestion& question);
/// The slab test with the ray's own inverse direction.
std::optional<Interval> aabb_interval(const AabbQuestion& question);
/// The cells along x, y and z.
std::tuple<int, int, int> grid_cells(const GridResolutionQuestion& question);

inline constexpr ProbeCall<StructureQuestion, StructureAnswers> bvh_call{"bvh", &bvh_answers};
inline constexpr ProbeCall<StructureQuestion, StructureAnswers> grid_call{"grid", &grid_answers};
inline constexpr ProbeCall<AabbQuestion, std::optional<Interval>> intersect_aabb_call{
    "intersect_aabb", &aabb_interval};
inline constexpr ProbeCall<GridResolutionQuestion, std::tuple<int, int, int>> grid_resolution_call{
    "grid_resolution", &grid_cells};

inline constexpr auto accel_calls =
    std::make_tuple(bvh_call, grid_call, intersect_aabb_call, grid_resolution_call);

}  // namespace raystep::probe
