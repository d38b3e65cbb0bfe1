// Stage 5 checks: the op matrices, compose and the moves between frames on hand-worked values
// (public and hidden), and random op chains, rays, points, normals and ellipsoids against the
// same products and roots computed in long double (grading/5_transforms/transform_oracle.h).
//
// Every call but compose gets its transform from here (matrix and inverse built from the ops in
// long double), so that each function is judged on its own. Every case is judged by a data judge
// (grading/5_transforms/transform_judges.h, value_judges.h): the public ones go into the student
// release as data, and the others are judged by the same code.

#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <utility>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "app/grade/value_judges.h"
#include "base/math/portable_random.h"
#include "base/math/unit_roundoff.h"
#include "grader/grade/checks/cpp_literal.h"
#include "grader/grade/checks/data_judged.h"
#include "grader/grade/checks/judging.h"
#include "grader/grade/checks/stage_checks.h"
#include "grading/5_transforms/transform_calls.h"
#include "grading/5_transforms/transform_judges.h"
#include "grading/5_transforms/transform_oracle.h"

namespace raystep::grade {

namespace {

using probe::Json;

// The stage's public and generated checks' names, shared by the grader's checks and the release's
// case files.
constexpr const char* kPublicName = "transform matrices, compose and frames on hand-worked values";
constexpr const char* kOracleName =
    "rotations, random op chains, rays, points, normals and ellipsoids against long double";

const double kInf = std::numeric_limits<double>::infinity();

TransformOp translate_op(const Vec3& offset) {
    return {TransformOp::Kind::translate, offset, 0.0};
}

TransformOp rotate_op(const Vec3& axis, double degrees) {
    return {TransformOp::Kind::rotate, axis, degrees};
}

TransformOp scale_op(const Vec3& factors) {
    return {TransformOp::Kind::scale, factors, 0.0};
}

// rotation(axis, degrees) against Rodrigues in long double.
PublicCase rotation_case(const Vec3& axis, double degrees) {
    const WideOp w = wide_op(rotate_op(axis, degrees));
    return {"rotation(" + full_text(axis) + ", " + full_text(degrees) + ")",
            probe::query(probe::rotation_call, {axis, degrees}),
            near_wide_matrix_judge(double_double(w.matrix),
                                   double_double(8 * kWideUnitRoundoff * w.size)),
            "rotation(" + cpp(axis) + ", " + cpp(degrees) + ")"};
}

// translation and scaling have exact entries.
template <class Call>
PublicCase exact_matrix_case(const Call& call, const Vec3& v, const WideMat& expected) {
    const std::string name = call.name;
    return {name + "(" + full_text(v) + ")", probe::query(call, {v}),
            near_wide_matrix_judge(double_double(expected), DoubleDoubleMat4()),
            name + "(" + cpp(v) + ")"};
}

PublicCase invalid_axis_case(const Vec3& axis, double degrees) {
    return {"rotation(" + full_text(axis) + ", " + full_text(degrees) + "): no axis",
            probe::query(probe::rotation_call, {axis, degrees}), threw_judge("invalid_argument"),
            "rotation(" + cpp(axis) + ", " + cpp(degrees) + ")"};
}

// compose's argument as a student writes it: the ops in file order.
std::string compose_code(const std::vector<TransformOp>& ops) {
    std::string code;
    for (const TransformOp& op : ops)
        code += (code.empty() ? "" : ", ") + cpp(op);
    return "compose({" + code + "})";
}

PublicCase compose_case(const std::vector<TransformOp>& ops) {
    const WideTransform expected = wide_compose(ops);
    return {"compose(" + ops_text(ops) + ")", probe::query(probe::compose_call, ops),
            near_wide_transform_judge(
                double_double(expected.matrix), double_double(expected.matrix_tolerance),
                double_double(expected.inverse), double_double(expected.inverse_tolerance)),
            compose_code(ops)};
}

// Where every op's inverse is exact in double (a negated offset, a reciprocal that rounds to
// itself) and each entry of their product is a single product, exact too, the inverse must be
// exact: built from the ops, never by inverting M, which divides by its determinant.
PublicCase exact_inverse_case(const std::vector<TransformOp>& ops) {
    const WideTransform expected = wide_compose(ops);
    return {"compose(" + ops_text(ops) + "): the inverse from the ops' exact inverses",
            probe::query(probe::compose_call, ops),
            near_wide_transform_judge(
                double_double(expected.matrix), double_double(expected.matrix_tolerance),
                DoubleDoubleMat4(narrow(expected.inverse)), DoubleDoubleMat4()),
            compose_code(ops)};
}

// A scale with a zero factor has no inverse, and 1 / 0 is infinite: M^-1 must carry that
// infinity on the zero axis's diagonal (NaN where a product meets it) rather than a finite
// stand-in, which would pass for an inverse and be none. M itself and the other axes'
// reciprocals are exact.
PublicCase singular_scale_case(const Vec3& factors) {
    const std::vector<TransformOp> ops{scale_op(factors)};
    std::array<std::optional<double>, 3> diagonal;
    for (int k = 0; k < 3; ++k) {
        if (factors[k] != 0.0) diagonal[k] = 1.0 / factors[k];
    }
    return {"compose(" + ops_text(ops) + "): a zero factor's reciprocal is infinite",
            probe::query(probe::compose_call, ops),
            singular_transform_judge(narrow(wide_scaling(widen(factors))), diagonal),
            compose_code(ops)};
}

// The world ray in the object's frame: by M^-1, the direction not renormalized, t unchanged.
PublicCase ray_to_object_case(const std::string& name, const Transform& t, const Ray& ray) {
    const WideProduct origin = wide_product(t.inverse, ray.origin, 1.0);
    const WideProduct direction = wide_product(t.inverse, ray.direction, 0.0);
    return {name + ": ray_to_object of " + ray_text(ray) + ", " + transform_text(t),
            probe::query(probe::ray_to_object_call, {t, ray}),
            near_wide_ray_judge(
                double_double(origin.value), double_double(8 * kWideUnitRoundoff * origin.size),
                double_double(direction.value),
                double_double(8 * kWideUnitRoundoff * direction.size), ray.t_min, ray.t_max),
            "ray_to_object(" + cpp(t) + ", " + cpp(ray) + ")"};
}

PublicCase point_to_world_case(const std::string& name, const Transform& t, const Vec3& p) {
    const WideProduct expected = wide_product(t.matrix, p, 1.0);
    const Vec3 tolerance = 8 * kUnitRoundoff * narrow(expected.size);
    return {name + ": point_to_world of " + full_text(p) + ", " + transform_text(t),
            probe::query(probe::point_to_world_call, {t, p}),
            near_wide_vec3_judge(double_double(expected.value), DoubleDoubleVec3(tolerance)),
            "point_to_world(" + cpp(t) + ", " + cpp(p) + ")"};
}

PublicCase normal_to_world_case(const std::string& name, const Transform& t, const Vec3& n) {
    const WideNormal expected = wide_normal(t.inverse, widen(n));
    return {name + ": normal_to_world of " + full_text(n) + ", " + transform_text(t),
            probe::query(probe::normal_to_world_call, {t, n}),
            near_wide_vec3_judge(double_double(expected.value), double_double(expected.tolerance),
                                 true),
            "normal_to_world(" + cpp(t) + ", " + cpp(n) + ")"};
}

PublicCase transformed_sphere_case(const std::string& name, const Ray& ray, const Sphere& sphere,
                                   const Transform& t) {
    const TransformedSphereHit e = wide_transformed_hit(ray, sphere, t);
    return {name + ": " + ray_text(ray) + ", sphere centre " + full_text(sphere.center) +
                " radius " + full_text(sphere.radius) + ", " + transform_text(t),
            probe::query(probe::intersect_transformed_sphere_call, {ray, sphere, t}),
            e.hit ? near_wide_hit_judge(e.t, e.t_tolerance, double_double(e.normal.value),
                                        double_double(e.normal.tolerance))
                  : wide_miss_judge(),
            "intersect_transformed_sphere(" + cpp(ray) + ", " + cpp(sphere) + ", " + cpp(t) + ")"};
}

std::vector<PublicCase> public_cases() {
    // M = T(1, 2, 3) S(2, 4, 0.5): object (1, 1, 2) goes to (2, 4, 1) + (1, 2, 3) = (3, 6, 4).
    const Transform moved_and_scaled =
        transform_of({translate_op({1, 2, 3}), scale_op({2, 4, 0.5})});
    // M = T(5, 5, 5) S(2, 1, 4): M^-T n = S^-1 n (the translation drops out of a direction).
    const Transform squashed = transform_of({translate_op({5, 5, 5}), scale_op({2, 1, 4})});
    // The unit sphere scaled to radii (3, 2, 1), centred at (1, 0, 0).
    const Transform ellipsoid = transform_of({translate_op({1, 0, 0}), scale_op({3, 2, 1})});
    const Sphere unit{{0, 0, 0}, 1.0};
    return {
        exact_matrix_case(probe::translation_call, {2, -3, 0.5}, wide_translation({2, -3, 0.5})),
        exact_matrix_case(probe::scaling_call, {2, -0.5, 4}, wide_scaling({2, -0.5, 4})),
        // A quarter turn about +z takes x to y: columns (0, 1, 0), (-1, 0, 0), (0, 0, 1).
        rotation_case({0, 0, 1}, 90),
        // About +x, y goes to z.
        rotation_case({1, 0, 0}, 90),
        // An axis of length 2 is the unit axis +y.
        rotation_case({0, 2, 0}, 30),
        invalid_axis_case({0, 0, 0}, 30),
        compose_case({}),
        // M = T R S: the point (1, 0, 0) is scaled to (2, 0, 0), turned to (0, 2, 0), moved to
        // (1, 4, 3).
        compose_case({translate_op({1, 2, 3}), rotate_op({0, 0, 1}, 90), scale_op({2, 1, 1})}),
        // Scale 1e-3, then translate 1e4: M^-1 = T(-t) S(1000), every entry exact (1 / 1e-3
        // rounds to 1000), where an inverse of M divides by its determinant, 1e-9.
        exact_inverse_case({scale_op({1e-3, 1e-3, 1e-3}), translate_op({1e4, -2e4, 5e3})}),
        // M^-1 (3, 6, 4, 1) = S^-1 (2, 4, 1) = (1, 1, 2); M^-1 (0, 8, 1, 0) = (0, 2, 2), not
        // normalized; t_min and t_max unchanged.
        ray_to_object_case("T S", moved_and_scaled, {{3, 6, 4}, {0, 8, 1}, 0.25, 9.0}),
        point_to_world_case("T S", moved_and_scaled, {1, 1, 2}),
        // n = (1, 1, 1): M^-T n = (0.5, 1, 0.25), normalized; M n = (2, 1, 4) leans away.
        normal_to_world_case("T S", squashed, {1, 1, 1}),
        // M = R S, a quarter turn about z after stretching x by 2: M^-T = R S^-1, so
        // n = (1, 1, 0) goes to R (0.5, 1, 0) = (-1, 0.5, 0), normalized. Neither M n = (-1, 2, 0)
        // nor M^-1 n = (0.5, -1, 0) points that way.
        normal_to_world_case("R S", transform_of({rotate_op({0, 0, 1}, 90), scale_op({2, 1, 1})}),
                             {1, 1, 0}),
        // Straight down the y axis of the ellipsoid from y = 10: its top is at y = 2, so t = 8
        // along the unit world direction, normal (0, 1, 0). (The object-frame direction has
        // length 1/2: normalized, t would come out as 4.)
        transformed_sphere_case("radii (3, 2, 1) at (1, 0, 0)", {{1, 10, 0}, {0, -1, 0}}, unit,
                                ellipsoid),
        // Aimed at (1 + 3 * 0.6, 2 * 0.8, 0) = (2.8, 1.6, 0) along minus its gradient
        // (x / 9, y / 4, 0) = (0.2, 0.4, 0): the normal there is (1, 2, 0) / sqrt 5.
        transformed_sphere_case("radii (3, 2, 1) at (1, 0, 0)",
                                {{4.8, 5.6, 0}, glm::normalize(Vec3{-1, -2, 0})}, unit, ellipsoid),
        // z = 1.5 is above the ellipsoid's top (z = 1): a miss.
        transformed_sphere_case("radii (3, 2, 1) at (1, 0, 0)", {{1, 10, 1.5}, {0, -1, 0}}, unit,
                                ellipsoid),
    };
}

// The hidden ones: the contract's edge cases a student's own tests may not reach.
std::vector<PublicCase> hidden_cases() {
    const Transform turned_and_squashed =
        transform_of({translate_op({-2, 0.5, 7}), rotate_op({1, 1, 0}, 40), scale_op({0.5, 3, 1})});
    // A sphere of radius 0.5 at (1, 0, 0) under a uniform scale of 2: the world sphere of
    // radius 1 at (2, 0, 0).
    const Transform doubled = transform_of({scale_op({2, 2, 2})});
    const Sphere offset_sphere{{1, 0, 0}, 0.5};
    const Transform ellipsoid = transform_of({translate_op({0, 0, -5}), scale_op({1, 1, 2})});
    const Sphere unit{{0, 0, 0}, 1.0};
    return {
        rotation_case({0, 0, 1}, 0),
        // About (1, 1, 1) by 120 degrees: x -> y -> z -> x.
        rotation_case({1, 1, 1}, 120),
        // About -y: the same as about +y by -90, so x goes to z.
        rotation_case({0, -3, 0}, 90),
        // 450 degrees is a quarter turn and a whole one.
        rotation_case({0, 0, 1}, 450),
        // An axis of length 1e-200 is still an axis: its square underflows, its direction does
        // not.
        rotation_case({0, 0, 1e-200}, 90),
        // And one of length 1.4e200: its square overflows, its direction does not.
        rotation_case({1e200, 0, -1e200}, 60),
        invalid_axis_case({0, 0, 0}, 0),
        exact_matrix_case(probe::scaling_call, {0, -2, 0.5}, wide_scaling({0, -2, 0.5})),
        // The inverse of scale(2, 0, 0.5) does not exist: diagonal (0.5, 1 / 0, 2).
        singular_scale_case({2, 0, 0.5}),
        compose_case({rotate_op({2, -1, 0.5}, 33)}),
        // M = R T: rotated after moving, so the origin goes to R (1, 0, 0) = (0, 1, 0).
        compose_case({rotate_op({0, 0, 1}, 90), translate_op({1, 0, 0})}),
        exact_inverse_case(
            {translate_op({-3e5, 7, 0.25}), scale_op({0.1, 0.5, 4}), translate_op({2, 0, -1})}),
        ray_to_object_case("T R S", turned_and_squashed, {{1, -2, 3}, {0.5, 0.25, -1}, 1e-3, kInf}),
        point_to_world_case("T R S", turned_and_squashed, {-0.5, 4, 2}),
        normal_to_world_case("T R S", turned_and_squashed, {0.3, -0.4, 0.2}),
        // A normal of length 7 under a translation alone: (0, 0, 1), exactly.
        normal_to_world_case("T", transform_of({translate_op({5, 6, 7})}), {0, 0, 7}),
        // A direction of length 2: t is in the world ray's own units, half the distance.
        transformed_sphere_case("radius 0.5 at (1, 0, 0) scaled by 2", {{2, 0, 10}, {0, 0, -2}},
                                offset_sphere, doubled),
        // From inside: the far side, z = -3 from the centre at z = -5 plus 2.
        transformed_sphere_case("radii (1, 1, 2) at (0, 0, -5)", {{0, 0, -5}, {0, 0, 1}}, unit,
                                ellipsoid),
        // t_max short of the ellipsoid, which the ray would enter at t = 3.
        transformed_sphere_case("radii (1, 1, 2) at (0, 0, -5)", {{0, 0, 0}, {0, 0, -1}, 0, 2.5},
                                unit, ellipsoid),
        // Behind the origin: a miss.
        transformed_sphere_case("radii (1, 1, 2) at (0, 0, -5)", {{0, 0, 0}, {0, 0, 1}}, unit,
                                ellipsoid),
        // t_min past the near side (t = 3) but short of the far side (t = 7): the far side.
        transformed_sphere_case("radii (1, 1, 2) at (0, 0, -5)", {{0, 0, 0}, {0, 0, -1}, 4, kInf},
                                unit, ellipsoid),
        // t_min past both sides: a miss.
        transformed_sphere_case("radii (1, 1, 2) at (0, 0, -5)", {{0, 0, 0}, {0, 0, -1}, 7.5, kInf},
                                unit, ellipsoid),
    };
}

// The grader's generated cases are drawn from kOracleSeed, a release's sample from kOracleSeed +
// kSampleSeedOffset.
constexpr std::uint64_t kOracleSeed = 0x5EED'0005;

// A chain of 1 to 6 random ops: offsets up to 1e3, any axis and angle, scale factors from 1e-2
// to 1e2 in magnitude, some negative.
std::vector<TransformOp> random_ops(PortableRandom& random) {
    const std::int64_t count = random.integer(1, 6);
    std::vector<TransformOp> ops;
    for (std::int64_t k = 0; k < count; ++k) {
        switch (random.integer(0, 2)) {
            case 0: {
                const double size = random.decade(-1, 3);
                ops.push_back(translate_op(size * random.point(1)));
                break;
            }
            case 1: {
                const Vec3 axis = random.point(1);
                ops.push_back(rotate_op(axis, random.uniform(-400, 400)));
                break;
            }
            default: {
                Vec3 factors;
                for (int i = 0; i < 3; ++i) {
                    const double size = random.decade(-2, 2);
                    factors[i] = random.unit() < 0.2 ? -size : size;
                }
                ops.push_back(scale_op(factors));
            }
        }
    }
    return ops;
}

PublicCase random_rotation_case(PortableRandom& random) {
    const Vec3 axis = random.unit_vector() * (0.01 + 10 * random.unit());
    return rotation_case(axis, random.uniform(-720, 720));
}

// A ray, a point and a normal under one op chain.
std::vector<PublicCase> random_frame_cases(PortableRandom& random) {
    const std::vector<TransformOp> ops = random_ops(random);
    const Transform t = transform_of(ops);
    const std::string name = ops_text(ops);
    const Vec3 origin = random.point(100);
    const Vec3 direction = random.point(1);
    const double t_min = random.unit();
    const Ray ray{origin, direction, t_min, 10 + 100 * random.unit()};
    const Vec3 point = random.point(10);
    const Vec3 normal = random.unit_vector();
    return {ray_to_object_case(name, t, ray), point_to_world_case(name, t, point),
            normal_to_world_case(name, t, normal)};
}

// A sphere, a point on it and a ray from outside aimed at that point at least 17 degrees off
// grazing (so that the point is where it enters); case k % 5 == 3 from inside, k % 5 == 4
// passing by; every other one with a world direction that is not unit length.
PublicCase random_transformed_sphere_case(PortableRandom& random, int k) {
    const std::vector<TransformOp> ops = random_ops(random);
    const Transform t = transform_of(ops);
    const Vec3 center = random.point(1);
    const Sphere sphere{center, 0.5 + 1.5 * random.unit()};
    const Vec3 normal = random.unit_vector();
    Vec3 leaving = random.unit_vector();
    if (glm::dot(leaving, normal) < 0.3) leaving = glm::normalize(leaving + 2.0 * normal);
    const double distance = 0.5 + 5 * random.unit();
    Vec3 origin = sphere.center + sphere.radius * normal + distance * sphere.radius * leaving;
    const Vec3 towards = -leaving;
    if (k % 5 == 3) origin = sphere.center + 0.8 * sphere.radius * random.unit_vector();
    if (k % 5 == 4) {
        // The line passes 1.2 to 2 radii from the centre.
        const Vec3 side = glm::normalize(glm::cross(leaving, random.unit_vector()));
        const double miss = 1.2 + 0.8 * random.unit();
        origin = sphere.center + miss * sphere.radius * side + 5 * sphere.radius * leaving;
    }
    const Vec3 world_origin = Vec3(t.matrix * Vec4(origin, 1.0));
    Vec3 world_direction = Vec3(t.matrix * Vec4(towards, 0.0));
    const double speed = k % 2 ? 1.0 : 0.1 + 10 * random.unit();
    world_direction *= speed / glm::length(world_direction);
    return transformed_sphere_case(ops_text(ops), {world_origin, world_direction}, sphere, t);
}

// How many of each kind of generated case.
struct GeneratedCounts {
    int rotations = 0;
    int composes = 0;
    int frame_groups = 0;
    int transformed_spheres = 0;
};

// The generated cases, each drawn from PortableRandom(seed, i) with i the index it gets in the
// list, so that `--case i` rebuilds it alone; the cases that share an op chain (a ray, a point and
// a normal under it) from their first one's.
std::vector<PublicCase> generated_cases(std::uint64_t seed, const GeneratedCounts& counts) {
    std::vector<PublicCase> cases;
    for (int k = 0; k < counts.rotations; ++k) {
        PortableRandom random(seed, cases.size());
        cases.push_back(random_rotation_case(random));
    }
    for (int k = 0; k < counts.composes; ++k) {
        PortableRandom random(seed, cases.size());
        cases.push_back(compose_case(random_ops(random)));
    }
    for (int k = 0; k < counts.frame_groups; ++k) {
        PortableRandom random(seed, cases.size());
        for (PublicCase& c : random_frame_cases(random))
            cases.push_back(std::move(c));
    }
    for (int k = 0; k < counts.transformed_spheres; ++k) {
        PortableRandom random(seed, cases.size());
        cases.push_back(random_transformed_sphere_case(random, k));
    }
    return cases;
}

}  // namespace

PublicCheck stage5_public_check() {
    return {"stage5.unit", 5, "unit", kPublicName, public_cases()};
}

PublicCheck stage5_sample_check() {
    return sample_check(5, kOracleName,
                        generated_cases(kOracleSeed + kSampleSeedOffset, {5, 10, 5, 10}));
}

std::vector<CheckDefinition> stage5_checks() {
    return stage_case_checks(
        {5, kPublicName, [] { return data_judged_cases(public_cases()); },
         "transforms on the contract's edge cases",
         [] { return data_judged_cases(hidden_cases()); }, kOracleName,
         [] {
             return data_judged_cases(generated_cases(kOracleSeed, {100, 200, 100, 200}));
         }});
}

}  // namespace raystep::grade
