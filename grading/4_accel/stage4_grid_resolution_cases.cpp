// grid_resolution against the handout's rule (docs/stage4.md, "Grid resolution"), worked out here
// in long double: k = (c n / V)^(1/d) cells per unit length over the d axes that share the cells,
// each axis round(e k) cells clamped to [1, kMaxCellsPerAxis]; an axis with no extent, or so thin
// that e k < 1, gets one cell and leaves the others to share the rest. Cases where the rule's
// answer is within rounding of a different one (an e k within 1e-9 of a half, or of the thin
// threshold 1) are not generated: the handout fixes no order of operations that would settle them.
// Each case's cells are judged by grid_cells_judge (grading/4_accel/accel_judges.h).

#include <cmath>

#include "base/math/portable_random.h"
#include "grader/grade/checks/cpp_literal.h"
#include "grader/grade/checks/judging.h"
#include "grader/oracle/wide_vec.h"
#include "grading/4_accel/accel_calls.h"
#include "grading/4_accel/accel_judges.h"
#include "grading/4_accel/stage4_cases.h"
#include "stages/4_accel/uniform_grid.h"

namespace raystep::grade {

namespace {

using probe::Json;

struct ResolutionCase {
    Vec3 min;
    Vec3 max;
    std::size_t n;
    std::string what;
};

struct Rule {
    glm::ivec3 cells{1};
    bool clear = true;  ///< no axis near a rounding or thinness threshold
};

Rule handout_rule(const ResolutionCase& c) {
    Rule rule;
    const Vec3 extent = c.max - c.min;  // as Aabb::extent() rounds it
    if (c.n == 0 || !(c.min.x <= c.max.x && c.min.y <= c.max.y && c.min.z <= c.max.z)) return rule;
    bool shares[3];
    for (int axis = 0; axis < 3; ++axis)
        shares[axis] = extent[axis] > 0.0 && std::isfinite(extent[axis]);
    constexpr Wide kNear = 1e-9L;
    Wide log_k = 0;
    for (bool thinned = true; thinned;) {
        int d = 0;
        Wide log_volume = 0;
        for (int axis = 0; axis < 3; ++axis) {
            if (!shares[axis]) continue;
            ++d;
            log_volume += std::log(static_cast<Wide>(extent[axis]));
        }
        if (d == 0) return rule;  // a point
        log_k = (std::log(static_cast<Wide>(kCellsPerPrimitive) * static_cast<Wide>(c.n)) -
                 log_volume) /
                d;
        thinned = false;
        for (int axis = 0; axis < 3; ++axis) {
            if (!shares[axis]) continue;
            const Wide log_cells = std::log(static_cast<Wide>(extent[axis])) + log_k;
            if (std::fabs(log_cells) < kNear) rule.clear = false;
            if (log_cells < 0) {
                shares[axis] = false;
                thinned = true;
            }
        }
    }
    for (int axis = 0; axis < 3; ++axis) {
        if (!shares[axis]) continue;
        const Wide exact = std::exp(std::log(static_cast<Wide>(extent[axis])) + log_k);
        if (exact < kMaxCellsPerAxis + 1 &&
            std::fabs(exact - std::floor(exact) - 0.5L) < kNear * exact)
            rule.clear = false;
        rule.cells[axis] = static_cast<int>(
            std::min<Wide>(std::max<Wide>(std::round(exact), 1), kMaxCellsPerAxis));
    }
    return rule;
}

// The handout's table, and the edges of the rule's domain.
std::vector<ResolutionCase> named_cases() {
    const double inf = HUGE_VAL;
    return {
        {{0, 0, 0}, {1, 1, 1}, 9, "the handout's cube"},
        {{0, 0, 0}, {4, 1, 1}, 12, "the handout's 4 x 1 x 1"},
        {{0, 0, 0}, {1, 2, 3}, 16, "the handout's 1 x 2 x 3"},
        {{0, 0, 0}, {4, 4, 0}, 12, "flat: 4 x 4 x 0"},
        {{0, 0, 0}, {4, 4, 1e-9}, 12, "thin: 4 x 4 x 1e-9"},
        {{0, 0, 0}, {4, 0, 0}, 3, "a line: 4 x 0 x 0"},
        {{1, 2, 3}, {1, 2, 3}, 5, "a point"},
        {{inf, inf, inf}, {-inf, -inf, -inf}, 5, "the empty box"},
        {{0, 0, 0}, {1, 1, 1}, 0, "no primitives"},
        {{0, 0, 0}, {1, 1, 1}, 10000000, "the cap: 10^7 primitives in a cube"},
        {{0, 0, 0}, {100, 1e-3, 1e-3}, 50, "two thin axes: a needle"},
        {{0, 0, 0}, {10, 10, 0.05}, 40, "thin only once the others share: 10 x 10 x 0.05"},
        {{-5e99, -5e99, -5e99}, {5e99, 5e99, 5e99}, 100, "huge: V overflows nothing in logs"},
        {{0, 0, 0}, {1e-100, 1e-100, 1e-100}, 100, "tiny: V = 1e-300"},
        {{0, 0, 0}, {1e-100, 2e-100, 0}, 100, "tiny and flat"},
    };
}

constexpr std::uint64_t kResolutionSeed = 0x6121D;

// Boxes with extents over five decades, a third of them flat or thin along one axis.
std::vector<ResolutionCase> generated_cases() {
    std::vector<ResolutionCase> cases;
    for (std::uint64_t k = 0; cases.size() < 60; ++k) {
        PortableRandom random(kResolutionSeed, k);
        const Vec3 min = random.point(10.0);
        Vec3 extent(random.decade(-3, 2), random.decade(-3, 2), random.decade(-3, 2));
        const int axis = static_cast<int>(random.integer(0, 2));
        if (k % 3 == 1) extent[axis] = 0.0;
        if (k % 3 == 2) extent[axis] *= 1e-6;
        const ResolutionCase c{
            min, min + extent, static_cast<std::size_t>(random.integer(1, 5000)),
            "random box " + std::to_string(k) + " of seed " + std::to_string(kResolutionSeed)};
        if (handout_rule(c).clear) cases.push_back(c);
    }
    return cases;
}

}  // namespace

std::vector<PublicCase> grid_resolution_cases() {
    std::vector<ResolutionCase> all = named_cases();
    for (const ResolutionCase& c : generated_cases())
        all.push_back(c);
    std::vector<PublicCase> cases;
    for (const ResolutionCase& c : all) {
        cases.push_back({c.what + ": box " + full_text(c.min) + " to " + full_text(c.max) +
                             ", n = " + std::to_string(c.n),
                         probe::query(probe::grid_resolution_call, {c.min, c.max, c.n}),
                         grid_cells_judge(handout_rule(c).cells),
                         "grid_resolution(Aabb{Vec3" + cpp(c.min) + ", Vec3" + cpp(c.max) + "}, " +
                             std::to_string(c.n) + ")"});
    }
    return cases;
}

}  // namespace raystep::grade
