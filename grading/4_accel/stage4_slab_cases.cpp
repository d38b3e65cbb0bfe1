// intersect_aabb judged by its values, not only hit or miss: the entry and exit it returns against
// the exact interval of the ray's [t_min, t_max] inside the closed box, worked out in long double
// and written into each case's data judge (slab_interval_judge, grading/4_accel/accel_judges.h).
//
// Tolerances. A slab's t = (b - o) * (1 / d) in double rounds three times (the difference, the
// reciprocal, the product): within 3u of the exact t, u = 2^-53. The exit may be widened by
// 2 gamma(3) |exit|, about 6u, so that rounding never loses a ray that touches the box. 16u |t|
// covers both with room for an alternative that divides instead; 4u of the slab's magnitude
// (|o| + |b|) / |d| more lets one that computes b / d - o / d pass. Long double's own rounding,
// 2^-63 relative, is far below either.
//
// Hit or miss. Where the exact interval is not empty, the ray touches or crosses the box and must
// be reported, however thin the crossing: rays that touch an edge or a corner exactly, in whole
// numbers whose slabs round differently (t = 3 * (1/3) against t = 7 * (1/7)), and rays aimed at
// an edge or a corner from anywhere, which cross it by an ulp or miss it by one. Long double
// cannot tell an exact touch from a miss by 2^-60 of t, so an interval empty by less than that
// counts as touching: a test that rounds safely widens by some 2^-51, far more. Where the exact
// interval is empty by more than both tolerances, the ray misses; between, either answer is
// right.

#include <cmath>

#include "base/math/portable_random.h"
#include "grader/grade/checks/cpp_literal.h"
#include "grader/grade/checks/judging.h"
#include "grader/oracle/wide_vec.h"
#include "grading/4_accel/accel_calls.h"
#include "grading/4_accel/accel_judges.h"
#include "grading/4_accel/stage4_cases.h"

namespace raystep::grade {

namespace {

using probe::Json;

struct SlabCase {
    Ray ray;
    Vec3 min;
    Vec3 max;
    std::string what;  ///< the kind of case, for the report
};

// The exact interval, and how near each end a double computation may come out.
SlabInterval exact_interval(const SlabCase& c) {
    SlabInterval exact;
    const bool empty = !(c.min.x <= c.max.x && c.min.y <= c.max.y && c.min.z <= c.max.z);
    if (empty) {
        exact.must_miss = true;
        return exact;
    }
    Wide enter = c.ray.t_min;
    Wide exit = c.ray.t_max;
    Wide enter_magnitude = 0;
    Wide exit_magnitude = 0;
    for (int axis = 0; axis < 3; ++axis) {
        const Wide o = c.ray.origin[axis];
        const Wide d = c.ray.direction[axis];
        const Wide low = c.min[axis];
        const Wide high = c.max[axis];
        // Parallel to the slab: inside it (its planes included) for every t, or never
        if (d == 0) {
            if (o < low || o > high) {
                exact.must_miss = true;
                return exact;
            }
            continue;
        }
        Wide t_near = (low - o) / d;
        Wide t_far = (high - o) / d;
        if (d < 0) std::swap(t_near, t_far);
        const Wide magnitude =
            (std::fabs(o) + std::max(std::fabs(low), std::fabs(high))) / std::fabs(d);
        if (t_near > enter) {
            enter = t_near;
            enter_magnitude = magnitude;
        }
        if (t_far < exit) {
            exit = t_far;
            exit_magnitude = magnitude;
        }
    }
    // An infinite end (t_max = inf on a ray parallel to every slab) is compared exactly
    const Wide enter_tolerance = std::isinf(enter) ? 0
                                                   : 16 * kWideUnitRoundoff * std::fabs(enter) +
                                                         4 * kWideUnitRoundoff * enter_magnitude;
    const Wide exit_tolerance = std::isinf(exit) ? 0
                                                 : 16 * kWideUnitRoundoff * std::fabs(exit) +
                                                       4 * kWideUnitRoundoff * exit_magnitude;
    const Wide wide_rounding =
        0x1p-60L * (std::fabs(enter) + enter_magnitude +
                    (std::isinf(exit) ? 0 : std::fabs(exit) + exit_magnitude));
    exact.enter = double_double(enter);
    exact.exit = double_double(exit);
    exact.enter_tolerance = double_double(enter_tolerance);
    exact.exit_tolerance = double_double(exit_tolerance);
    exact.must_hit = exit - enter >= -wide_rounding;
    exact.must_miss = enter - exit > enter_tolerance + exit_tolerance;
    return exact;
}

// Boxes of every size and place, each side at least 0.1 long.
void random_box(PortableRandom& random, Vec3& min, Vec3& max) {
    min = random.point(2.0);
    max = min + Vec3(random.uniform(0.1, 2.0), random.uniform(0.1, 2.0), random.uniform(0.1, 2.0));
}

Vec3 inside(PortableRandom& random, const Vec3& min, const Vec3& max) {
    return {random.uniform(min.x, max.x), random.uniform(min.y, max.y),
            random.uniform(min.z, max.z)};
}

// [t_min, t_max] in four ways: from 0, from beyond 0, from far beyond (often past the exit), and
// from 0 to a short t_max.
void random_interval(PortableRandom& random, int kind, Ray& ray) {
    switch (kind % 4) {
        case 0:
            break;
        case 1:
            ray.t_min = random.uniform(0.0, 0.5);
            break;
        case 2:
            ray.t_min = random.uniform(0.5, 5.0);
            break;
        default:
            ray.t_max = random.uniform(0.01, 1.0);
            break;
    }
}

constexpr std::uint64_t kSlabSeed = 0x51AB;
constexpr std::uint64_t kFacePlaneSeed = 0xFACE;

// Direction components whose reciprocals round: t = n * (1/d) comes out an ulp off for some.
constexpr double kOddSteps[] = {3.0, 5.0, 7.0, 9.0, 11.0};

// Each family's case k is rebuilt from (kSlabSeed, its number).
std::vector<SlabCase> generated_cases() {
    std::vector<SlabCase> cases;
    std::uint64_t number = 0;
    const auto next = [&number] { return PortableRandom(kSlabSeed, number++); };
    for (int k = 0; k < 40; ++k) {
        PortableRandom random = next();
        SlabCase c{{}, {}, {}, "origin inside"};
        random_box(random, c.min, c.max);
        c.ray = {inside(random, c.min, c.max), random.unit_vector()};
        random_interval(random, k, c.ray);
        cases.push_back(c);
    }
    for (int k = 0; k < 40; ++k) {
        PortableRandom random = next();
        SlabCase c{{}, {}, {}, "origin on a face"};
        random_box(random, c.min, c.max);
        Vec3 origin = inside(random, c.min, c.max);
        const int axis = static_cast<int>(random.integer(0, 2));
        origin[axis] = random.unit() < 0.5 ? c.min[axis] : c.max[axis];
        c.ray = {origin, random.unit_vector()};
        random_interval(random, k, c.ray);
        cases.push_back(c);
    }
    // Aimed at a point of an edge (one coordinate free) or a corner: D = P - O rounds, so the ray
    // crosses the box by an ulp or misses it by one.
    for (int k = 0; k < 200; ++k) {
        PortableRandom random = next();
        const bool corner = k >= 120;
        SlabCase c{{}, {}, {}, corner ? "through a corner" : "through an edge"};
        random_box(random, c.min, c.max);
        Vec3 target = inside(random, c.min, c.max);
        const int free_axis = corner ? -1 : static_cast<int>(random.integer(0, 2));
        for (int axis = 0; axis < 3; ++axis) {
            if (axis != free_axis) target[axis] = random.unit() < 0.5 ? c.min[axis] : c.max[axis];
        }
        const Vec3 origin = target + random.uniform(0.5, 4.0) * random.unit_vector();
        c.ray = {origin, target - origin};
        if (k % 5 == 4) c.ray.t_min = random.uniform(0.0, 0.9);
        if (k % 5 == 3) c.ray.t_max = random.uniform(1.1, 3.0);
        cases.push_back(c);
    }
    // Touching an edge or a corner exactly, in whole numbers: the ray leaves one slab at P as it
    // enters another, so the interval is the single point t = 1 (or 2, 3), and each slab's t is
    // an integer times a rounded reciprocal.
    for (int k = 0; k < 120; ++k) {
        PortableRandom random = next();
        const bool corner = k >= 70;
        SlabCase c{{}, {}, {}, corner ? "touching a corner" : "touching an edge"};
        for (int axis = 0; axis < 3; ++axis) {
            c.min[axis] = static_cast<double>(random.integer(-8, 0));
            c.max[axis] = c.min[axis] + static_cast<double>(random.integer(2, 8));
        }
        const int free_axis = corner ? -1 : static_cast<int>(random.integer(0, 2));
        const int leaving_axis = (free_axis + 1 + static_cast<int>(random.integer(0, 1))) % 3;
        Vec3 touch;
        Vec3 direction;
        for (int axis = 0; axis < 3; ++axis) {
            const double magnitude = kOddSteps[random.integer(0, 4)];
            if (axis == free_axis) {
                touch[axis] = c.min[axis] + 1.0;  // strictly inside: the box is at least 2 long
                direction[axis] = random.unit() < 0.5 ? -magnitude : magnitude;
                continue;
            }
            const bool at_max = random.unit() < 0.5;
            touch[axis] = at_max ? c.max[axis] : c.min[axis];
            // Outwards across the face on the leaving axis, inwards on the others
            const bool outwards = axis == leaving_axis;
            direction[axis] = (at_max == outwards) ? magnitude : -magnitude;
        }
        const double t = static_cast<double>(random.integer(1, 3));
        c.ray = {touch - t * direction, direction};
        cases.push_back(c);
    }
    // From outside, through the box's middle, with t_min and t_max on either side of its entry
    // and exit
    for (int k = 0; k < 40; ++k) {
        PortableRandom random = next();
        SlabCase c{{}, {}, {}, "a bounded interval from outside"};
        random_box(random, c.min, c.max);
        const Vec3 origin = inside(random, c.min, c.max) + 5.0 * random.unit_vector();
        c.ray = {origin, inside(random, c.min, c.max) - origin};
        c.ray.t_min = random.uniform(0.0, 1.2);
        c.ray.t_max = c.ray.t_min + random.uniform(0.0, 0.6);
        cases.push_back(c);
    }
    return cases;
}

// Rays lying in a face's plane: the direction's component along that axis is +0 or -0 and the
// origin is on the min or the max plane, so one of the axis' two t's is 0 * inf = NaN. Every
// axis, both planes and both zeros, as the NaN must be harmless whichever axis it comes from
// (a NaN on the last axis is not overwritten by another) and whichever bound it falls on. The
// origin is outside the face (aimed into it), inside it, or on one of its edges (aimed inwards,
// or along the edge, where a second axis gives a NaN too); t_min and t_max vary as elsewhere, so
// a NaN that throws away t_min or t_max is seen as well as one that turns a hit into a miss.
std::vector<SlabCase> face_plane_cases() {
    static const char* const kAxes[] = {"x", "y", "z"};
    static const char* const kPlaces[] = {"outside the face", "inside the face",
                                          "on an edge of the face"};
    const Vec3 min(-1, -2, 0.5), max(3, 1, 2.5);
    std::vector<SlabCase> cases;
    std::uint64_t number = 0;
    for (int axis = 0; axis < 3; ++axis) {
        const int b = (axis + 1) % 3;
        const int c = (axis + 2) % 3;
        for (const bool on_max : {false, true}) {
            for (const double zero : {0.0, -0.0}) {
                for (int place = 0; place < 3; ++place) {
                    for (int k = 0; k < 4; ++k) {
                        PortableRandom random(kFacePlaneSeed, number++);
                        SlabCase s{{},
                                   min,
                                   max,
                                   std::string("in the ") + kAxes[axis] + " = " +
                                       (on_max ? "max" : "min") + " face's plane, D." +
                                       kAxes[axis] + " = " + (std::signbit(zero) ? "-0" : "+0") +
                                       ", origin " + kPlaces[place]};
                        Vec3 origin = inside(random, min, max);
                        origin[axis] = on_max ? max[axis] : min[axis];
                        Vec3 direction = random.unit_vector();
                        if (place == 0) {
                            // Beyond the face along b, aimed at a point inside it
                            const Vec3 target = inside(random, min, max);
                            origin[b] = min[b] - random.uniform(0.5, 3.0);
                            direction[b] = target[b] - origin[b];
                            direction[c] = target[c] - origin[c];
                        } else if (place == 2) {
                            // On the face's edge along c; inwards across b, or along the edge
                            const bool edge_at_max = random.unit() < 0.5;
                            origin[b] = edge_at_max ? max[b] : min[b];
                            if (k % 2 == 0) {
                                direction[b] = zero;
                            } else {
                                direction[b] = std::fabs(direction[b]) * (edge_at_max ? -1 : 1);
                            }
                        }
                        direction[axis] = zero;
                        s.ray = {origin, direction};
                        random_interval(random, k, s.ray);
                        cases.push_back(s);
                    }
                }
            }
        }
    }
    return cases;
}

// The cases the slab formula gets wrong when written straight from the slide.
std::vector<SlabCase> named_cases() {
    const double inf = HUGE_VAL;
    const Vec3 low(-1, -1, -1), high(1, 1, 1);
    return {
        {{{0, 0, -5}, {0, 0, 1}}, low, high, "straight through"},
        {{{1, 0, -5}, {0, 0, 1}}, low, high, "on the x = 1 face's plane (0 * inf)"},
        {{{1.5, 0, -5}, {0, 0, 1}}, low, high, "beside the box, parallel"},
        {{{-1, -1, -5}, {0, 0, 1}}, low, high, "along an edge"},
        {{{0, 0, -5}, {0, 0, 1}}, {0, 0, 0}, {0, 0, 0}, "a point box on the ray"},
        {{{0, 0, -5}, {0, 0, 1}}, {inf, inf, inf}, {-inf, -inf, -inf}, "the empty box"},
        {{{0, 0, 5}, {0, 0, 1}}, low, high, "behind the origin"},
        {{{0, 0, 0}, {0, 0, 1}}, low, high, "from inside"},
        {{{0, 0, -5}, {0, 0, 1}, 0.0, 3.0}, low, high, "t_max before the box"},
        {{{0, 0, -5}, {0, 0, 1}, 4.5, 5.5}, low, high, "t_min and t_max inside the box"},
        {{{0, 0, 0}, {0, 0, 1}, 2.0, inf}, low, high, "from inside, t_min beyond the exit"},
        {{{0, 0, 0}, {0, 0, 1}, 0.5, inf}, low, high, "from inside, t_min before the exit"},
        {{{0, 0, -5}, {-0.0, 0.0, 1}}, low, high, "a direction of -0 along x"},
        {{{1, 1, -5}, {-0.0, -0.0, 1}}, low, high, "-0 along x and y, on an edge's planes"},
        {{{0.5, 0.5, 0.5}, {0, 0, 0}}, low, high, "no direction, origin inside"},
        {{{2, 0, 0}, {0, 0, 0}}, low, high, "no direction, origin outside"},
        {{{-3, -3, -3}, {1, 1, 1}}, low, high, "through two opposite corners"},
        {{{1, 1, 1}, {1, 1, 1}}, low, high, "from a corner, outwards"},
        {{{1, 0, 0}, {-1, 0, 0}, 1.0, 1.0}, low, high, "t_min = t_max inside the box"},
        {{{0, 0, -1e100}, {0, 0, 1e100}},
         {-1e99, -1e99, -1e99},
         {1e99, 1e99, 1e99},
         "far and huge"},
    };
}

}  // namespace

std::vector<PublicCase> slab_cases() {
    std::vector<SlabCase> all = named_cases();
    for (const SlabCase& c : generated_cases())
        all.push_back(c);
    for (const SlabCase& c : face_plane_cases())
        all.push_back(c);
    std::vector<PublicCase> cases;
    for (const SlabCase& c : all) {
        cases.push_back({c.what + ": " + ray_text(c.ray) + ", box " + full_text(c.min) + " to " +
                             full_text(c.max),
                         probe::query(probe::intersect_aabb_call, {c.ray, c.min, c.max}),
                         slab_interval_judge(exact_interval(c)),
                         "intersect_aabb(" + cpp(c.ray) + ", 1.0 / Vec3" + cpp(c.ray.direction) +
                             ", Aabb{" + cpp(c.min) + ", " + cpp(c.max) + "})"});
    }
    return cases;
}

}  // namespace raystep::grade
