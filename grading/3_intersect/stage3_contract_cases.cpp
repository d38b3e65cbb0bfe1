#include "grading/3_intersect/stage3_contract_cases.h"

#include <cmath>
#include <limits>

#include "grading/3_intersect/undecided_case.h"

namespace raystep {

namespace {

// A triangle in the plane coordinate `axis` = 0.5, its normal along +axis (sign 1) or -axis
// (sign -1), its vertices lifted off that plane by tilt times (0, 1, -0.5): a tilt of 0 puts the
// normal exactly on the axis, the projection method's choice of the coordinate to drop. The
// other two coordinates follow the axis cyclically, so that counter-clockwise there is +axis.
Triangle axis_triangle(int axis, double sign, double tilt) {
    const int u = (axis + 1) % 3;
    const int v = (axis + 2) % 3;
    const auto vertex = [&](double a, double b, double lift) {
        Vec3 p;
        p[axis] = 0.5 + lift;
        p[u] = a;
        p[v] = b;
        return p;
    };
    const Vec3 p0 = vertex(-1, -1, 0);
    const Vec3 p1 = vertex(1, -1, tilt);
    const Vec3 p2 = vertex(0, 1, -0.5 * tilt);
    return sign > 0 ? Triangle{p0, p1, p2} : Triangle{p0, p2, p1};
}

// A ray along -sign * axis (from the side the normal of axis_triangle points to) or against it,
// through the point (0.2, -0.3) of the other two coordinates, well inside the triangle.
Ray along_axis(int axis, double sign) {
    Vec3 origin;
    origin[axis] = 0.5 + 5 * sign;
    origin[(axis + 1) % 3] = 0.2;
    origin[(axis + 2) % 3] = -0.3;
    Vec3 direction(0.0);
    direction[axis] = -sign;
    return Ray{origin, direction};
}

void number(CaseFamily& family) {
    for (std::size_t k = 0; k < family.cases.size(); ++k)
        family.cases[k].index = k;
}

}  // namespace

// The contract on hand-picked cases, which random families reach seldom: a ray's [t_min, t_max]
// cutting a hit off among several primitives, triangles in the coordinate planes (the projection
// method's choice of axis), several primitives at once, the nearest not the first in closest_hit's
// order (spheres, triangles, planes), slivers whose double cross product is not zero though an
// edge's inward normal rounds to zero (the half-spaces method's 0 / 0 barycentric), triangles whose
// normal lies on or next to each positive and each negative axis (a projection that picks the axis
// by the signed component instead of its magnitude projects those along a negative axis to a
// segment), and rays nearly parallel to a plane, D . N from 1e-7 down to a few times the oracle's
// grazing bound, that cross it inside [t_min, t_max] (only an exactly parallel ray misses).
CaseFamily contract_family() {
    const double inf = HUGE_VAL;
    const Triangle in_z{{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}};
    const Triangle in_x{{2, -1, -1}, {2, 1, -1}, {2, 0, 1}};
    const Triangle in_y{{-1, -3, -1}, {0, -3, 1}, {1, -3, -1}};
    const Sphere unit{{0, 0, 0}, 1};
    const Sphere far_sphere{{0, 0, 10}, 1};
    const Plane at_z3{{0, 0, 3}, {0, 0, 1}};
    const Plane at_z15{{0, 0, 15}, {0, 0, -1}};
    CaseFamily family{
        "contract",
        0,
        "t ranges, triangles in coordinate planes, nearest of several, ties, slivers",
        {
            undecided_case({{0.3, -0.2, 5}, {0, 0, -1}}, in_z),
            undecided_case({{3, 0, 5}, {0, 0, -1}}, in_z),
            undecided_case({{-0.2, 0.5, 5}, {0.05, -0.1, -1}}, in_z),
            undecided_case({{5, 0.1, 0.1}, {-1, 0, 0}}, in_x),
            undecided_case({{5, 0.9, 0.9}, {-1, 0, 0}}, in_x),
            undecided_case({{-4, -0.3, -0.5}, {1, 0.02, 0.03}}, in_x),
            undecided_case({{0.1, 2, -0.2}, {0, -1, 0}}, in_y),
            undecided_case({{0.9, 2, 0.9}, {0, -1, 0}}, in_y),
            undecided_case({{0, 0, -5}, {0, 0, 1}}, unit),
            undecided_case({{0, 0, 5}, {0, 0, -1}, 0.0, 3.0}, at_z3),
            undecided_case_of_all({{0, 0, -5}, {0, 0, 1}}, {far_sphere, in_z, at_z3}),
            undecided_case_of_all({{0.1, 0.1, 20}, {0, 0, -1}}, {far_sphere, in_z, at_z15}),
            undecided_case_of_all({{0.1, 0.1, 20}, {0, 0, -1}, 0.0, 8.0},
                                  {far_sphere, in_z, at_z15}),
            undecided_case_of_all({{0.1, 0.1, 20}, {0, 0, -1}, 6.0, inf},
                                  {far_sphere, in_z, at_z15}),
            undecided_case_of_all({{0.1, 0.1, 20}, {0, 0, -1}, 12.0, inf},
                                  {far_sphere, in_z, at_z15}),
            undecided_case(
                {{1.0275703435596424, 0.78125, 3.2150703435596424},
                 {-0.7071067811865475, -0.0, -0.7071067811865475}},
                Triangle{{-0.875, 0.625, 0.875}, {-1.3125, 0.9374999999999999, 1.3125}, {0, 0, 0}}),
            undecided_case({{-0.6853907864998738, -0.28125, 3.0582815729997477},
                            {0.4472135954999579, -0.0, -0.8944271909999159}},
                           Triangle{{0.875, -0.375, 0.5},
                                    {0.4375, -0.18749999999999997, 0.24999999999999997},
                                    {0, 0, 0}}),
        }};
    for (int axis = 0; axis < 3; ++axis) {
        for (const double sign : {1.0, -1.0}) {
            for (const double tilt : {0.0, 1e-3, 1e-9}) {
                family.cases.push_back(
                    undecided_case(along_axis(axis, sign), axis_triangle(axis, sign, tilt)));
            }
            family.cases.push_back(
                undecided_case(along_axis(axis, -sign), axis_triangle(axis, sign, 0.0)));
        }
    }
    const Plane z0{{0, 0, 0}, {0, 0, 1}};
    const Plane tilted{{0, 0, 0}, {1, 1, 1}};
    for (const double d_dot_n : {1e-7, 1e-9, 1e-11, 1e-13}) {
        // From above z = 0 going down, and from below the tilted plane going up; both cross at
        // t = 1, up to the rounding of the inputs.
        family.cases.push_back(
            undecided_case({{-0.4, 0.2, d_dot_n}, {1, 0.5, -d_dot_n}, 0.5, 2.0}, z0));
        family.cases.push_back(
            undecided_case({{-0.5, 0.5, -d_dot_n}, {1, -1, d_dot_n}, 0.5, 2.0}, tilted));
    }
    number(family);
    return family;
}

// The contract's exact sentences, on cases every correct test computes without rounding: small
// dyadic coordinates, axis-parallel rays and edges, powers of two at the ends of the domain, so
// that every product, quotient and square root is exact. There the oracle's "near a boundary,
// either passes" does not apply, and each sentence of intersect.h has a case that fails a test
// breaking it: edges and vertices belong to the triangle, a tangent ray touches the sphere,
// surfaces two-sided, a ray a power of two off parallel a hit, the domain's ends. The range's
// ends, ties, rays in a plane and degenerate input are checks of their own
// (stage3_contract_edges.h).
CaseFamily exact_family() {
    const double big = std::ldexp(1.0, 330);  // 2.2e99: three such factors stay finite
    const double small = std::ldexp(1.0, -330);
    const double sphere_big = std::ldexp(1.0, 250);  // the quadratic multiplies four
    const double sphere_small = std::ldexp(1.0, -250);
    const Triangle in_z{{-1, -1, 0}, {1, -1, 0}, {0, 1, 0}};
    const Triangle in_y{{-1, -3, -1}, {0, -3, 1}, {1, -3, -1}};
    const Sphere unit{{0, 0, 0}, 1};
    const Plane at_z3{{0, 0, 3}, {0, 0, 1}};
    const Plane z0{{0, 0, 0}, {0, 0, 1}};
    // Rays a power of two off parallel to z0, down to 4 ulps of their length: D . N and t = 1
    // are exact, so they hit, though the oracle counts the last as grazing.
    const auto nearly_parallel = [](int exponent) {
        const double height = std::ldexp(1.0, exponent);
        return Ray{{-0.5, 0.25, height}, {1, 0, -height}, 0.5, 2.0};
    };
    const auto scaled = [](const Triangle& t, double k) {
        return Triangle{t.p0 * k, t.p1 * k, t.p2 * k};
    };
    CaseFamily family{
        "exact",
        0,
        "the contract on cases no rounding can move: edges, tangents, two sides, the domain",
        {
            undecided_case({{1, 0, -5}, {0, 0, 1}}, unit),  // tangent: a double root
            undecided_case({{0, -0.5, -5}, {0, 0, 1}},
                           Sphere{{0, 0, 0}, 0.5}),                // tangent from below
            undecided_case({{0.5, -1, 5}, {0, 0, -1}}, in_z),      // on the edge p0 p1
            undecided_case({{1, -1, 5}, {0, 0, -1}}, in_z),        // on the vertex p1
            undecided_case({{0.5, 2, -1}, {0, -1, 0}}, in_y),      // on the edge p2 p0
            undecided_case({{0.25, -0.25, -5}, {0, 0, 1}}, in_z),  // from behind
            undecided_case({{0, 0, 0}, {0, 0, 1}}, at_z3),         // from behind
            undecided_case(nearly_parallel(-24), z0),
            undecided_case(nearly_parallel(-40), z0),
            undecided_case(nearly_parallel(-50), z0),
            undecided_case({{0, 0, 5 * big}, {0, 0, -big}}, Plane{{0, 0, 3 * big}, {0, 0, small}}),
            undecided_case({{0.25 * big, -0.25 * big, 5 * big}, {0, 0, -big}}, scaled(in_z, big)),
            undecided_case({{0.25 * small, -0.25 * small, 5 * small}, {0, 0, -small}},
                           scaled(in_z, small)),
            undecided_case({{0, 0, -5 * sphere_big}, {0, 0, sphere_big}},
                           Sphere{{0, 0, 0}, sphere_big}),
            undecided_case({{0, 0, -5 * sphere_small}, {0, 0, sphere_small}},
                           Sphere{{0, 0, 0}, sphere_small}),
        }};
    number(family);
    return family;
}

void tighten_exact_family(CaseFamily& family) {
    for (RayCase& ray_case : family.cases) {
        for (CasePrimitive& primitive : ray_case.primitives) {
            Expectation& e = primitive.expected;
            e.near_boundary = false;
            if (e.hit) e.t_tolerance = 0.0;
            // A sphere's far root passes beside the near one only where rounding may move the
            // near root across t_min: here it cannot, and the near root at t_min is the answer.
            e.t_alternative = std::numeric_limits<double>::quiet_NaN();
            e.normal_alternative = Vec3(std::numeric_limits<double>::quiet_NaN());
        }
    }
}

}  // namespace raystep
