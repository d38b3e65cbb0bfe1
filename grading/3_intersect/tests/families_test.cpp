#include <set>
#include <tuple>

#include <glm/geometric.hpp>

#include "base/testing/catch.h"
#include "grading/3_intersect/closed_mesh.h"
#include "grading/3_intersect/decide_cases.h"
#include "grading/3_intersect/stage3_families.h"

using namespace raystep;

TEST_CASE("icosphere: closed, every edge shared by two faces, vertices on the unit sphere",
          "[families]") {
    const ClosedMesh mesh = icosphere(2);
    CHECK(mesh.faces.size() == 320);
    CHECK(mesh.vertices.size() == 162);
    CHECK(mesh.edges.size() == 480);  // Euler: V - E + F = 2
    for (const ClosedMesh::Edge& edge : mesh.edges) {
        CAPTURE(edge.a, edge.b);
        CHECK(edge.faces[0] != edge.faces[1]);
    }
    for (const Vec3& v : mesh.vertices)
        CHECK(glm::length(v) == Approx(1.0));
    for (const auto& fan : mesh.vertex_faces)
        CHECK((fan.size() == 5 || fan.size() == 6));
}

TEST_CASE("generate_cases: a case depends only on the seed and its index", "[families]") {
    for (const Stage3Family& family : stage3_families()) {
        CAPTURE(family.name);
        const CaseFamily first = generate_cases(family, 7, 20);
        const CaseFamily again = generate_cases(family, 7, 25);
        const CaseFamily other = generate_cases(family, 8, 20);
        REQUIRE(first.cases.size() == 20);
        CHECK(first.name == family.name);
        for (std::size_t k = 0; k < 20; ++k) {
            CAPTURE(k);
            CHECK(first.cases[k].index == k);
            CHECK(first.cases[k].ray.origin == again.cases[k].ray.origin);
            CHECK(first.cases[k].ray.direction == again.cases[k].ray.direction);
        }
        CHECK(first.cases[0].ray.origin != other.cases[0].ray.origin);
    }
}

TEST_CASE("shared-edge and shared-vertex cases share their vertices bit for bit", "[families]") {
    for (const char* name :
         {"shared-edges", "shared-edges-far", "shared-vertices", "shared-vertices-far"}) {
        CAPTURE(name);
        const CaseFamily family = generate_cases(*find_stage3_family(name), 3, 50);
        for (const RayCase& ray_case : family.cases) {
            CAPTURE(ray_case.index);
            // Every triangle shares at least two of its vertices with the others of the group.
            std::set<std::tuple<double, double, double>> corners;
            std::size_t total = 0;
            for (const CasePrimitive& primitive : ray_case.primitives) {
                const Triangle& t = std::get<Triangle>(primitive.shape);
                for (const Vec3& p : {t.p0, t.p1, t.p2}) {
                    corners.insert({p.x, p.y, p.z});
                    ++total;
                }
            }
            CHECK(corners.size() < total);
        }
    }
}

TEST_CASE("a shared group is watertight exactly when all its triangles face the ray one way",
          "[families]") {
    for (const char* name : {"shared-edges", "shared-vertices-far"}) {
        CAPTURE(name);
        const CaseFamily family = generate_cases(*find_stage3_family(name), 4, 400);
        std::size_t watertight = 0;
        for (const RayCase& ray_case : family.cases) {
            CAPTURE(ray_case.index);
            int front = 0;
            int back = 0;
            for (const CasePrimitive& primitive : ray_case.primitives) {
                const Triangle& t = std::get<Triangle>(primitive.shape);
                const double facing =
                    glm::dot(ray_case.ray.direction, glm::cross(t.p1 - t.p0, t.p2 - t.p0));
                (facing < 0.0 ? front : back)++;
            }
            const bool one_way = front == 0 || back == 0;
            CHECK(ray_case.watertight == one_way);
            watertight += ray_case.watertight;
        }
        CHECK(watertight > 300);  // off the silhouette, most of them
    }
}

TEST_CASE("the far families really are 1e5 to 1e6 from the origin", "[families]") {
    const CaseFamily family = generate_cases(*find_stage3_family("shared-edges-far"), 5, 30);
    for (const RayCase& ray_case : family.cases) {
        const double distance = glm::length(std::get<Triangle>(ray_case.primitives[0].shape).p0);
        CHECK(distance > 9e4);
        CHECK(distance < 1.1e6);
    }
}

TEST_CASE("in-plane rays are in the triangle's plane exactly, and the oracle says miss",
          "[families]") {
    CaseFamily family = generate_cases(*find_stage3_family("in-plane"), 11, 100);
    decide_cases(family);
    for (const RayCase& ray_case : family.cases) {
        CAPTURE(ray_case.index);
        CHECK_FALSE(ray_case.primitives[0].expected.hit);
    }
}

TEST_CASE("the stable-roots family asks for t within 16 ulps", "[families]") {
    CaseFamily family = generate_cases(*find_stage3_family("stable-roots"), 2, 50);
    decide_cases(family, find_stage3_family("stable-roots")->t_ulps);
    for (const RayCase& ray_case : family.cases) {
        const Expectation& e = ray_case.primitives[0].expected;
        CAPTURE(ray_case.index);
        REQUIRE(e.hit);
        CHECK(e.t > 0.0);
        CHECK(e.t_tolerance <= 16 * (std::nextafter(e.t, 1e300) - e.t) * 2);
    }
}
