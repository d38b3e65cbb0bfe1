// The reference acceleration structures against brute force: on every stage-3 family, on a closed
// mesh far from the origin, on the real meshes of Debian's libcgal-demo, and (node_test.h) the two
// builds of the BVH's inner loop against each other. Each must give exactly closest_hit's answer:
// same primitive, same t, compared with ==.

#include <cmath>
#include <cstring>
#include <filesystem>
#include <string>

#include <glm/ext/matrix_transform.hpp>

#include "base/math/portable_random.h"
#include "base/scene/mesh_loader.h"
#include "base/testing/catch.h"
#include "grading/3_intersect/closed_mesh.h"
#include "grading/3_intersect/stage3_families.h"
#include "solutions/4_accel/node_test.h"
#include "stages/4_accel/bvh.h"
#include "stages/4_accel/uniform_grid.h"
#include "studies/structures/bench_geometry.h"
#include "studies/structures/bench_rays.h"

using namespace raystep;

namespace {

// The mesh's faces as triangles.
PrimitiveList mesh_primitives(const ClosedMesh& mesh) {
    PrimitiveList list;
    for (const auto& [a, b, c] : mesh.faces)
        list.triangles.push_back({mesh.vertices[a], mesh.vertices[b], mesh.vertices[c]});
    return list;
}

// The case's spheres and triangles (acceleration structures leave planes out).
PrimitiveList bounded_primitives(const RayCase& ray_case) {
    PrimitiveList list;
    for (const CasePrimitive& primitive : ray_case.primitives) {
        if (const auto* sphere = std::get_if<Sphere>(&primitive.shape))
            list.spheres.push_back(*sphere);
        if (const auto* triangle = std::get_if<Triangle>(&primitive.shape)) {
            list.triangles.push_back(*triangle);
        }
    }
    return list;
}

bool same(const std::optional<PrimitiveHit>& a, const std::optional<PrimitiveHit>& b) {
    if (a.has_value() != b.has_value()) return false;
    return !a || (a->kind == b->kind && a->index == b->index && a->hit.t == b->hit.t);
}

}  // namespace

TEST_CASE("accel: the BVHs and the grid give closest_hit's answer on every stage-3 family",
          "[accel]") {
    for (const Stage3Family& family : stage3_families()) {
        const CaseFamily cases = generate_cases(family, 77, 300);
        for (const RayCase& ray_case : cases.cases) {
            const PrimitiveList list = bounded_primitives(ray_case);
            if (list.spheres.empty() && list.triangles.empty()) continue;
            CAPTURE(family.name, ray_case.index);
            const std::optional<PrimitiveHit> expected = closest_hit(ray_case.ray, list);
            CHECK(same(Bvh(list, BvhSplit::sah).closest_hit(ray_case.ray), expected));
            CHECK(same(Bvh(list, BvhSplit::median).closest_hit(ray_case.ray), expected));
            CHECK(same(UniformGrid(list).closest_hit(ray_case.ray), expected));
        }
    }
}

TEST_CASE("accel: rays through the edges and vertices of a closed mesh 1e5 away", "[accel]") {
    // An icosphere of 1280 triangles, scaled, turned and placed 3e5 from the origin, as one
    // structure; rays from around it through its edges and vertices.
    const ClosedMesh mesh = icosphere(3);
    const glm::dmat4 place =
        glm::rotate(glm::translate(glm::dmat4(1.0), Vec3(3e5, -1e5, 2e5)), 0.7, Vec3(1, 2, 3)) *
        glm::scale(glm::dmat4(1.0), Vec3(2.5));
    std::vector<Vec3> vertices;
    for (const Vec3& v : mesh.vertices)
        vertices.push_back(Vec3(place * glm::dvec4(v, 1.0)));
    PrimitiveList list;
    for (const auto& [a, b, c] : mesh.faces)
        list.triangles.push_back({vertices[a], vertices[b], vertices[c]});
    const Vec3 centre(place * glm::dvec4(0, 0, 0, 1));

    const Bvh sah(list, BvhSplit::sah);
    const Bvh median(list, BvhSplit::median);
    const UniformGrid grid(list);
    int hits = 0;
    for (int k = 0; k < 4000; ++k) {
        PortableRandom random(78, static_cast<std::uint64_t>(k));
        const ClosedMesh::Edge& edge = mesh.edges[static_cast<std::size_t>(k) % mesh.edges.size()];
        const Vec3 target =
            k % 4 == 0 ? vertices[edge.a]
                       : vertices[edge.a] + random.unit() * (vertices[edge.b] - vertices[edge.a]);
        const Vec3 origin = centre + random.point(10.0);
        const Ray ray{origin, target - origin};
        CAPTURE(k);
        const std::optional<PrimitiveHit> expected = closest_hit(ray, list);
        hits += expected.has_value();
        CHECK(same(sah.closest_hit(ray), expected));
        CHECK(same(median.closest_hit(ray), expected));
        CHECK(same(grid.closest_hit(ray), expected));
        CHECK(sah.occluded(ray) == expected.has_value());
        CHECK(grid.occluded(ray) == expected.has_value());
    }
    CHECK(hits > 3000);
}

TEST_CASE("accel: the BVHs and the grid give closest_hit's answer on three real meshes",
          "[accel][meshes]") {
    // Real meshes, where triangles are many, small and of every shape: rays from all around into
    // the mesh's box, and rays aimed at its vertices and through its edges, where two triangles
    // meet and the nearer of equal hits is decided by comes_before.
    for (const char* name : {"bunny00.off", "armadillo.off", "elephant.off"}) {
        const std::filesystem::path path = std::filesystem::path(RAYSTEP_BENCH_MESHES) / name;
        INFO(path.string() << " (Debian's libcgal-demo, which scripts/install-deps.sh installs)");
        REQUIRE(std::filesystem::exists(path));
        const TriangleMesh mesh = load_mesh(path);
        PrimitiveList list;
        list.triangles = mesh_triangles(mesh);
        const Aabb box = bench_bounds(list);
        std::vector<Ray> rays = incoherent_rays(box, 100, 79);
        const double size = glm::length(box.extent());
        for (std::size_t k = 0; k < 200; ++k) {
            PortableRandom random(80, k);
            const auto& face = mesh.faces[k * (mesh.faces.size() / 200)];
            const Vec3 a = mesh.positions[face[0]];
            const Vec3 b = mesh.positions[face[1]];
            const Vec3 target = k % 3 == 0 ? a : a + random.unit() * (b - a);
            const Vec3 origin = box.center() + size * random.point(1.0);
            rays.push_back({origin, target - origin});
        }

        const Bvh sah(list, BvhSplit::sah);
        const Bvh median(list, BvhSplit::median);
        const UniformGrid grid(list);
        int hits = 0;
        for (std::size_t k = 0; k < rays.size(); ++k) {
            CAPTURE(name, k);
            const std::optional<PrimitiveHit> expected = closest_hit(rays[k], list);
            hits += expected.has_value();
            CHECK(same(sah.closest_hit(rays[k]), expected));
            CHECK(same(median.closest_hit(rays[k]), expected));
            CHECK(same(grid.closest_hit(rays[k]), expected));
            CHECK(sah.occluded(rays[k]) == expected.has_value());
            CHECK(grid.occluded(rays[k]) == expected.has_value());
        }
        CHECK(hits > 200);  // every aimed ray hits the mesh, and some of the others
    }
}

#ifdef RAYSTEP_BVH_SSE2
TEST_CASE("accel: the BVH's SSE2 node test computes what the plain one does, bit for bit",
          "[accel]") {
    for (int k = 0; k < 20000; ++k) {
        PortableRandom random(79, static_cast<std::uint64_t>(k));
        const auto coordinate = [&] { return static_cast<float>(random.uniform(-10.0, 10.0)); };
        const auto direction = [&] { return random.uniform(-1.0, 1.0); };
        BvhNode node{};
        for (int c = 0; c < BvhNode::kWidth; ++c) {
            for (int axis = 0; axis < 3; ++axis) {
                const float a = coordinate();
                const float b = coordinate();
                node.planes[2 * axis][c] = std::min(a, b);
                node.planes[2 * axis + 1][c] = std::max(a, b);
            }
        }
        // Unused lanes of a collapsed node hold the empty box.
        constexpr int kUnused = BvhNode::kWidth - 1;
        if (k % 4 == 0) {
            for (int axis = 0; axis < 3; ++axis) {
                node.planes[2 * axis][kUnused] = std::numeric_limits<float>::infinity();
                node.planes[2 * axis + 1][kUnused] = -std::numeric_limits<float>::infinity();
            }
        }
        Vec3 d{direction(), direction(), direction()};
        Vec3 o{coordinate(), coordinate(), coordinate()};
        // Zero components (the stand-in scale), some with the origin exactly on a plane.
        if (k % 3 == 0) d[k % 3] = 0.0;
        if (k % 6 == 0) o[k % 3] = node.planes[k % 2][0];
        const NodeRay ray(Ray{o, d}, 1.0 / d, 10.0, 100.0);
        float entry_scalar[BvhNode::kWidth];
        float entry_sse[BvhNode::kWidth];
        const float limit = k % 5 == 0 ? 3.0f : std::numeric_limits<float>::infinity();
        const int hits_scalar = ChildTestScalar(ray).enter_children(node, limit, entry_scalar);
        const int hits_sse = ChildTestSse(ray).enter_children(node, limit, entry_sse);
        CAPTURE(k);
        REQUIRE(hits_scalar == hits_sse);
        if (k % 4 == 0) CHECK((hits_scalar & (1 << kUnused)) == 0);
        for (int c = 0; c < BvhNode::kWidth; ++c) {
            if (hits_scalar & (1 << c))
                CHECK(std::memcmp(&entry_scalar[c], &entry_sse[c], sizeof(float)) == 0);
        }
    }
}
#endif

TEST_CASE(
    "accel: the node test enters every box a ray passes through, zero direction "
    "components and rays in a box's face included",
    "[accel]") {
    // Eighths, so that the point on the ray and the boxes' planes are exact in float and double:
    // the ray passes through child 0 at t_hit exactly, often through its face or corner. Every
    // other ray is scaled down, in a scene a millionth the size, with a direction 2^-45 long and
    // t up to 10^8: there the drift added for a zero component (node_test.h) is what keeps the
    // box.
    int zero_components = 0;
    for (int k = 0; k < 20000; ++k) {
        PortableRandom random(80, static_cast<std::uint64_t>(k));
        const auto eighth = [&] { return static_cast<double>(random.integer(-40, 40)) / 8.0; };
        const auto size = [&] { return static_cast<double>(random.integer(0, 8)); };
        const bool small = k % 2 == 1;
        const double length = small ? 0x1p-20 : 1.0;
        const double speed = small ? 0x1p-45 : 1.0;
        Vec3 o = length * Vec3{eighth(), eighth(), eighth()};
        Vec3 d = speed * Vec3{eighth() / 4.0, eighth() / 4.0, eighth() / 4.0};
        if (k % 3 == 0) d[k % 3] = 0.0;
        if (k % 7 == 0) d[(k + 1) % 3] = 0.0;
        const double largest = std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)});
        if (largest == 0.0) continue;
        zero_components += (d.x == 0.0) + (d.y == 0.0) + (d.z == 0.0);
        const double t_hit = std::abs(eighth()) * length / speed;
        const Vec3 p = o + t_hit * d;

        BvhNode node{};
        for (int c = 0; c < BvhNode::kWidth; ++c) {
            for (int axis = 0; axis < 3; ++axis) {
                node.planes[2 * axis][c] = std::numeric_limits<float>::infinity();
                node.planes[2 * axis + 1][c] = -std::numeric_limits<float>::infinity();
            }
        }
        // Child 0 holds p, with a side of zero now and then; child 1 lies behind the origin,
        // along the direction's largest component, where the ray never goes.
        for (int axis = 0; axis < 3; ++axis) {
            node.planes[2 * axis][0] = static_cast<float>(p[axis] - length * size() / 8.0);
            node.planes[2 * axis + 1][0] = static_cast<float>(p[axis] + length * size() / 8.0);
            const double behind = o[axis] - d[axis] * (0.5 * length / largest);
            node.planes[2 * axis][1] = static_cast<float>(behind - 0.125 * length);
            node.planes[2 * axis + 1][1] = static_cast<float>(behind + 0.125 * length);
        }
        const NodeRay ray(Ray{o, d}, 1.0 / d, 20.0 * length, 2.0 * t_hit + 1.0);
        REQUIRE(ray.fits_float);
        const float limit =
            k % 2 == 0 ? static_cast<float>(t_hit) : std::numeric_limits<float>::infinity();
        float entry[BvhNode::kWidth];
        const int hits = ChildTest(ray).enter_children(node, limit, entry);
        CAPTURE(k, o.x, o.y, o.z, d.x, d.y, d.z, t_hit);
        REQUIRE((hits & 1) != 0);
        CHECK(entry[0] <= t_hit);
        CHECK((hits & 2) == 0);
        CHECK((hits & ~3) == 0);
    }
    CHECK(zero_components > 5000);
}

TEST_CASE("accel: axis-parallel rays prune the BVH as well as tilted ones", "[accel]") {
    // A zero direction component gets a stand-in scale (node_test.h): it must still reject the
    // boxes the ray passes beside, or an orthographic view would walk the whole tree.
    const PrimitiveList list = mesh_primitives(icosphere(4));
    const Bvh bvh(list, BvhSplit::sah);
    TraversalStats straight;
    TraversalStats tilted;
    for (int k = 0; k < 1000; ++k) {
        PortableRandom random(81, static_cast<std::uint64_t>(k));
        const Vec3 origin{random.uniform(-0.6, 0.6), random.uniform(-0.6, 0.6), -3.0};
        const Ray axis_ray{origin, Vec3(0, 0, 1)};
        const Ray tilted_ray{origin, Vec3(1e-3, -1e-3, 1)};
        const std::optional<PrimitiveHit> hit = bvh.closest_hit(axis_ray, &straight);
        REQUIRE(hit.has_value());
        CHECK(same(hit, closest_hit(axis_ray, list)));
        REQUIRE(bvh.closest_hit(tilted_ray, &tilted).has_value());
    }
    CAPTURE(straight.nodes, tilted.nodes, bvh.node_count());
    CHECK(straight.nodes < tilted.nodes * 11 / 10);
}

TEST_CASE("accel: a ray too long for the float node test is answered by testing every primitive",
          "[accel]") {
    // A direction 1e-20 long: the ray's t runs to 1e20, beyond what node_test.h computes in
    // float, so the BVH tests every primitive, and still gives closest_hit's answer.
    const PrimitiveList list = mesh_primitives(icosphere(2));
    const Bvh bvh(list, BvhSplit::sah);
    const Ray ray{Vec3(0.1, 0.2, -3.0), Vec3(1e-21, 2e-21, 1e-20)};
    TraversalStats stats;
    const std::optional<PrimitiveHit> hit = bvh.closest_hit(ray, &stats);
    REQUIRE(hit.has_value());
    CHECK(same(hit, closest_hit(ray, list)));
    CHECK(stats.nodes == 0);
    CHECK(stats.primitive_tests == list.triangles.size());
    CHECK(bvh.occluded(ray));
}
