#pragma once

#include <optional>
#include <string>
#include <vector>

#include "app/grade/public_case.h"
#include "grader/grade/check_definition.h"
#include "grading/4_accel/timed_walk.h"
#include "stages/3_intersect/intersect.h"

namespace raystep::grade {

// The parts of stage 4's checks that live in their own files; stage4_checks.cpp lists the checks.

/// intersect_aabb's entry and exit against the exact interval (stage4_slab_cases.cpp): origins
/// inside the box, on a face and outside it, rays through edges and corners, t_min > 0 and finite
/// t_max, the 0 * inf planes, empty and point boxes. Each case a public one, judged by
/// slab_interval_judge (grading/4_accel/accel_judges.h).
std::vector<PublicCase> slab_cases();

/// grid_resolution against the handout's rule, thin and flat boxes included
/// (stage4_grid_resolution_cases.cpp). Each case a public one, judged by grid_cells_judge.
std::vector<PublicCase> grid_resolution_cases();

/// What a structure must answer (stage4_checks.cpp): closest_hit over the list's spheres and
/// triangles, its planes left out, as the reference's brute force finds it.
std::optional<PrimitiveHit> structure_answer(const Ray& ray, const PrimitiveList& primitives);

/// What a structure must do less of than brute force (stage4_work.cpp): which structure, and the
/// check that asks.
struct WorkQuery {
    std::string check_id;  ///< the check that asks, for the reproduce command
    std::string call;      ///< "bvh" or "grid"
    std::string split;     ///< the BVH's split, "sah" or "median"; empty for the grid
};

/// How far every pass of a timed walk moves its rays (timed_walk.h), for the walls walks and the
/// speed checks alike: a thousandth of the scene's size and a ten-thousandth of a direction's
/// length, far too little to change what a ray meets, drawn from the grade's own seed.
probe::Jitter timed_walk_jitter(const GradingContext& context);

/// Whether the submission's structure does a structure's work, measured from outside its probe:
/// the structure handed back as data (Bvh::nodes, UniformGrid::cells), checked and walked by the
/// grader, costs at most four times the reference's tests and nodes per ray, or a 16th of brute
/// force's; and its own walk, in CPU time on rays new every pass, takes at most ten times as long
/// through 768 walls as through one, and forty times the reference's (stage4_work.cpp says why
/// each).
/// Measured once per probe and structure; failed with the reason otherwise, or not implemented
/// when nodes() or cells() is a stub.
CheckMeasure measure_work(const GradingContext& context, const BuiltProbe& probe,
                          const WorkQuery& query);

}  // namespace raystep::grade
