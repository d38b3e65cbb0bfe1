#include "grading/4_accel/accel_workloads.h"

#include <stdexcept>
#include <string>
#include <utility>

#include "stages/3_intersect/intersect.h"
#include "stages/4_accel/uniform_grid.h"

namespace raystep::probe {

namespace {

// The question with its scene as data: `asked` itself, whose primitives and rays are not copied,
// or, where it names a scene, `made`, that scene made here.
const WorkloadQuestion& with_scene(const WorkloadQuestion& asked, WorkloadQuestion& made) {
    if (!asked.walls && !asked.speed) return asked;
    if (asked.speed && asked.speed->rays < 0)
        throw std::invalid_argument("the speed scene's rays are a count, not " +
                                    std::to_string(asked.speed->rays));
    grade::WorkScene scene = asked.walls
                                 ? grade::walls_scene(asked.walls->layers, asked.walls->side)
                                 : grade::speed_scene(asked.speed->rays);
    made = asked;
    made.shadow_rays = grade::shadow_rays(scene);
    made.primitives = std::move(scene.primitives);
    made.rays = std::move(scene.rays);
    return made;
}

// The timed walk of timed_walk.h through `structure`: its digest.
template <class Structure>
std::uint64_t run_workload(const Structure& structure, const WorkloadQuestion& question) {
    return timed_walk(structure, question.rays, question.shadow_rays, question.jitter,
                      question.repeat);
}

struct BruteForce {
    PrimitiveList primitives;
    std::optional<PrimitiveHit> closest_hit(const Ray& ray) const {
        return raystep::closest_hit(ray, primitives);
    }
    bool occluded(const Ray& ray) const { return closest_hit(ray).has_value(); }
};

}  // namespace

std::vector<BvhNodeData> bvh_structure(const StructureBuildQuestion& question) {
    return Bvh(question.primitives, bvh_split_from(question.split)).nodes();
}

UniformGridData grid_structure(const StructureBuildQuestion& question) {
    return UniformGrid(question.primitives).cells();
}

std::uint64_t bvh_workload(const WorkloadQuestion& asked) {
    WorkloadQuestion made;
    const WorkloadQuestion& question = with_scene(asked, made);
    return run_workload(Bvh(question.primitives, bvh_split_from(question.split)), question);
}

std::uint64_t grid_workload(const WorkloadQuestion& asked) {
    WorkloadQuestion made;
    const WorkloadQuestion& question = with_scene(asked, made);
    return run_workload(UniformGrid(question.primitives), question);
}

std::uint64_t brute_force_workload(const WorkloadQuestion& asked) {
    WorkloadQuestion made;
    const WorkloadQuestion& question = with_scene(asked, made);
    return run_workload(BruteForce{question.primitives}, question);
}

}  // namespace raystep::probe
