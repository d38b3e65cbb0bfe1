#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "base/math/portable_random.h"
#include "stages/3_intersect/intersect.h"

namespace raystep::grade {

// The scenes stage 4's work is measured on (stage4_work.cpp): one to walk a structure handed over
// as data, one to time the submission's own walk, which the grader's probe makes too
// (accel_workloads.h), so that a timed run's query names it in a few bytes.

/// Primitives and the rays asked about them, with a name for reports.
struct WorkScene {
    std::string name;
    PrimitiveList primitives;
    std::vector<Ray> rays;
};

/// 1,500 small triangles and 150 small spheres strewn through [-1, 1]^3, met by 400 rays from a
/// sphere of radius 3 around it; a quarter of the rays start beyond 0 and a quarter stop short,
/// so that a walk must keep to [t_min, t_max].
WorkScene strewn_scene();

/// Where a walls scene's rays come from: above the walls (z > 1, looking down), below them, or
/// half from each side.
enum class Side { above, below, both };

/// The seed of the walls scene's rays. The jitter of the timed passes has a seed of its own,
/// drawn for each grade (GradingContext::timed_walk_seed).
inline constexpr std::uint64_t kTraversalSeed = 0x7A1C;

/// The height of the column the walls scene's walls fill.
inline constexpr double kWallsHeight = 4.0;

/// `layers` walls across a column [0, 1]^2 x [0, kWallsHeight], each a 2 x 2 mesh of squares (two
/// triangles each) that no ray crosses without a hit, spread evenly in z (one lies at its middle),
/// and a speck at two opposite corners so that every number of walls fills the same box; 1,000
/// rays from 1 beyond its top or its bottom, on `side`, through the other end, each crossing
/// every wall (few, since every timed run makes them and its structure before its first pass;
/// the passes make the time). A walk that stops at the nearest hit visits a wall's worth of nodes
/// or cells whatever the number of walls; one that goes on visits every wall behind; one that
/// visits a node's children in a fixed order, not the nearer first, takes the far walls first for
/// rays from one side. The column keeps the walls as far apart as a cube of a quarter as many
/// would, so that a grid's cell holds as few of them.
WorkScene walls_scene(int layers, Side side);

/// Small triangles and spheres in the cube [-1, 1]^3 and three planes through it: 300 triangles
/// (edges up to 0.2 on each axis), 60 spheres (radii 0.01 to 0.15), 3 planes, drawn from
/// `random`. The random soups of stage 4's checks, and the speed scene's first primitives.
PrimitiveList soup_primitives(PortableRandom& random);

/// The scene stage 4's speed checks time, which the grader's probe makes too: the soup of seed
/// 0x5BEED, 3,000 triangles of edges up to 0.05 among it, and `rays` rays from a sphere of radius 3
/// around it towards its middle. The rays are drawn last, one after the other, so the first 1,000
/// of 20,000 are the scene of 1,000 rays (on which brute force is timed).
WorkScene speed_scene(int rays);

/// A scene's shadow rays: its rays, each cut short before the scene (every origin lies some 2 from
/// the unit cube's centre and every direction about as long, or, in the walls scene, 1 beyond the
/// column's end along a unit direction, so t 0.25 ends well outside it). A walk answers them from
/// its first box; brute force tests every primitive.
std::vector<Ray> shadow_rays(const WorkScene& scene);

}  // namespace raystep::grade
