#include "grading/3_intersect/stage3_contract_edges.h"

#include <cmath>
#include <utility>

#include <glm/geometric.hpp>

#include "grading/3_intersect/collinear_triangles.h"
#include "grading/3_intersect/dyadic_hits.h"
#include "grading/3_intersect/undecided_case.h"

namespace raystep {

namespace {

// Each family draws from its own seed, so that one grading seed gives unrelated cases.
constexpr std::uint64_t kRangeEndSalt = 0x7A11'0001;
constexpr std::uint64_t kTieSalt = 0x7A11'0002;
constexpr std::uint64_t kInPlaneSalt = 0x7A11'0003;
constexpr std::uint64_t kDegenerateSalt = 0x7A11'0004;

constexpr double kInf = HUGE_VAL;

// The hand-picked cases' primitives: the unit sphere, the plane z = 3, a triangle in z = 0.
const Sphere kUnit{{0, 0, 0}, 1};
const Plane kAtZ3{{0, 0, 3}, {0, 0, 1}};
const Triangle kInZ{{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}};

int random_axis(PortableRandom& random) {
    return static_cast<int>(random.integer(0, 2));
}

// A multiple of 1/4 from 1/4 to 2: a step along a ray, in units of t.
double quarter_steps(PortableRandom& random) {
    return static_cast<double>(random.integer(1, 8)) / 4.0;
}

// Fisher-Yates, from the case's own generator.
void shuffle(PortableRandom& random, std::vector<CaseShape>& shapes) {
    for (std::size_t k = shapes.size(); k > 1; --k) {
        const auto j =
            static_cast<std::size_t>(random.integer(0, static_cast<std::int64_t>(k - 1)));
        std::swap(shapes[k - 1], shapes[j]);
    }
}

CaseFamily drawn(const char* name, const char* description, std::uint64_t seed,
                 std::vector<RayCase> hand_picked, std::size_t count,
                 RayCase (*make)(PortableRandom&, std::size_t), std::uint64_t salt) {
    CaseFamily family{name, seed, description, std::move(hand_picked)};
    for (std::size_t k = 0; k < count; ++k) {
        PortableRandom random(seed + salt, k);
        family.cases.push_back(make(random, k));
    }
    for (std::size_t k = 0; k < family.cases.size(); ++k)
        family.cases[k].index = k;
    return family;
}

// A plane or a triangle met at `point` by an oblique ray, or a sphere entered there by a ray
// along an axis (its near root, or the far one at t + chord / |D|), the range ending exactly at
// the root asked for or a step short of it; or a triangle at an end with a plane just beyond that
// end.
RayCase range_end_case(PortableRandom& random, std::size_t) {
    const Vec3 point = dyadic_point(random, 4.0);
    const int axis = random_axis(random);
    double t = 0.0;
    const auto kind = random.integer(0, 3);
    if (kind == 2) {
        Ray ray = dyadic_ray_to(random, point, axis, true, t);
        double chord = 0.0;
        const double sign = ray.direction[axis] > 0.0 ? 1.0 : -1.0;
        const Sphere sphere = dyadic_sphere_entered_at(random, point, axis, sign, chord);
        const double far = t + chord / std::abs(ray.direction[axis]);
        switch (random.integer(0, 5)) {
            case 0:  // the near root at t_min
                ray.t_min = t;
                break;
            case 1:  // the near root at t_max
                ray.t_max = t;
                break;
            case 2:  // the far root at t_max, the near one before t_min
                ray.t_min = (t + far) / 2.0;
                ray.t_max = far;
                break;
            case 3:  // the far root at t_min, the near one before it
                ray.t_min = far;
                break;
            case 4:  // both roots beyond t_max: a miss
                ray.t_max = t - quarter_steps(random) / 2.0;
                break;
            default:  // both roots before t_min: a miss
                ray.t_min = far + quarter_steps(random);
                break;
        }
        return undecided_case(ray, sphere);
    }
    Ray ray = dyadic_ray_to(random, point, axis, false, t);
    if (kind == 3) {
        // The triangle at one end, a plane normal to the axis a little beyond it
        const double beyond = quarter_steps(random);
        const bool at_t_max = random.unit() < 0.5;
        const Vec3 other = point + (at_t_max ? beyond : -beyond) * ray.direction;
        (at_t_max ? ray.t_max : ray.t_min) = t;
        return undecided_case_of_all(ray, {dyadic_triangle_around(random, point, axis),
                                           dyadic_plane_through(random, other, axis)});
    }
    // The hit at t_min or t_max, or a step beyond either (a miss)
    const double step = random.unit() < 0.25 ? quarter_steps(random) / 2.0 : 0.0;
    if (random.unit() < 0.5) {
        ray.t_min = t + step;
        if (random.unit() < 0.5) ray.t_max = ray.t_min + quarter_steps(random);
    } else {
        ray.t_max = t - step;
        if (random.unit() < 0.5) ray.t_min = ray.t_max / 2.0;
    }
    if (kind == 0) return undecided_case(ray, dyadic_plane_through(random, point, axis));
    return undecided_case(ray, dyadic_triangle_around(random, point, axis));
}

// Primitives of kind 0 (sphere), 1 (triangle) or 2 (plane) that the ray along `axis` meets at
// `point`, each a draw of its own.
CaseShape met_at(PortableRandom& random, int kind, const Vec3& point, int axis, double sign) {
    if (kind == 0) {
        double chord = 0.0;
        return dyadic_sphere_entered_at(random, point, axis, sign, chord);
    }
    if (kind == 1) return dyadic_triangle_around(random, point, axis);
    return dyadic_plane_through(random, point, axis);
}

// Copies of one primitive, or different primitives of one kind, or of several kinds, all met at
// t, with a primitive met farther on, in a shuffled list.
RayCase tie_case(PortableRandom& random, std::size_t) {
    const Vec3 point = dyadic_point(random, 4.0);
    const int axis = random_axis(random);
    double t = 0.0;
    const Ray ray = dyadic_ray_to(random, point, axis, true, t);
    const double sign = ray.direction[axis] > 0.0 ? 1.0 : -1.0;
    const auto kind = static_cast<int>(random.integer(0, 2));
    std::vector<CaseShape> shapes;
    switch (random.integer(0, 2)) {
        case 0: {  // copies
            const CaseShape shape = met_at(random, kind, point, axis, sign);
            shapes.assign(static_cast<std::size_t>(random.integer(2, 3)), shape);
            break;
        }
        case 1:  // different primitives of one kind
            for (auto k = random.integer(2, 3); k > 0; --k)
                shapes.push_back(met_at(random, kind, point, axis, sign));
            break;
        default:  // several kinds: every kind but `kind`, or all three
            for (int other = 0; other < 3; ++other) {
                if (other == kind && random.unit() < 0.5) continue;
                for (auto k = random.integer(1, 2); k > 0; --k)
                    shapes.push_back(met_at(random, other, point, axis, sign));
            }
            break;
    }
    const Vec3 farther = point + quarter_steps(random) * ray.direction;
    shapes.push_back(met_at(random, kind, farther, axis, sign));
    shuffle(random, shapes);
    return undecided_case_of_all(ray, shapes);
}

// A ray lying in a plane, or in a triangle's plane (through the triangle or beside it), from
// outside or from a point of it; or along an axis in such a plane or triangle, crossing a
// sphere or a plane farther on that closest_hit must return.
RayCase in_plane_case(PortableRandom& random, std::size_t) {
    const Vec3 point = dyadic_point(random, 4.0);
    const int axis = random_axis(random);
    const int u = (axis + 1) % 3;
    const int v = (axis + 2) % 3;
    const auto kind = random.integer(0, 2);
    const CaseShape lying_in = random.unit() < 0.5
                                   ? CaseShape(dyadic_plane_through(random, point, axis))
                                   : CaseShape(dyadic_triangle_around(random, point, axis));
    const double t = static_cast<double>(random.integer(0, 32)) / 4.0;
    if (kind == 2) {
        // Along u, crossing a sphere or a plane normal to u farther on
        Vec3 direction(0.0);
        const double sign = random.unit() < 0.5 ? -1.0 : 1.0;
        direction[u] = sign * std::ldexp(1.0, static_cast<int>(random.integer(-2, 2)));
        const Vec3 crossing = point + quarter_steps(random) * direction;
        const CaseShape crossed = met_at(random, random.unit() < 0.5 ? 0 : 2, crossing, u, sign);
        return undecided_case_of_all(Ray{point - t * direction, direction}, {lying_in, crossed});
    }
    // In the plane, its larger component a power of two (dyadic_hits.h says why)
    Vec3 direction(0.0);
    direction[u] = (random.unit() < 0.5 ? -1.0 : 1.0) *
                   std::ldexp(1.0, static_cast<int>(random.integer(0, 2)));
    direction[v] = dyadic(random, 1.0);
    if (random.unit() < 0.5) std::swap(direction[u], direction[v]);
    Vec3 through = point;
    if (kind == 1) through[u] += dyadic(random, 8.0);  // beside the triangle, or not
    return undecided_case(Ray{through - t * direction, direction}, lying_in);
}

// Of every eight cases, five collinear triangles that Cramer's rule (the even ones) or
// Moller-Trumbore (the odd ones) would hit without a zero-normal test, half of them with a plane
// behind; then a repeated vertex; a zero direction against every kind; a zero radius and a zero
// plane normal.
RayCase degenerate_case(PortableRandom& random, std::size_t k) {
    switch (k % 8) {
        case 6: {  // a zero direction against every kind
            const Vec3 origin = random.point(4.0);
            return undecided_case_of_all(
                Ray{origin, Vec3(0.0)},
                {Triangle{random.point(2.0), random.point(2.0), random.point(2.0)},
                 Sphere{random.point(2.0), random.uniform(0.1, 2.0)},
                 Plane{random.point(2.0), random.unit_vector()}});
        }
        case 7: {  // a zero radius and a zero normal, the ray aimed at each
            const Vec3 target = random.point(2.0);
            const Vec3 origin = target + random.unit_vector() * random.uniform(2.0, 8.0);
            return undecided_case_of_all(Ray{origin, target - origin},
                                         {Sphere{target, 0.0}, Plane{target, Vec3(0.0)}});
        }
        case 5: {  // a repeated vertex, the ray aimed at the segment
            const Vec3 p = random.point(2.0);
            const Vec3 q = random.point(2.0);
            const Vec3 target = p + random.unit() * (q - p);
            const Vec3 origin = target + random.unit_vector() * random.uniform(2.0, 8.0);
            const auto which = random.integer(0, 2);
            const Triangle repeated = which == 0   ? Triangle{p, p, q}
                                      : which == 1 ? Triangle{p, q, q}
                                                   : Triangle{p, q, p};
            return undecided_case(Ray{origin, target - origin}, repeated);
        }
        default:
            break;
    }
    const CollinearCase drawn =
        collinear_case(random, k % 2 == 0 ? SolveForm::cramer : SolveForm::moller_trumbore);
    if (random.unit() < 0.5) return undecided_case(drawn.ray, drawn.triangle);
    // A plane the ray crosses beyond the triangle: closest_hit's answer
    const Vec3 d = drawn.ray.direction;
    const Plane behind{drawn.ray.origin + random.uniform(1.5, 4.0) * d,
                       -d + 0.3 * glm::length(d) * random.unit_vector()};
    return undecided_case_of_all(drawn.ray, {drawn.triangle, behind});
}

}  // namespace

CaseFamily range_end_family(std::uint64_t seed, std::size_t count) {
    return drawn(
        "range-ends", "hits exactly at t_min or t_max, which are in the range, or just beyond them",
        seed,
        {
            undecided_case({{0, 0, 5}, {0, 0, -1}, 0.0, 2.0}, kAtZ3),         // t = t_max
            undecided_case({{0, 0, 5}, {0, 0, -1}, 2.0, kInf}, kAtZ3),        // t = t_min
            undecided_case({{0, 0, -5}, {0, 0, 1}, 4.0, kInf}, kUnit),        // near root at t_min
            undecided_case({{0, 0, -5}, {0, 0, 1}, 0.0, 4.0}, kUnit),         // near root at t_max
            undecided_case({{0, 0, -5}, {0, 0, 1}, 5.0, 6.0}, kUnit),         // far root at t_max
            undecided_case({{0, 0, -5}, {0, 0, 1}, 6.0, kInf}, kUnit),        // far root at t_min
            undecided_case({{0.25, -0.25, 5}, {0, 0, -1}, 0.0, 5.0}, kInZ),   // t = t_max
            undecided_case({{0.25, -0.25, 5}, {0, 0, -1}, 5.0, kInf}, kInZ),  // t = t_min
            undecided_case({{0.25, -0.25, 5}, {0, 0, -1}, 6.0, kInf}, kInZ),  // before t_min
            undecided_case({{0.25, -0.25, 5}, {0, 0, -1}, 0.0, 4.0}, kInZ),   // beyond t_max
            undecided_case({{0.25, -0.25, 5}, {0, 0, 1}}, kInZ),              // behind the origin
            undecided_case({{0, 0, -5}, {0, 0, 1}, 0.0, 3.0}, kUnit),  // both roots beyond t_max
            undecided_case({{0, 0, -5}, {0, 0, 1}, 4.5, kInf},
                           kUnit),  // the near root before t_min
            undecided_case({{0, 0, -5}, {0, 0, 1}, 6.5, kInf}, kUnit),  // both before t_min
            undecided_case({{0, 0, 5}, {0, 0, 1}}, kUnit),              // behind the origin
            undecided_case({{0, 0, 5}, {0, 0, -1}, 0.0, 1.0}, kAtZ3),   // beyond t_max
            undecided_case({{0, 0, 5}, {0, 0, -1}, 2.5, kInf}, kAtZ3),  // before t_min
        },
        count, range_end_case, kRangeEndSalt);
}

CaseFamily tie_family(std::uint64_t seed, std::size_t count) {
    const Sphere far_sphere{{0, 0, 10}, 1};
    const Sphere under_z0{{0.25, -0.25, -1}, 1};  // touches z = 0 at (0.25, -0.25, 0)
    const Plane z0{{0, 0, 0}, {0, 0, 1}};
    return drawn(
        "ties", "primitives met at the same t: the first in closest_hit's order wins", seed,
        {
            undecided_case_of_all({{0, 0, -5}, {0, 0, 1}}, {kUnit, kUnit}),
            undecided_case_of_all({{0.25, -0.25, 5}, {0, 0, -1}}, {kInZ, kInZ, kInZ}),
            undecided_case_of_all({{0, 0, 5}, {0, 0, -1}}, {kAtZ3, kAtZ3}),
            undecided_case_of_all({{0, 0, -5}, {0, 0, 1}}, {far_sphere, kUnit, kInZ, kUnit, kInZ}),
            undecided_case_of_all({{0.25, -0.25, 5}, {0, 0, -1}},
                                  {z0, kInZ, under_z0}),                        // the sphere wins
            undecided_case_of_all({{0.25, -0.25, 5}, {0, 0, -1}}, {z0, kInZ}),  // the triangle wins
        },
        count, tie_case, kTieSalt);
}

CaseFamily in_plane_family(std::uint64_t seed, std::size_t count) {
    return drawn("rays-in-plane", "rays lying in a plane or a triangle's plane: a miss", seed,
                 {
                     undecided_case({{0, 0, 3}, {1, 0, 0}}, kAtZ3),
                     undecided_case({{-5, -0.5, 0}, {1, 0, 0}}, kInZ),
                 },
                 count, in_plane_case, kInPlaneSalt);
}

CaseFamily degenerate_family(std::uint64_t seed, std::size_t count) {
    const Triangle collinear{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}};
    return drawn("degenerate",
                 "collinear triangles, repeated vertices, zero directions, radii and normals: a "
                 "miss, never a NaN",
                 seed,
                 {
                     undecided_case_of_all({{0, 0, 5}, {0, 0, 0}}, {kUnit, kInZ, kAtZ3}),
                     undecided_case({{0, 0, 5}, {0, 0, -1}}, Sphere{{0, 0, 0}, 0.0}),
                     undecided_case({{1, 1, 5}, {0, 0, -1}}, collinear),
                     undecided_case({{0, 0, 5}, {0, 0, -1}}, Plane{{0, 0, 0}, {0, 0, 0}}),
                 },
                 count, degenerate_case, kDegenerateSalt);
}

}  // namespace raystep
