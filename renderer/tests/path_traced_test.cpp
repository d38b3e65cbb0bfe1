// The renderer's use of stage 10: `integrator pathtracer` renders by paths over the scene.

#include <string>

#include <glm/gtc/constants.hpp>

#include "base/scene/scene_loader.h"
#include "base/testing/catch.h"
#include "renderer/polygon_irradiance.h"
#include "renderer/render_pixel.h"
#include "renderer/tile_renderer.h"

using namespace raystep;

namespace {

Scene path_traced_scene(const std::string& text) {
    return parse_scene(text, "paths.test", ".");
}

Color path_traced_pixel(const Scene& scene, int i, int j) {
    return render_pixel(prepare_render_scene(scene), View::full, i, j);
}

// A 1 x 1 image of the floor point at the origin under a 2 x 2 light 2 units above it, emitting
// 5 downwards; the floor's albedo 0.5. The field of view is narrow enough that the pixel's
// samples see the same light: its footprint is a hundredth of a unit.
const std::string kFloorUnderLight =
    "size 1 1\ncamera 3 5 0 0 0 0 0 1 0 0.1\nintegrator pathtracer\ndiffuse 0.5 0.5 0.5\n"
    "quadLight -1 2 -1 0 0 2 2 0 0 5 5 5\nvertex -40 0 -40\nvertex 40 0 -40\nvertex 40 0 40\n"
    "vertex -40 0 40\ntri 0 3 2\ntri 0 2 1\nmaxdepth 1\n";

// Kd / pi L E at the pixel's floor point, E the light's exact irradiance (Lambert's formula).
double direct_light(const Scene& scene) {
    const RenderScene render_scene = prepare_render_scene(scene);
    const Ray ray = camera_ray(render_scene, 0, 0);
    const std::optional<PrimitiveHit> hit = scene_closest_hit(render_scene, ray, nullptr);
    REQUIRE(hit);
    return 0.5 / glm::pi<double>() * 5.0 *
           quad_light_irradiance(scene.quad_lights[0], ray.at(hit->hit.t), Vec3(0, 1, 0));
}

}  // namespace

TEST_CASE("render_pixel: a path-traced floor's direct light is Lambert's, by every rule", "[app]") {
    const double expected = direct_light(path_traced_scene(kFloorUnderLight));
    // The standard deviation of such a pixel, measured over eight seeds: 0.3% of it with a
    // light sample at 4096 paths, 2.7% by cosine sampling alone, so 0.7% at 65536. Each bound
    // below is five of them.
    struct Rule {
        std::string text;
        double tolerance;
    };
    for (const Rule& rule :
         {Rule{"nexteventestimation on\nspp 4096\n", 0.015},
          Rule{"nexteventestimation mis\nspp 4096\n", 0.015},
          Rule{"nexteventestimation mis\nimportancesampling brdf\nspp 4096\n", 0.015},
          Rule{"importancesampling cosine\nspp 65536\n", 0.035}}) {
        CAPTURE(rule.text);
        const Color lit = path_traced_pixel(path_traced_scene(kFloorUnderLight + rule.text), 0, 0);
        CHECK(lit.r == Approx(expected).epsilon(rule.tolerance));
    }
}

TEST_CASE("render_pixel: a path-traced point out of the light's sight is lit by a bounce",
          "[app]") {
    // The floor point (3, 0, 0) under a plate at height 0.5 over x in [2, 4], z in [-1, 1],
    // which hides the whole light from it; under the plate's edge it sees a wall at x = 6 that
    // the light reaches. One bounce leaves it black, two light it. The eye looks at it from
    // under the plate.
    const std::string shadowed =
        "size 1 1\ncamera 3 0.25 0 3 0 0 1 0 0 0.1\nintegrator pathtracer\n"
        "diffuse 0.8 0.8 0.8\nnexteventestimation on\nimportancesampling cosine\nspp 256\n"
        "quadLight -2 3 -1 0 0 2 2 0 0 5 5 5\nvertex -40 0 -40\nvertex 40 0 -40\n"
        "vertex 40 0 40\nvertex -40 0 40\ntri 0 3 2\ntri 0 2 1\nvertex 2 0.5 -1\n"
        "vertex 4 0.5 -1\nvertex 4 0.5 1\nvertex 2 0.5 1\ntri 4 7 6\ntri 4 6 5\n"
        "vertex 6 0 -40\nvertex 6 40 -40\nvertex 6 40 40\nvertex 6 0 40\ntri 8 9 10\n"
        "tri 8 10 11\n";
    CHECK(path_traced_pixel(path_traced_scene(shadowed + "maxdepth 1\n"), 0, 0) == Color(0.0));
    CHECK(path_traced_pixel(path_traced_scene(shadowed + "maxdepth 2\n"), 0, 0).r > 0.0);
}

TEST_CASE("render_pixel: a closed white room's paths end after kLongestPath bounces", "[app]") {
    // Albedo 1: the throughput stays 1 and Russian roulette never ends a path. Every hit emits
    // 0.01, so a path gathers 0.01 at each of its 1001 hits.
    const Scene scene = path_traced_scene(
        "size 1 1\ncamera 0 0 0 0 0 -1 0 1 0 60\nintegrator pathtracer\nmaxdepth -1\n"
        "russianroulette on\nimportancesampling cosine\nambient 0 0 0\ndiffuse 1 1 1\n"
        "emission 0.01 0.01 0.01\nsphere 0 0 0 10\n");
    CHECK(path_traced_pixel(scene, 0, 0).r == Approx(0.01 * (kLongestPath + 1)).epsilon(1e-9));
}

TEST_CASE("render_image: a path-traced scene is the same for any thread count", "[app]") {
    const Scene scene = path_traced_scene(
        "size 12 8\ncamera 0 2 6 0 0.5 0 0 1 0 40\nintegrator pathtracer\nspp 4\nseed 5\n"
        "nexteventestimation mis\nimportancesampling brdf\nrussianroulette on\nmaxdepth -1\n"
        "quadLight -0.5 3 -0.5 0 0 1 1 0 0 20 20 20\ndiffuse 0.6 0.6 0.6\nspecular 0.3 0.3 0.3\n"
        "shininess 20\nvertex -4 0 -4\nvertex 4 0 -4\nvertex 4 0 4\nvertex -4 0 4\ntri 0 3 2\n"
        "tri 0 2 1\nbrdf ggx\nroughness 0.3\nsphere 0 1 0 0.8\n");
    const RenderScene render_scene = prepare_render_scene(scene);
    RenderOptions one;
    one.threads = 1;
    RenderOptions three;
    three.threads = 3;
    const Image a = render_image(render_scene, one);
    const Image b = render_image(render_scene, three);
    int lit = 0;
    for (int j = 0; j < scene.height; ++j) {
        for (int i = 0; i < scene.width; ++i) {
            CAPTURE(i, j);
            REQUIRE(a.at(i, j) == b.at(i, j));
            lit += a.at(i, j).r > 0.0 ? 1 : 0;
        }
    }
    CHECK(lit > 0);
}

TEST_CASE("render_image: the indirect view is the full path less its direct light", "[app]") {
    // The scene of the thread test: a sphere on a floor under a light, each pixel 4 paths. The
    // full view less the same scene cut at maxdepth 1 (the same seed, so the same random
    // numbers up to the cut) is the indirect view, within the images' float rounding.
    const std::string scene_text =
        "size 12 8\ncamera 0 2 6 0 0.5 0 0 1 0 40\nintegrator pathtracer\nspp 4\nseed 5\n"
        "nexteventestimation mis\nimportancesampling brdf\nrussianroulette on\n"
        "quadLight -0.5 3 -0.5 0 0 1 1 0 0 20 20 20\ndiffuse 0.6 0.6 0.6\nspecular 0.3 0.3 0.3\n"
        "shininess 20\nvertex -4 0 -4\nvertex 4 0 -4\nvertex 4 0 4\nvertex -4 0 4\ntri 0 3 2\n"
        "tri 0 2 1\nbrdf ggx\nroughness 0.3\nsphere 0 1 0 0.8\n";
    const auto render = [](const std::string& text, View view) {
        RenderOptions options;
        options.view = view;
        options.threads = 1;
        return render_image(prepare_render_scene(path_traced_scene(text)), options);
    };
    const Image full = render(scene_text + "maxdepth -1\n", View::full);
    const Image direct = render(scene_text + "maxdepth 1\n", View::full);
    const Image indirect = render(scene_text + "maxdepth -1\n", View::indirect);
    int bounced = 0;
    for (int j = 0; j < full.height(); ++j) {
        for (int i = 0; i < full.width(); ++i) {
            CAPTURE(i, j);
            const Color expected = full.at(i, j) - direct.at(i, j);
            const Color got = indirect.at(i, j);
            for (int c = 0; c < 3; ++c)
                CHECK(got[c] == Approx(expected[c]).margin(1e-6 * full.at(i, j)[c] + 1e-12));
            bounced += got.r > 0.0 ? 1 : 0;
        }
    }
    CHECK(bounced > 0);
    // At maxdepth 1 nothing bounces twice: the indirect view is black.
    const Image none = render(scene_text + "maxdepth 1\n", View::indirect);
    for (int j = 0; j < none.height(); ++j) {
        for (int i = 0; i < none.width(); ++i)
            CHECK(none.at(i, j) == Color(0.0));
    }
}
