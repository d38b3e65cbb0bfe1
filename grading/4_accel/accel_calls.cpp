#include "grading/4_accel/accel_calls.h"

#include <stdexcept>

#include "stages/4_accel/uniform_grid.h"

namespace raystep::probe {

namespace {

// The structure's answers for every ray: its closest hits, or whether each ray is occluded.
template <class Structure>
StructureAnswers answer_rays(const Structure& structure, const StructureQuestion& question) {
    StructureAnswers answers;
    if (question.occluded.value_or(false)) {
        answers.occluded.emplace();
        for (const Ray& r : question.rays)
            answers.occluded->push_back(structure.occluded(r));
    } else {
        for (const Ray& r : question.rays)
            answers.hits.push_back(structure.closest_hit(r));
    }
    return answers;
}

}  // namespace

BvhSplit bvh_split_from(const std::optional<std::string>& name) {
    if (name == "sah") return BvhSplit::sah;
    if (name == "median") return BvhSplit::median;
    throw std::invalid_argument("expected a split: sah or median");
}

StructureAnswers bvh_answers(const StructureQuestion& question) {
    const Bvh bvh(question.primitives, bvh_split_from(question.split));
    return answer_rays(bvh, question);
}

StructureAnswers grid_answers(const StructureQuestion& question) {
    const UniformGrid grid(question.primitives);
    return answer_rays(grid, question);
}

std::optional<Interval> aabb_interval(const AabbQuestion& question) {
    return intersect_aabb(question.ray, 1.0 / question.ray.direction,
                          Aabb{question.min, question.max});
}

std::tuple<int, int, int> grid_cells(const GridResolutionQuestion& question) {
    const glm::ivec3 cells =
        grid_resolution(Aabb{question.min, question.max}, static_cast<std::size_t>(question.n));
    return {cells.x, cells.y, cells.z};
}

}  // namespace raystep::probe
