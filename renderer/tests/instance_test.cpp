// Instances: objects under a transform intersected in their own frame, under a BVH of their world
// boxes. Whatever the structure, the renderer's hit must be brute force's: every object tested in
// turn in its own frame, the nearest kept by comes_before.

#include <algorithm>
#include <fstream>
#include <string>

#include <glm/geometric.hpp>

#include "base/math/portable_random.h"
#include "base/math/to_text.h"
#include "base/scene/scene_loader.h"
#include "base/testing/catch.h"
#include "base/testing/scratch_folder.h"
#include "renderer/render_scene.h"
#include "renderer/tile_renderer.h"

using namespace raystep;

namespace {

// A bumpy grid of 2 n^2 triangles over [-1, 1]^2 at z = bumps, as an OFF file.
void write_grid_mesh(const std::filesystem::path& path, int n) {
    std::ofstream out(path);
    out << "OFF\n" << (n + 1) * (n + 1) << " " << 2 * n * n << " 0\n";
    for (int j = 0; j <= n; ++j) {
        for (int i = 0; i <= n; ++i) {
            out << -1.0 + 2.0 * i / n << " " << -1.0 + 2.0 * j / n << " " << 0.1 * ((i * j) % 3)
                << "\n";
        }
    }
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            const int a = j * (n + 1) + i;
            out << "3 " << a << " " << a + 1 << " " << a + n + 2 << "\n";
            out << "3 " << a << " " << a + n + 2 << " " << a + n + 1 << "\n";
        }
    }
}

// The transform of an object of the scene, none at the root.
std::optional<Transform> transform_at(const Scene& scene, std::uint32_t node) {
    if (node == 0) return std::nullopt;
    return compose(transform_ops(scene, node));
}

// One object in its own frame, as brute force sees it.
std::optional<Hit> hit_in_frame(const std::optional<Transform>& transform,
                                const std::optional<Hit>& object_hit) {
    if (!object_hit || !transform) return object_hit;
    Hit hit = *object_hit;
    hit.normal = normal_to_world(*transform, hit.normal);
    return hit;
}

// A triangle's normal as the scene format defines it: along (p1 - p0) x (p2 - p0) of its world
// vertices M p, which a mirroring M turns against M^-T n.
std::optional<Hit> along_world_winding(const std::optional<Transform>& transform,
                                       const Triangle& triangle, std::optional<Hit> hit) {
    if (!hit || !transform) return hit;
    const Vec3 p0 = point_to_world(*transform, triangle.p0);
    const Vec3 winding = glm::cross(point_to_world(*transform, triangle.p1) - p0,
                                    point_to_world(*transform, triangle.p2) - p0);
    if (glm::dot(hit->normal, winding) < 0.0) hit->normal = -hit->normal;
    return hit;
}

void keep(std::optional<PrimitiveHit>& best, const std::optional<Hit>& hit, PrimitiveKind kind,
          std::size_t index) {
    if (!hit) return;
    const PrimitiveHit candidate{*hit, kind, index};
    if (!best || comes_before(candidate, *best)) best = candidate;
}

// Every sphere, triangle (written and instanced) and plane of the scene in turn.
std::optional<PrimitiveHit> brute_force(const Scene& scene, const Ray& ray) {
    std::optional<PrimitiveHit> best;
    for (std::size_t k = 0; k < scene.spheres.size(); ++k) {
        const auto transform = transform_at(scene, scene.spheres[k].attributes.transform);
        const Ray local = transform ? ray_to_object(*transform, ray) : ray;
        keep(best, hit_in_frame(transform, intersect_sphere(local, scene.spheres[k].shape)),
             PrimitiveKind::sphere, k);
    }
    for (std::size_t k = 0; k < scene.triangles.size(); ++k) {
        const auto transform = transform_at(scene, scene.triangles[k].attributes.transform);
        const Ray local = transform ? ray_to_object(*transform, ray) : ray;
        const Triangle& triangle = scene.triangles[k].shape;
        keep(best,
             along_world_winding(transform, triangle,
                                 hit_in_frame(transform, intersect_triangle(local, triangle))),
             PrimitiveKind::triangle, k);
    }
    std::size_t number = scene.triangles.size();
    for (const MeshInstance& instance : scene.mesh_instances) {
        const auto transform = transform_at(scene, instance.attributes.transform);
        const Ray local = transform ? ray_to_object(*transform, ray) : ray;
        for (const Triangle& triangle : scene.mesh_definitions[instance.definition].triangles) {
            keep(best,
                 along_world_winding(transform, triangle,
                                     hit_in_frame(transform, intersect_triangle(local, triangle))),
                 PrimitiveKind::triangle, number++);
        }
    }
    for (std::size_t k = 0; k < scene.planes.size(); ++k) {
        keep(best, intersect_plane(ray, scene.planes[k].shape), PrimitiveKind::plane, k);
    }
    return best;
}

std::string vec(const Vec3& v) {
    return to_text(v.x) + " " + to_text(v.y) + " " + to_text(v.z);
}

// Transformed spheres and triangles (some sharing a transform), and `meshes` placements of the
// grid mesh, each under its own rotation, non-uniform scale and translation.
std::string instanced_scene(PortableRandom& random, int spheres, int meshes) {
    std::string text = "camera 0 0 30 0 0 0 0 1 0 45\ndefine grid grid.off\n";
    // A mesh of no faces, turned: nothing to hit, and no box to spoil the others'
    text +=
        "define empty empty.off\npushTransform\nrotate 1 2 3 40\ninstance empty\npopTransform\n";
    text += "vertex -1 -1 0\nvertex 1 -1 0\nvertex 0 1 0\n";
    for (int k = 0; k < spheres + meshes; ++k) {
        text += "pushTransform\ntranslate " + vec(random.point(8.0)) + "\n";
        text +=
            "rotate " + vec(random.unit_vector()) + " " + to_text(random.uniform(0, 360)) + "\n";
        // Factors of either sign: a mirror turns a triangle's winding over
        const auto factor = [&] {
            const double size = random.uniform(0.2, 2);
            return random.integer(0, 3) == 0 ? -size : size;
        };
        const double fx = factor();
        const double fy = factor();
        const Vec3 factors(fx, fy, factor());
        text += "scale " + vec(factors) + "\n";
        if (k < spheres) {
            text +=
                "sphere " + vec(random.point(0.5)) + " " + to_text(random.uniform(0.3, 1)) + "\n";
            if (k % 3 == 0) text += "tri 0 1 2\n";  // a group: a sphere and a triangle
        } else {
            text += "instance grid\n";
        }
        text += "popTransform\n";
    }
    return text + "sphere 0 0 -3 1\ntri 0 1 2\n";
}

void check_same(const std::optional<PrimitiveHit>& got,
                const std::optional<PrimitiveHit>& expected) {
    REQUIRE(got.has_value() == expected.has_value());
    if (!got) return;
    CHECK(got->kind == expected->kind);
    CHECK(got->index == expected->index);
    CHECK(got->hit.t == expected->hit.t);
    CHECK(got->hit.normal == expected->hit.normal);
}

}  // namespace

TEST_CASE("instances: the instance BVH finds brute force's hits on spheres, triangles and meshes",
          "[app]") {
    testing::ScratchFolder folder("instances");
    write_grid_mesh(folder.path() / "grid.off", 4);  // 32 triangles: a BVH of their own
    std::ofstream(folder.path() / "empty.off") << "OFF\n0 0 0\n";
    for (const int spheres : {5, 60}) {
        CAPTURE(spheres);
        PortableRandom random(static_cast<std::uint64_t>(spheres));
        const Scene scene =
            parse_scene(instanced_scene(random, spheres, 30), "instances.test", folder.path());
        const RenderScene render_scene = prepare_render_scene(scene);
        REQUIRE(render_scene.instance_bvh.has_value());
        REQUIRE(render_scene.instance_geometries.back().bvh.has_value());
        int hits = 0;
        for (int k = 0; k < 4000; ++k) {
            CAPTURE(k);
            const Vec3 origin = random.point(15.0);
            Ray ray{origin, random.point(8.0) - origin};
            if (k % 2 == 1) ray.t_max = random.uniform(0.2, 1.5);  // a bounded, shadow-like ray
            const std::optional<PrimitiveHit> expected = brute_force(scene, ray);
            check_same(scene_closest_hit(render_scene, ray, nullptr), expected);
            CHECK(scene_occluded(render_scene, ray) == expected.has_value());
            hits += expected.has_value();
        }
        CHECK(hits > 500);
    }
}

TEST_CASE("instances: a mesh defined once is placed many times without copying it", "[app]") {
    testing::ScratchFolder folder("instances");
    write_grid_mesh(folder.path() / "grid.off", 10);
    std::string text = "camera 0 0 30 0 0 0 0 1 0 45\ndefine grid grid.off\n";
    for (int k = 0; k < 100; ++k) {
        text += "pushTransform\ntranslate " + std::to_string(k % 10) + " " +
                std::to_string(k / 10) + " 0\ninstance grid\npopTransform\n";
    }
    const Scene scene = parse_scene(text, "placed.test", folder.path());
    REQUIRE(scene.mesh_definitions.size() == 1);
    CHECK(scene.mesh_definitions[0].triangles.size() == 200);
    CHECK(scene.mesh_instances.size() == 100);
    CHECK(triangle_count(scene) == 20000);
    const RenderScene render_scene = prepare_render_scene(scene);
    CHECK(render_scene.instance_geometries.size() == 1);
    CHECK(render_scene.instances.size() == 100);
    // The 51st instance's triangle 7: its line, and its shape in the object frame.
    const std::size_t index = 50 * 200 + 7;
    CHECK(attributes_of(render_scene, PrimitiveKind::triangle, index).line ==
          scene.mesh_instances[50].attributes.line);
    CHECK(triangle_shape(render_scene, index).p0 == scene.mesh_definitions[0].triangles[7].p0);
    CHECK(instance_of(render_scene, PrimitiveKind::triangle, index) == &render_scene.instances[50]);
}

TEST_CASE("instances: define and instance errors name the line", "[app]") {
    testing::ScratchFolder folder("instances");
    write_grid_mesh(folder.path() / "grid.off", 2);
    const auto error_of = [&](const std::string& text) {
        try {
            parse_scene("camera 0 0 5 0 0 0 0 1 0 45\n" + text, "bad.test", folder.path());
        } catch (const std::exception& error) {
            return std::string(error.what());
        }
        return std::string("no error");
    };
    CHECK_THAT(error_of("instance grid\n"),
               Catch::Contains("bad.test:2") && Catch::Contains("no mesh named 'grid'"));
    CHECK_THAT(error_of("define grid grid.off\ndefine grid grid.off\n"),
               Catch::Contains("bad.test:3") && Catch::Contains("already defined, at line 2"));
    CHECK_THAT(error_of("define grid missing.off\n"),
               Catch::Contains("bad.test:2") && Catch::Contains("not found"));
    CHECK_THAT(error_of("define grid\n"), Catch::Contains("takes 2 or 3 arguments"));
}

TEST_CASE("instances: a defined mesh's normals and uvs shade each instance as its mesh's own",
          "[app]") {
    testing::ScratchFolder folder("instances");
    write_grid_mesh(folder.path() / "grid.off", 6);
    const std::string top =
        "size 40 30\ncamera 0 0 4 0 0 0 0 1 0 45\npoint 1 2 3 1 1 1\ndiffuse 0.8 0.8 0.8\n";
    const auto shaded = [&](const std::string& objects) {
        RenderOptions options;
        options.view = View::shaded;
        return render_image(
            prepare_render_scene(parse_scene(top + objects, "grid.test", folder.path())), options);
    };
    const Image meshed = shaded("mesh grid.off smooth\n");
    const Image placed = shaded("define grid grid.off smooth\ninstance grid\n");
    const Image flat = shaded("define grid grid.off\ninstance grid\n");
    double largest = 0.0;
    int unlike_flat = 0;
    for (int j = 0; j < meshed.height(); ++j) {
        for (int i = 0; i < meshed.width(); ++i) {
            const Color d = glm::abs(meshed.at(i, j) - placed.at(i, j));
            largest = std::max({largest, d.r, d.g, d.b});
            if (glm::length(meshed.at(i, j) - flat.at(i, j)) > 1e-3) ++unlike_flat;
        }
    }
    CHECK(largest < 1e-9);
    CHECK(unlike_flat > 100);

    // The texture coordinates an instance's triangle looks up are its definition's.
    std::ofstream(folder.path() / "quad.obj")
        << "v 0 0 0\nv 1 0 0\nv 1 1 0\nvt 0.5 0\nvt 1 0\nvt 1 1\nf 1/1 2/2 3/3\n";
    const Scene scene = parse_scene(
        "camera 0 0 4 0 0 0 0 1 0 45\ndefine quad quad.obj\n"
        "instance quad\ninstance quad\n",
        "quad.test", folder.path());
    const RenderScene render_scene = prepare_render_scene(scene);
    const TriangleCorners second = triangle_corners(render_scene, 1);
    REQUIRE(second.vertex_uvs >= 0);
    CHECK(scene.vertex_uvs[static_cast<std::size_t>(second.vertex_uvs)].uv0 == Vec2(0.5, 0));
    CHECK(second.vertex_normals == -1);
}
