#pragma once

// Stage 4's calls that only the grader's probe has: a structure handed back as data (its nodes or
// cells), for the grader to check and walk itself; and the timed workloads, whose time the grader
// takes from the kernel, outside the probe's process (docs/instructor.md, "What student code can
// touch"). The structure's answers themselves are grading/4_accel/accel_calls.h's.
//
// A workload is the timed walk of timed_walk.h: the base rays and the shadow rays `repeat` times,
// each pass's moved a little by numbers of its own, so that a structure that remembers answers
// gains nothing; it answers with the digest of every answer, which the grader checks against the
// reference's.

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "grading/4_accel/accel_calls.h"
#include "grading/4_accel/stage4_work_scenes.h"
#include "grading/4_accel/structure_json.h"
#include "grading/4_accel/timed_walk.h"

namespace raystep::probe {

/// The primitives a structure is built over, and the BVH's split (none for the grid).
struct StructureBuildQuestion {
    PrimitiveList primitives;
    std::optional<std::string> split;
};

/// A walls scene of stage4_work_scenes.h, named rather than sent: the probe makes it.
struct WallsScene {
    int layers = 0;
    grade::Side side = grade::Side::both;
};

/// The speed scene of stage4_work_scenes.h, with its first `rays` rays, named rather than sent.
struct SpeedScene {
    int rays = 0;
};

struct WorkloadQuestion {
    PrimitiveList primitives;
    std::optional<std::string> split;  ///< the BVH's; the grid and brute force take none
    std::vector<Ray> rays;
    std::vector<Ray> shadow_rays;
    Jitter jitter;
    int repeat = 0;
    /// In place of the primitives and both kinds of rays, a scene the probe makes, with its shadow
    /// rays: a walls scene, or the speed scene (some 5 MB of JSON, for each of a check's timed
    /// runs to write and read, when sent).
    std::optional<WallsScene> walls;
    std::optional<SpeedScene> speed;
};

template <>
struct JsonFields<StructureBuildQuestion> {
    static constexpr auto list =
        std::make_tuple(json_field("primitives", &StructureBuildQuestion::primitives),
                        json_field("split", &StructureBuildQuestion::split));
};

template <>
struct JsonFields<Jitter> {
    static constexpr auto list =
        std::make_tuple(json_field("seed", &Jitter::seed), json_field("origin", &Jitter::origin),
                        json_field("direction", &Jitter::direction));
};

template <>
struct JsonCodec<grade::Side> {
    static Json write(grade::Side side) { return static_cast<int>(side); }
    static grade::Side read(const Json& value) {
        const int side = JsonCodec<int>::read(value);
        if (side < 0 || side > static_cast<int>(grade::Side::both))
            throw std::invalid_argument("a walls scene's side is 0, 1 or 2");
        return static_cast<grade::Side>(side);
    }
};

template <>
struct JsonFields<WallsScene> {
    static constexpr auto list = std::make_tuple(json_field("layers", &WallsScene::layers),
                                                 json_field("side", &WallsScene::side));
};

template <>
struct JsonFields<SpeedScene> {
    static constexpr auto list = std::make_tuple(json_field("rays", &SpeedScene::rays));
};

template <>
struct JsonFields<WorkloadQuestion> {
    using Q = WorkloadQuestion;
    static constexpr auto list =
        std::make_tuple(json_field("primitives", &Q::primitives), json_field("split", &Q::split),
                        json_field("rays", &Q::rays), json_field("shadow_rays", &Q::shadow_rays),
                        json_field("walls", &Q::walls), json_field("speed", &Q::speed),
                        json_field("jitter", &Q::jitter), json_field("repeat", &Q::repeat));
};

template <>
struct JsonCodec<std::vector<BvhNodeData>>
    : FunctionCodec<std::vector<BvhNodeData>, bvh_nodes, bvh_nodes_from> {};
template <>
struct JsonCodec<UniformGridData>
    : FunctionCodec<UniformGridData, uniform_grid_data, uniform_grid_data_from> {};

std::vector<BvhNodeData> bvh_structure(const StructureBuildQuestion& question);
UniformGridData grid_structure(const StructureBuildQuestion& question);
std::uint64_t bvh_workload(const WorkloadQuestion& question);
std::uint64_t grid_workload(const WorkloadQuestion& question);
/// No structure: stage 3's closest_hit over every primitive, the baseline a structure must beat.
std::uint64_t brute_force_workload(const WorkloadQuestion& question);

inline constexpr ProbeCall<StructureBuildQuestion, std::vector<BvhNodeData>> bvh_structure_call{
    "bvh_structure", &bvh_structure};
inline constexpr ProbeCall<StructureBuildQuestion, UniformGridData> grid_structure_call{
    "grid_structure", &grid_structure};
inline constexpr ProbeCall<WorkloadQuestion, std::uint64_t> bvh_workload_call{"bvh_workload",
                                                                              &bvh_workload};
inline constexpr ProbeCall<WorkloadQuestion, std::uint64_t> grid_workload_call{"grid_workload",
                                                                               &grid_workload};
inline constexpr ProbeCall<WorkloadQuestion, std::uint64_t> brute_force_workload_call{
    "brute_force_workload", &brute_force_workload};

inline constexpr auto accel_workload_calls =
    std::make_tuple(bvh_structure_call, grid_structure_call, bvh_workload_call, grid_workload_call,
                    brute_force_workload_call);

}  // namespace raystep::probe
