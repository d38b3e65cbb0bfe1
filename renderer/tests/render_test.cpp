#include "renderer/tile_renderer.h"

#include <cmath>
#include <cstring>
#include <limits>
#include <string>

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

#include "base/math/to_text.h"
#include "base/scene/scene_loader.h"
#include "base/testing/catch.h"
#include "renderer/render_pixel.h"

using namespace raystep;

namespace {

// A 2 x 1 rectangle at z = 0 with its corner at (0, 0): neither centred nor symmetric, so a
// render that is shifted, mirrored, rotated or upside down has the wrong silhouette.
const Vec3 kCorners[4] = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}};

struct Camera {
    const char* name;
    Vec3 from;
    Vec3 at;
    Vec3 up;
    double fovy;            // perspective when > 0
    double ortho_half = 0;  // orthographic window [-h a, h a] x [-h, h] when fovy = 0
    int width;
    int height;
};

std::string quad_scene(const Camera& c) {
    std::string text = "size " + std::to_string(c.width) + " " + std::to_string(c.height) + "\n";
    text += "camera " + std::to_string(c.from.x) + " " + std::to_string(c.from.y) + " " +
            std::to_string(c.from.z) + " " + std::to_string(c.at.x) + " " + std::to_string(c.at.y) +
            " " + std::to_string(c.at.z) + " " + std::to_string(c.up.x) + " " +
            std::to_string(c.up.y) + " " + std::to_string(c.up.z) + " " +
            std::to_string(c.fovy > 0 ? c.fovy : 45.0) + "\n";
    if (c.fovy == 0) {
        const double aspect = double(c.width) / c.height;
        text += "ortho " + std::to_string(-c.ortho_half * aspect) + " " +
                std::to_string(c.ortho_half * aspect) + " " + std::to_string(-c.ortho_half) + " " +
                std::to_string(c.ortho_half) + "\n";
    }
    text += "vertex 0 0 0\nvertex 2 0 0\nvertex 2 1 0\nvertex 0 1 0\ntri 0 1 2\ntri 0 2 3\n";
    return text;
}

// Where OpenGL's own matrices put a world point, in pixel coordinates (x right, y down).
glm::dvec2 project(const Camera& c, const Vec3& p) {
    const double aspect = double(c.width) / c.height;
    const glm::dmat4 projection = c.fovy > 0
                                      ? glm::perspective(glm::radians(c.fovy), aspect, 0.01, 100.0)
                                      : glm::ortho(-c.ortho_half * aspect, c.ortho_half * aspect,
                                                   -c.ortho_half, c.ortho_half, 0.01, 100.0);
    const glm::dvec4 clip = projection * glm::lookAt(c.from, c.at, c.up) * glm::dvec4(p, 1.0);
    const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
    return {(ndc.x + 1.0) / 2.0 * c.width, (1.0 - ndc.y) / 2.0 * c.height};
}

// The signed distance in pixels from q to the line a -> b (positive on the left).
double edge_distance(glm::dvec2 a, glm::dvec2 b, glm::dvec2 q) {
    const glm::dvec2 e = b - a;
    return (e.x * (q.y - a.y) - e.y * (q.x - a.x)) / std::sqrt(e.x * e.x + e.y * e.y);
}

Image render_view(const Scene& scene, View view, int threads) {
    RenderOptions options;
    options.view = view;
    options.threads = threads;
    return render_image(prepare_render_scene(scene), options);
}

}  // namespace

TEST_CASE(
    "render: a rectangle seen from several cameras covers the pixels OpenGL's matrices predict",
    "[app]") {
    const Camera cameras[] = {
        {"front", {1, 0.5, 5}, {1, 0.5, 0}, {0, 1, 0}, 40, 0, 64, 48},
        {"from behind (mirrored)", {1, 0.5, -5}, {1, 0.5, 0}, {0, 1, 0}, 40, 0, 64, 48},
        {"rolled 45 degrees", {1, 0.5, 5}, {1, 0.5, 0}, {1, 1, 0}, 40, 0, 64, 48},
        {"upside down", {1, 0.5, 5}, {1, 0.5, 0}, {0, -1, 0}, 40, 0, 64, 48},
        {"oblique, off-centre", {4, 3, 4}, {0.5, 0.2, 0}, {0, 1, 0}, 35, 0, 72, 54},
        {"wide image", {1, 0.5, 4}, {0, 0, 0}, {0, 1, 0}, 30, 0, 96, 32},
        {"tall image", {1, 0.5, 4}, {1.5, 1, 0}, {0, 1, 0}, 60, 0, 30, 80},
        {"orthographic", {1, 0.5, 5}, {0.5, 0.5, 0}, {0, 1, 0}, 0, 1.2, 64, 48},
    };
    for (const Camera& camera : cameras) {
        CAPTURE(camera.name);
        const Scene scene = parse_scene(quad_scene(camera), "quad.test", ".");
        const Image depth = render_view(scene, View::depth, 2);

        glm::dvec2 corner[4];
        for (int k = 0; k < 4; ++k)
            corner[k] = project(camera, kCorners[k]);
        // The projected rectangle's winding: every inside point has this sign for all edges.
        const double winding = edge_distance(corner[0], corner[1], corner[2]) > 0 ? 1.0 : -1.0;

        int inside = 0;
        int outside = 0;
        for (int j = 0; j < camera.height; ++j) {
            for (int i = 0; i < camera.width; ++i) {
                const glm::dvec2 centre{i + 0.5, j + 0.5};
                double nearest_edge = std::numeric_limits<double>::infinity();
                bool in = true;
                for (int k = 0; k < 4; ++k) {
                    const double d =
                        winding * edge_distance(corner[k], corner[(k + 1) % 4], centre);
                    nearest_edge = std::min(nearest_edge, std::abs(d));
                    in = in && d > 0;
                }
                if (nearest_edge < 0.5) continue;  // a pixel centre this close could go either way
                CAPTURE(i, j);
                const bool hit = depth.at(i, j).r > 0.0;
                CHECK(hit == in);
                ++(in ? inside : outside);
            }
        }
        CHECK(inside > 50);  // the rectangle is really in view
        CHECK(outside > 50);
    }
}

TEST_CASE("render: the image is the same for any number of threads", "[app]") {
    const Scene scene = parse_scene(
        "size 97 61\ncamera 1 2 6 0 0 0 0 1 0 50\npoint 2 4 3 1 1 1\ndiffuse 0.3 0.5 0.2\n"
        "specular 0.4 0.4 0.4\nsphere 0 0 0 1\nsphere 1.5 0.5 -1 0.7\npushTransform\n"
        "translate -1.5 0.5 -1\nscale 1 0.5 1\nsphere 0 0 0 0.7\npopTransform\n"
        "vertex -3 -1 -3\nvertex 3 -1 -3\nvertex 0 -1 3\ntri 0 1 2\nplane 0 -2 0 0 1 0\n",
        "threads.test", ".");
    for (const View view :
         {View::rays, View::depth, View::normal, View::barycentric, View::shaded, View::full}) {
        CAPTURE(view_name(view));
        const Image one = render_view(scene, view, 1);
        for (const int threads : {2, 3, 8}) {
            CAPTURE(threads);
            const Image many = render_view(scene, view, threads);
            CHECK(std::memcmp(one.data(), many.data(), sizeof(float) * 3 * 97 * 61) == 0);
        }
    }
}

TEST_CASE("render: an error in a worker thread stops the render and reaches the caller", "[app]") {
    // The point light sits exactly where the centre pixel's ray meets the sphere, (0, 0, 1):
    // sample_light has no direction to it and throws, and the error must come out of the worker
    // threads intact (as a stub's NotImplemented does in a student's build).
    const Scene scene =
        parse_scene("size 1 1\ncamera 0 0 5 0 0 0 0 1 0 45\npoint 0 0 1 1 1 1\nsphere 0 0 0 1\n",
                    "light_on_surface.test", ".");
    CHECK_THROWS_WITH(render_view(scene, View::shaded, 4),
                      Catch::Matchers::Contains("is at the light"));
}

TEST_CASE("render_pixel: the rays view shows the direction as 0.5 (d + 1)", "[app]") {
    const Scene scene = parse_scene("size 3 3\ncamera 0 0 5 0 0 0 0 1 0 45\n", "rays.test", ".");
    const RenderScene render_scene = prepare_render_scene(scene);
    const Color centre = render_pixel(render_scene, View::rays, 1, 1);
    CHECK(centre.r == Approx(0.5));
    CHECK(centre.g == Approx(0.5));
    CHECK(centre.b == Approx(0.0));  // straight down -z
}

TEST_CASE("finish_view: depth becomes t_near / t, misses black", "[app]") {
    Image image(3, 1);
    image.set(0, 0, Color(2.0));
    image.set(1, 0, Color(8.0));
    image.set(2, 0, Color(std::numeric_limits<double>::infinity()));
    finish_view(image, View::depth);
    CHECK(image.at(0, 0) == Color(1.0));
    CHECK(image.at(1, 0) == Color(0.25));
    CHECK(image.at(2, 0) == Color(0.0));
}

TEST_CASE("render: the normal and barycentric views colour a triangle as expected", "[app]") {
    // fovy 90 from z = 5: the 9 x 9 image spans [-5, 5]^2 at z = 0, 10/9 per pixel.
    const Scene scene = parse_scene(
        "size 9 9\ncamera 0 0 5 0 0 0 0 1 0 90\nvertex -4 -4 0\nvertex 4 -4 0\nvertex 0 4 0\n"
        "tri 0 1 2\n",
        "views.test", ".");
    const Image normal = render_view(scene, View::normal, 1);
    CHECK(normal.at(4, 4).r == Approx(0.5));
    CHECK(normal.at(4, 4).b == Approx(1.0));  // the normal +z
    const Image barycentric = render_view(scene, View::barycentric, 1);
    const Color centre = barycentric.at(4, 4);  // (0, 0): weights 1/4, 1/4, 1/2
    CHECK(centre.r == Approx(0.25));
    CHECK(centre.g == Approx(0.25));
    CHECK(centre.b == Approx(0.5));
    CHECK(barycentric.at(4, 1).b > 0.9);        // (0, 3.33), near p2 at the top: blue
    CHECK(barycentric.at(0, 0) == Color(0.0));  // (-4.4, 4.4): a miss
}

TEST_CASE("scene_closest_hit: through the BVH, the same hit as closest_hit at every pixel",
          "[app]") {
    // 200 triangles and 50 spheres: a BVH scene. Every camera ray must get closest_hit's answer.
    std::string text = "size 48 36\ncamera 0 1 12 0 0 0 0 1 0 50\nplane 0 -3 0 0 1 0\n";
    for (int k = 0; k < 200; ++k) {
        const double x = (k % 20) * 0.5 - 5.0;
        const double y = (k / 20) * 0.5 - 2.5;
        text += "vertex " + std::to_string(x) + " " + std::to_string(y) + " " +
                std::to_string(0.1 * (k % 7)) + "\n";
    }
    for (int k = 0; k + 21 < 200; ++k) {
        text += "tri " + std::to_string(k) + " " + std::to_string(k + 1) + " " +
                std::to_string(k + 21) + "\n";
    }
    for (int k = 0; k < 50; ++k) {
        text += "sphere " + std::to_string((k % 10) - 4.5) + " " + std::to_string(k / 10 - 2.0) +
                " 1.5 0.3\n";
    }
    const Scene scene = parse_scene(text, "bvh.test", ".");
    const RenderScene render_scene = prepare_render_scene(scene);
    REQUIRE(render_scene.bvh.has_value());
    for (int j = 0; j < scene.height; ++j) {
        for (int i = 0; i < scene.width; ++i) {
            CAPTURE(i, j);
            const Ray ray = camera_ray(render_scene, i, j);
            const std::optional<PrimitiveHit> expected = closest_hit(ray, render_scene.primitives);
            const std::optional<PrimitiveHit> got = scene_closest_hit(render_scene, ray, nullptr);
            REQUIRE(got.has_value() == expected.has_value());
            if (got) {
                CHECK(got->kind == expected->kind);
                CHECK(got->index == expected->index);
                CHECK(got->hit.t == expected->hit.t);
            }
        }
    }
}
