// Public tests for stage 5. Run them with `ctest --preset student -L stage5`, or run
// build/student/bin/raystep_stage5_tests directly to see every failure in full; one function's
// tests with `build/student/bin/raystep_stage5_tests "normal_to_world:*"`. A loop over cases stops
// at the first that fails, and a function built from others names them: fix theirs first.

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "base/math/portable_random.h"
#include "base/testing/catch.h"
#include "base/testing/number_matchers.h"
#include "base/testing/number_text.h"
#include "base/testing/uses.h"
#include "base/testing/vec3_matchers.h"
#include "stages/3_intersect/tests/hit_text.h"
#include "stages/5_transforms/transform.h"

using namespace raystep;
using raystep::testing::exact_text;
using raystep::testing::IsNear;
using raystep::testing::text;
using raystep::testing::uses;

namespace {

constexpr double kTight = 1e-14;

Vec3 apply_to_point(const Mat4& m, const Vec3& p) {
    return Vec3(m * Vec4(p, 1.0));
}

Vec3 apply_to_direction(const Mat4& m, const Vec3& d) {
    return Vec3(m * Vec4(d, 0.0));
}

// The transform of `translate offset` then `scale factors`, built here with glm rather than by
// compose, so that the object-frame tests need only the function they test.
Transform moved_and_scaled(const Vec3& offset, const Vec3& factors) {
    return {glm::scale(glm::translate(Mat4(1.0), offset), factors),
            glm::translate(glm::scale(Mat4(1.0), 1.0 / factors), -offset)};
}

TransformOp translate_op(const Vec3& offset) {
    return {TransformOp::Kind::translate, offset, 0.0};
}

TransformOp rotate_op(const Vec3& axis, double degrees) {
    return {TransformOp::Kind::rotate, axis, degrees};
}

TransformOp scale_op(const Vec3& factors) {
    return {TransformOp::Kind::scale, factors, 0.0};
}

}  // namespace

TEST_CASE("translation: moves points and leaves directions alone", "[stage5]") {
    const Mat4 m = translation({1, -2, 3});
    CHECK_THAT(apply_to_point(m, {10, 20, 30}), IsNear(Vec3(11, 18, 33), 0.0));
    CHECK_THAT(apply_to_direction(m, {10, 20, 30}), IsNear(Vec3(10, 20, 30), 0.0));
}

TEST_CASE("scaling: multiplies each coordinate by its factor", "[stage5]") {
    const Mat4 m = scaling({2, 3, -4});
    CHECK_THAT(apply_to_point(m, {1, 1, 1}), IsNear(Vec3(2, 3, -4), 0.0));
    CHECK(m[3] == Vec4(0, 0, 0, 1));
}

TEST_CASE("rotation: a quarter turn about z takes x to y (right-hand rule)", "[stage5]") {
    INFO(uses("rotation", "stage 1's normalize"));
    const Mat4 m = rotation({0, 0, 1}, 90.0);
    CHECK_THAT(apply_to_point(m, {1, 0, 0}), IsNear(Vec3(0, 1, 0), kTight));
    CHECK_THAT(apply_to_point(m, {0, 1, 0}), IsNear(Vec3(-1, 0, 0), kTight));
    CHECK_THAT(apply_to_point(m, {0, 0, 1}), IsNear(Vec3(0, 0, 1), kTight));
}

TEST_CASE("rotation: about x and y, the right-hand rule too", "[stage5]") {
    INFO(uses("rotation", "stage 1's normalize"));
    REQUIRE_THAT(apply_to_point(rotation({1, 0, 0}, 90.0), {0, 1, 0}),
                 IsNear(Vec3(0, 0, 1), kTight));
    REQUIRE_THAT(apply_to_point(rotation({0, 1, 0}, 90.0), {0, 0, 1}),
                 IsNear(Vec3(1, 0, 0), kTight));
}

TEST_CASE("rotation: the axis need not be unit length", "[stage5]") {
    INFO(uses("rotation", "stage 1's normalize"));
    const Mat4 unit = rotation({0, 0, 1}, 30.0);
    const Mat4 long_axis = rotation({0, 0, 7}, 30.0);
    CHECK_THAT(apply_to_point(long_axis, {1, 2, 3}),
               IsNear(apply_to_point(unit, {1, 2, 3}), kTight));
}

TEST_CASE("rotation: agrees with glm::rotate about random axes", "[stage5]") {
    INFO(uses("rotation", "stage 1's normalize"));
    for (int k = 0; k < 200; ++k) {
        PortableRandom random(5, k);  // case k, the same on every platform
        const Vec3 axis = random.point(1.0);
        const double degrees = random.uniform(-360.0, 360.0);
        const Vec3 p = random.point(1.0);
        CAPTURE(k, axis.x, axis.y, axis.z, degrees);
        const Mat4 ours = rotation(axis, degrees);
        const Mat4 theirs = glm::rotate(Mat4(1.0), glm::radians(degrees), axis);
        REQUIRE_THAT(apply_to_point(ours, p), IsNear(apply_to_point(theirs, p), 1e-13));
    }
}

TEST_CASE("rotation: keeps lengths and the axis itself", "[stage5]") {
    INFO(uses("rotation", "stage 1's normalize"));
    const Vec3 axis{1, 2, 2};
    const Mat4 m = rotation(axis, 123.0);
    CHECK_THAT(apply_to_point(m, axis), IsNear(axis, 1e-14));
    const Vec3 p{3, -1, 4};
    CHECK(glm::length(apply_to_point(m, p)) == Approx(glm::length(p)).epsilon(kTight));
}

TEST_CASE("rotation: a zero axis is an error", "[stage5]") {
    INFO(uses("rotation", "stage 1's normalize"));
    CHECK_THROWS_AS(rotation({0, 0, 0}, 45.0), std::invalid_argument);
}

TEST_CASE("compose: no ops is the identity", "[stage5]") {
    INFO(uses("compose", "translation, rotation and scaling"));
    const Transform t = compose({});
    CHECK(t.matrix == Mat4(1.0));
    CHECK(t.inverse == Mat4(1.0));
}

TEST_CASE("compose: right-multiplies, so the last op written acts first", "[stage5]") {
    INFO(uses("compose", "translation, rotation and scaling"));
    INFO("translate 1 0 0, then scale 2 2 2: M = T S, the point is scaled, then moved.");
    const Transform translate_then_scale = compose({translate_op({1, 0, 0}), scale_op({2, 2, 2})});
    CHECK_THAT(apply_to_point(translate_then_scale.matrix, {1, 1, 1}), IsNear(Vec3(3, 2, 2), 0.0));
    // The other order, M = S T: moved, then scaled.
    const Transform scale_then_translate = compose({scale_op({2, 2, 2}), translate_op({1, 0, 0})});
    CHECK_THAT(apply_to_point(scale_then_translate.matrix, {1, 1, 1}), IsNear(Vec3(4, 2, 2), 0.0));
}

TEST_CASE("compose: translate then rotate turns the object in place, then moves it", "[stage5]") {
    INFO(uses("compose", "translation, rotation and scaling"));
    INFO(
        "The classic scene idiom: `translate 5 0 0` then `rotate 0 0 1 90` spins the object about "
        "its own centre and puts it at x = 5, not on a circle about the world's origin.");
    const Transform t = compose({translate_op({5, 0, 0}), rotate_op({0, 0, 1}, 90.0)});
    CHECK_THAT(apply_to_point(t.matrix, {1, 0, 0}), IsNear(Vec3(5, 1, 0), kTight));
}

TEST_CASE("compose: the inverse undoes the matrix", "[stage5]") {
    INFO(uses("compose", "translation, rotation and scaling"));
    for (int k = 0; k < 200; ++k) {
        PortableRandom random(55, k);  // case k, the same on every platform
        std::vector<TransformOp> ops;
        for (int n = 0; n < 5; ++n) {
            switch ((k + n) % 3) {
                case 0:
                    ops.push_back(translate_op(random.point(1.0)));
                    break;
                case 1: {
                    const Vec3 axis = random.point(1.0);
                    ops.push_back(rotate_op(axis, random.uniform(-180.0, 180.0)));
                    break;
                }
                default: {
                    const double x = random.uniform(0.25, 4.0);
                    const double y = random.uniform(0.25, 4.0);
                    ops.push_back(scale_op({x, y, random.uniform(0.25, 4.0)}));
                }
            }
        }
        const Transform t = compose(ops);
        const Vec3 p = random.point(1.0);
        CAPTURE(k);
        REQUIRE_THAT(apply_to_point(t.inverse, apply_to_point(t.matrix, p)), IsNear(p, 1e-12));
        REQUIRE_THAT(apply_to_point(t.matrix, apply_to_point(t.inverse, p)), IsNear(p, 1e-12));
    }
}

TEST_CASE("compose: the inverse comes from the ops, exact where they are", "[stage5]") {
    INFO(uses("compose", "translation, rotation and scaling"));
    INFO(
        "Scale by 1e-3 and translate by 1e4: inverting the product would divide by a determinant "
        "of 1e-9; the ops' own inverses (scale by 1000, translate by -1e4) need no division at "
        "all.");
    const Transform t = compose({translate_op({1e4, 0, 0}), scale_op({1e-3, 1e-3, 1e-3})});
    // scale(1 / 1e-3) * translate(-1e4, 0, 0), written out: the translation column is scaled too.
    const double s = 1.0 / 1e-3;
    Mat4 expected(1.0);
    expected[0][0] = expected[1][1] = expected[2][2] = s;
    expected[3][0] = s * -1e4;
    CHECK(t.inverse == expected);
}

TEST_CASE("compose: a zero scale factor has no inverse, and its 1 / 0 stays infinite", "[stage5]") {
    INFO(uses("compose", "translation, rotation and scaling"));
    INFO(
        "scale(2, 0, 0.5) flattens y: its inverse would scale y by 1 / 0. A finite stand-in such "
        "as 1 would make M^-1 look like an inverse when there is none.");
    const Transform t = compose({scale_op({2, 0, 0.5})});
    CHECK(t.matrix ==
          Mat4(Vec4(2, 0, 0, 0), Vec4(0, 0, 0, 0), Vec4(0, 0, 0.5, 0), Vec4(0, 0, 0, 1)));
    CHECK(t.inverse[0][0] == 0.5);
    CHECK_FALSE(std::isfinite(t.inverse[1][1]));
    CHECK(t.inverse[2][2] == 2.0);
}

TEST_CASE("ray_to_object: the direction is not renormalized, so t is the same in both frames",
          "[stage5]") {
    const Transform t = moved_and_scaled({1, 2, 3}, {2, 2, 2});
    const Ray world{{0, 0, 10}, {0, 0, -1}, 0.5, 20.0};
    const Ray object = ray_to_object(t, world);
    // Scaling by 2 makes object distances half: the object direction has length 1/2.
    CHECK(glm::length(object.direction) == Approx(0.5).epsilon(kTight));
    CHECK(object.t_min == 0.5);
    CHECK(object.t_max == 20.0);
    for (const double s : {0.0, 1.0, 7.25}) {
        CAPTURE(s);
        REQUIRE_THAT(apply_to_point(t.matrix, object.at(s)), IsNear(world.at(s), 1e-13));
    }
}

TEST_CASE("ray_to_object: a translation moves the origin and not the direction", "[stage5]") {
    const Transform t = moved_and_scaled({1, 2, 3}, Vec3(1.0));
    const Ray object = ray_to_object(t, Ray{{1, 1, 1}, {0, 1, 0}});
    CHECK_THAT(object.origin, IsNear(Vec3(0, -1, -2), 0.0));
    CHECK_THAT(object.direction, IsNear(Vec3(0, 1, 0), 0.0));
}

TEST_CASE("point_to_world: applies the whole matrix, translation included", "[stage5]") {
    const Transform t = moved_and_scaled({1, 0, 0}, {2, 3, 4});
    CHECK_THAT(point_to_world(t, {1, 1, 1}), IsNear(Vec3(3, 3, 4), 0.0));
}

TEST_CASE("normal_to_world: under a non-uniform scale M^-T n stays perpendicular, M n does not",
          "[stage5]") {
    INFO(uses("normal_to_world", "stage 1's normalize"));
    INFO(
        "The plane x + y = 0 has normal n = (1, 1, 0) and contains the tangent (1, -1, 0). Squash "
        "y by 4: the tangent becomes M t = (1, -4, 0).");
    const Transform t = moved_and_scaled(Vec3(0.0), {1, 4, 1});
    const Vec3 n{1, 1, 0};
    const Vec3 tangent = apply_to_direction(t.matrix, {1, -1, 0});
    // The tempting answer, M n = (1, 4, 0), is visibly off: (1, 4, 0) . (1, -4, 0) = -15.
    CHECK(glm::dot(apply_to_direction(t.matrix, n), tangent) == -15.0);
    // M^-T n = (1, 1/4, 0), normalized: perpendicular to the squashed surface.
    const Vec3 world = normal_to_world(t, n);
    CHECK_THAT(glm::dot(world, tangent), IsNear(0.0, kTight));
    CHECK_THAT(world, IsNear(glm::normalize(Vec3(1, 0.25, 0)), kTight));
}

TEST_CASE("normal_to_world: unit length, and a translation leaves normals alone", "[stage5]") {
    INFO(uses("normal_to_world", "stage 1's normalize"));
    const Transform moved = moved_and_scaled({5, 6, 7}, Vec3(1.0));
    const Transform scaled = moved_and_scaled(Vec3(0.0), {3, 3, 3});
    const Vec3 after_translation = normal_to_world(moved, {0, 0, 1});
    const Vec3 after_scale = normal_to_world(scaled, {0, 2, 0});
    INFO("normal_to_world(translate (5, 6, 7), (0, 0, 1)) is (0, 0, 1)");
    CHECK_THAT(after_translation, IsNear(Vec3(0, 0, 1), 0.0));
    INFO("normal_to_world(scale (3, 3, 3), (0, 2, 0)) has length 1");
    CHECK(glm::length(after_scale) == Approx(1.0).epsilon(kTight));
}

TEST_CASE("intersect_transformed_sphere: t along a unit world ray is the world distance",
          "[stage5]") {
    INFO(uses("intersect_transformed_sphere", "ray_to_object, normal_to_world, intersect_sphere"));
    INFO("A unit sphere squashed to half its height in z: its top is at z = 0.5.");
    const Transform t = moved_and_scaled(Vec3(0.0), {2, 1, 0.5});
    const Sphere unit{{0, 0, 0}, 1.0};
    const std::optional<Hit> hit =
        intersect_transformed_sphere(Ray{{0, 0, 10}, {0, 0, -1}}, unit, t);
    REQUIRE(hit);
    CHECK(hit->t == Approx(9.5).epsilon(kTight));
    CHECK_THAT(hit->normal, IsNear(Vec3(0, 0, 1), kTight));
}

TEST_CASE("intersect_transformed_sphere: the normal is the ellipsoid's analytic normal",
          "[stage5]") {
    INFO(uses("intersect_transformed_sphere", "ray_to_object, normal_to_world, intersect_sphere"));
    INFO(
        "The unit sphere scaled by (a, b, c) is the ellipsoid x^2/a^2 + y^2/b^2 + z^2/c^2 = 1, "
        "moved by `centre`. Its normal at p is the gradient (x/a^2, y/b^2, z/c^2), normalized.");
    const Vec3 radii{3, 1, 0.5};
    const Vec3 centre{1, -2, 0.5};
    const Transform t = moved_and_scaled(centre, radii);
    const Sphere unit{{0, 0, 0}, 1.0};
    int hits = 0;
    for (int k = 0; k < 500; ++k) {
        PortableRandom random(17, k);  // case k, the same on every platform
        const Vec3 origin = centre + 10.0 * random.unit_vector();
        const Vec3 target = centre + 0.5 * radii * random.point(1.0);
        const Ray ray{origin, glm::normalize(target - origin)};
        CAPTURE(k);
        INFO(text(ray) + "\nellipsoid: centre " + exact_text(centre) + ", radii " +
             exact_text(radii));
        const std::optional<Hit> hit = intersect_transformed_sphere(ray, unit, t);
        REQUIRE(hit);  // every ray aims inside the ellipsoid
        ++hits;
        const Vec3 q = (ray.at(hit->t) - centre) / radii;
        REQUIRE(glm::dot(q, q) == Approx(1.0).epsilon(1e-12));
        const Vec3 gradient = (ray.at(hit->t) - centre) / (radii * radii);
        REQUIRE_THAT(hit->normal, IsNear(glm::normalize(gradient), 1e-12));
    }
    CHECK(hits == 500);
}

TEST_CASE("intersect_transformed_sphere: hits only within [t_min, t_max] of the world ray",
          "[stage5]") {
    INFO(uses("intersect_transformed_sphere", "ray_to_object, normal_to_world, intersect_sphere"));
    INFO(
        "The unit sphere stretched to height 2 in z and moved to z = -5: down the z axis from the "
        "origin, the ray enters at t = 3 and leaves at t = 7. t counts along the world ray in both "
        "frames (ray_to_object keeps t_min and t_max), so the range is the world ray's.");
    const Transform t = moved_and_scaled({0, 0, -5}, {1, 1, 2});
    const Sphere unit{{0, 0, 0}, 1.0};
    const std::optional<Hit> near =
        intersect_transformed_sphere(Ray{{0, 0, 0}, {0, 0, -1}}, unit, t);
    REQUIRE(near);
    REQUIRE(near->t == Approx(3.0).epsilon(kTight));
    // From t = 4 on, the near side is behind: the far side, whose outward normal is -z.
    const std::optional<Hit> far =
        intersect_transformed_sphere(Ray{{0, 0, 0}, {0, 0, -1}, 4.0, 100.0}, unit, t);
    REQUIRE(far);
    REQUIRE(far->t == Approx(7.0).epsilon(kTight));
    REQUIRE_THAT(far->normal, IsNear(Vec3(0, 0, -1), kTight));
    // Past both sides, and short of the first: misses.
    REQUIRE_FALSE(intersect_transformed_sphere(Ray{{0, 0, 0}, {0, 0, -1}, 7.5, 100.0}, unit, t));
    REQUIRE_FALSE(intersect_transformed_sphere(Ray{{0, 0, 0}, {0, 0, -1}, 0.0, 2.5}, unit, t));
}

TEST_CASE("intersect_transformed_sphere: a ray past the ellipsoid misses", "[stage5]") {
    INFO(uses("intersect_transformed_sphere", "ray_to_object, normal_to_world, intersect_sphere"));
    const Transform t = moved_and_scaled(Vec3(0.0), {2, 1, 0.5});
    const Sphere unit{{0, 0, 0}, 1.0};
    // The line x = 1, z = 0.6 along y: (1/2)^2 + (0.6/0.5)^2 = 1.69 > 1, outside at every y.
    CHECK_FALSE(intersect_transformed_sphere(Ray{{1.0, -10, 0.6}, {0, 1, 0}}, unit, t));
}
