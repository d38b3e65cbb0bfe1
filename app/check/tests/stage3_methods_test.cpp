#include "app/check/stage3_methods.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "base/errors/not_implemented.h"
#include "base/testing/catch.h"
#include "base/testing/vec3_matchers.h"

using namespace raystep;
using raystep::testing::IsNear;

namespace {

using Kind = Stage3Method::Kind;

// Rounding in the reference tests stays within a few ulps of these short exact numbers.
constexpr double kTolerance = 1e-12;

// Straight down through (0.25, 0.5): a plane at t = 15, a triangle it misses, a sphere at t = 7
// and a triangle at t = 5 with barycentrics (0.25, 0.5). Computed by hand.
RayCase mixed_case() {
    RayCase ray_case;
    ray_case.ray = {{0.25, 0.5, 5.0}, {0.0, 0.0, -1.0}};
    ray_case.primitives = {
        {Plane{{0.0, 0.0, -10.0}, {0.0, 0.0, 2.0}}, {}},
        {Triangle{{1.0, 0.0, 0.0}, {1.0, 1.0, 0.0}, {0.0, 1.0, 0.0}}, {}},
        {Sphere{{0.25, 0.5, -3.0}, 1.0}, {}},
        {Triangle{{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}}, {}},
    };
    return ray_case;
}

const Stage3Method& method_named(const std::vector<Stage3Method>& methods,
                                 const std::string& name) {
    for (const Stage3Method& method : methods) {
        if (method.name == name) return method;
    }
    throw std::invalid_argument("no method " + name);
}

std::optional<Hit> throws_domain_error(const Ray&, const Triangle&) {
    throw std::domain_error("the triangle is too thin");
}

std::optional<Hit> is_a_stub(const Ray&, const Triangle&) {
    throw_not_implemented(3, "intersect_triangle_cramer", "Method 3: Cramer's rule");
}

std::optional<Hit> throws_empty_message(const Ray&, const Triangle&) {
    throw std::runtime_error("");
}

std::optional<Hit> throws_an_int(const Ray&, const Triangle&) {
    throw 42;
}

}  // namespace

TEST_CASE("stage3_methods: every function of intersect.h, in order, by kind", "[app]") {
    const std::vector<Stage3Method> methods = stage3_methods();
    std::vector<std::string> names;
    for (const Stage3Method& method : methods)
        names.push_back(method.name);
    CHECK(names == std::vector<std::string>{"intersect_plane", "intersect_triangle_projection",
                                            "intersect_triangle_halfspaces",
                                            "intersect_triangle_cramer", "intersect_triangle",
                                            "intersect_sphere", "closest_hit"});
    for (const Stage3Method& method : methods) {
        CAPTURE(method.name);
        CHECK((method.sphere != nullptr) == (method.kind == Kind::sphere));
        CHECK((method.triangle != nullptr) == (method.kind == Kind::triangle));
        CHECK((method.plane != nullptr) == (method.kind == Kind::plane));
    }
    CHECK(methods[0].plane == &intersect_plane);
    CHECK(methods[3].triangle == &intersect_triangle_cramer);
    CHECK(methods[5].sphere == &intersect_sphere);
    CHECK(methods[6].kind == Kind::closest);
}

TEST_CASE("applies_to: a test applies to its own kind, closest_hit to every kind", "[app]") {
    const std::vector<Stage3Method> methods = stage3_methods();
    const CaseShape sphere = Sphere{{0, 0, 0}, 1};
    const CaseShape triangle = Triangle{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    const CaseShape plane = Plane{{0, 0, 0}, {0, 0, 1}};
    const Stage3Method& sphere_test = method_named(methods, "intersect_sphere");
    CHECK(applies_to(sphere_test, sphere));
    CHECK_FALSE(applies_to(sphere_test, triangle));
    CHECK_FALSE(applies_to(sphere_test, plane));
    const Stage3Method& triangle_test = method_named(methods, "intersect_triangle_halfspaces");
    CHECK(applies_to(triangle_test, triangle));
    CHECK_FALSE(applies_to(triangle_test, plane));
    const Stage3Method& plane_test = method_named(methods, "intersect_plane");
    CHECK(applies_to(plane_test, plane));
    CHECK_FALSE(applies_to(plane_test, sphere));
    const Stage3Method& closest = method_named(methods, "closest_hit");
    CHECK(applies_to(closest, sphere));
    CHECK(applies_to(closest, triangle));
    CHECK(applies_to(closest, plane));
}

TEST_CASE("run_method: each test answers for its own kind of primitive only", "[app]") {
    const RayCase ray_case = mixed_case();
    for (const Stage3Method& method : stage3_methods()) {
        if (method.kind == Kind::closest) continue;
        CAPTURE(method.name);
        const CaseAnswer answer = run_method(method, ray_case);
        CHECK(answer.error.empty());
        CHECK_FALSE(answer.not_implemented);
        CHECK_FALSE(answer.closest_hit);
        REQUIRE(answer.hits.size() == 4);
        CHECK(answer.hits[0].has_value() == (method.kind == Kind::plane));
        CHECK_FALSE(answer.hits[1].has_value());  // the triangle the ray passes beside
        CHECK(answer.hits[2].has_value() == (method.kind == Kind::sphere));
        CHECK(answer.hits[3].has_value() == (method.kind == Kind::triangle));
    }

    const std::vector<Stage3Method> methods = stage3_methods();
    const CaseAnswer plane = run_method(method_named(methods, "intersect_plane"), ray_case);
    REQUIRE(plane.hits[0]);
    CHECK(std::abs(plane.hits[0]->t - 15.0) <= kTolerance);
    CHECK_THAT(plane.hits[0]->normal, IsNear({0, 0, 1}, kTolerance));

    const CaseAnswer sphere = run_method(method_named(methods, "intersect_sphere"), ray_case);
    REQUIRE(sphere.hits[2]);
    CHECK(std::abs(sphere.hits[2]->t - 7.0) <= kTolerance);

    const CaseAnswer triangle =
        run_method(method_named(methods, "intersect_triangle_projection"), ray_case);
    REQUIRE(triangle.hits[3]);
    CHECK(std::abs(triangle.hits[3]->t - 5.0) <= kTolerance);
    CHECK(std::abs(triangle.hits[3]->beta - 0.25) <= kTolerance);
    CHECK(std::abs(triangle.hits[3]->gamma - 0.5) <= kTolerance);
}

TEST_CASE("run_method: closest_hit's choice is numbered as in the case", "[app]") {
    const std::vector<Stage3Method> methods = stage3_methods();
    const Stage3Method& closest = method_named(methods, "closest_hit");
    // The nearest hit is the second triangle of closest_hit's list, and primitive 3 of the case.
    const CaseAnswer answer = run_method(closest, mixed_case());
    CHECK(answer.error.empty());
    REQUIRE(answer.closest_primitive);
    CHECK(*answer.closest_primitive == 3);
    REQUIRE(answer.closest_hit);
    CHECK(std::abs(answer.closest_hit->t - 5.0) <= kTolerance);
    CHECK(std::abs(answer.closest_hit->beta - 0.25) <= kTolerance);
    for (const std::optional<Hit>& hit : answer.hits)
        CHECK_FALSE(hit);

    // Without the triangles, the sphere (primitive 1 now) is nearest.
    RayCase no_triangles = mixed_case();
    no_triangles.primitives = {no_triangles.primitives[0], no_triangles.primitives[2]};
    const CaseAnswer sphere = run_method(closest, no_triangles);
    REQUIRE(sphere.closest_primitive);
    CHECK(*sphere.closest_primitive == 1);
    REQUIRE(sphere.closest_hit);
    CHECK(std::abs(sphere.closest_hit->t - 7.0) <= kTolerance);

    // Past every primitive: a miss.
    RayCase away = mixed_case();
    away.ray.direction = {0.0, 0.0, 1.0};
    const CaseAnswer miss = run_method(closest, away);
    CHECK_FALSE(miss.closest_primitive);
    CHECK_FALSE(miss.closest_hit);
}

TEST_CASE("run_method: what a method throws becomes its answer", "[app]") {
    const RayCase ray_case = mixed_case();

    const CaseAnswer domain_error =
        run_method({"throws_domain_error", Kind::triangle, nullptr, throws_domain_error}, ray_case);
    CHECK_FALSE(domain_error.not_implemented);
    CHECK(domain_error.error == "the triangle is too thin");

    const CaseAnswer stub = run_method({"is_a_stub", Kind::triangle, nullptr, is_a_stub}, ray_case);
    CHECK(stub.not_implemented);
    CHECK(stub.error ==
          "stage 3: intersect_triangle_cramer is not implemented yet, see "
          "docs/stage3.md, section \"Method 3: Cramer's rule\"");

    // An empty error would read as a normal return.
    const CaseAnswer empty = run_method(
        {"throws_empty_message", Kind::triangle, nullptr, throws_empty_message}, ray_case);
    CHECK(empty.error == "an exception with an empty message");

    const CaseAnswer not_std =
        run_method({"throws_an_int", Kind::triangle, nullptr, throws_an_int}, ray_case);
    CHECK_FALSE(not_std.not_implemented);
    CHECK(not_std.error == "an exception that is not a std::exception");

    // A case without triangles never calls the triangle test, so nothing is thrown.
    RayCase spheres_only;
    spheres_only.ray = ray_case.ray;
    spheres_only.primitives = {ray_case.primitives[2]};
    const CaseAnswer not_called =
        run_method({"throws_an_int", Kind::triangle, nullptr, throws_an_int}, spheres_only);
    CHECK(not_called.error.empty());
    CHECK_FALSE(not_called.hits[0]);
}
