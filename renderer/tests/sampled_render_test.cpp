// The renderer's use of stage 8: samples per pixel, the random streams of a render, quad lights.

#include <string>

#include <glm/gtc/constants.hpp>

#include "base/scene/scene_loader.h"
#include "base/testing/catch.h"
#include "renderer/polygon_irradiance.h"
#include "renderer/render_pixel.h"
#include "renderer/sample_streams.h"
#include "renderer/tile_renderer.h"

using namespace raystep;

namespace {

// An orthographic 4 x 4 view of [-2, 2]^2 at z = 0: pixel column i covers x in [i - 2, i - 1].
// A white emitting rectangle covers x <= -0.5, so column 1 is half covered, split down the
// middle, and no sample of a regular 2 x 2 or 4 x 4 grid lies on the edge.
const std::string kHalfCovered =
    "size 4 4\ncamera 0 0 5 0 0 0 0 1 0 45\northo -2 2 -2 2\nambient 0 0 0\nemission 1 1 1\n"
    "vertex -9 -9 0\nvertex -0.5 -9 0\nvertex -0.5 9 0\nvertex -9 9 0\ntri 0 1 2\n"
    "tri 0 2 3\n";

Scene scene_from(const std::string& text) {
    return parse_scene(text, "sampled.test", ".");
}

Color pixel_of(const Scene& scene, View view, int i, int j) {
    return render_pixel(prepare_render_scene(scene), view, i, j);
}

// A sphere on a floor under a quad light, four samples per pixel: every random number a render
// draws.
const std::string kSoftShadow =
    "size 24 16\ncamera 0 2 6 0 0.5 0 0 1 0 40\nspp 4\nlightsamples 4\nlightstratify on\n"
    "seed 7\nquadLight -0.5 3 -0.5 0 0 1 1 0 0 20 20 20\nambient 0.05 0.05 0.05\n"
    "diffuse 0.8 0.8 0.8\nvertex -4 0 -4\nvertex 4 0 -4\nvertex 4 0 4\nvertex -4 0 4\n"
    "tri 0 3 2\ntri 0 2 1\nsphere 0 1 0 0.8\n";

}  // namespace

TEST_CASE("render_pixel: a pixel half covered by an edge averages to one half at spp 16", "[app]") {
    Scene scene = scene_from(kHalfCovered);
    scene.samples_per_pixel = 16;
    scene.pixel_sampling = SamplePattern::regular;
    // Two of the four columns of stratum centres, x = -0.875 and -0.625, are covered.
    CHECK(pixel_of(scene, View::full, 1, 2).r == 0.5);
    CHECK(pixel_of(scene, View::shaded, 1, 2).r == 0.5);
    CHECK(pixel_of(scene, View::full, 0, 2).r == 1.0);  // wholly covered
    CHECK(pixel_of(scene, View::full, 2, 2).r == 0.0);  // wholly outside
    // Jittered: 4 of the 16 strata's columns are in, whatever the jitter, so still one half.
    scene.pixel_sampling = SamplePattern::jittered;
    CHECK(pixel_of(scene, View::full, 1, 2).r == 0.5);
}

TEST_CASE("render_pixel: at spp 1 the seed and the pattern change nothing: one centre ray",
          "[app]") {
    Scene scene = scene_from(kSoftShadow);
    scene.samples_per_pixel = 1;
    scene.light_samples = 1;
    scene.quad_lights.clear();
    scene.point_lights.push_back({Vec3(1, 4, 2), Color(1.0), Attenuation{}, 0});
    const Color centre = pixel_of(scene, View::full, 12, 9);
    scene.seed = 99;
    scene.pixel_sampling = SamplePattern::random;
    CHECK(pixel_of(scene, View::full, 12, 9) == centre);
}

TEST_CASE("render_pixel: the depth, normal and rays views keep one centre ray at spp > 1",
          "[app]") {
    Scene scene = scene_from(kHalfCovered);
    scene.samples_per_pixel = 1;
    const Color depth = pixel_of(scene, View::depth, 1, 1);
    const Color normal = pixel_of(scene, View::normal, 1, 1);
    scene.samples_per_pixel = 16;
    CHECK(pixel_of(scene, View::depth, 1, 1) == depth);
    CHECK(pixel_of(scene, View::normal, 1, 1) == normal);
    CHECK_FALSE(averages_samples(View::depth));
    CHECK_FALSE(averages_samples(View::rays));
    CHECK(averages_samples(View::shaded));
}

TEST_CASE("render_image: a sampled scene with a quad light is the same for any thread count",
          "[app]") {
    const Scene scene = scene_from(kSoftShadow);
    const RenderScene render_scene = prepare_render_scene(scene);
    RenderOptions one;
    one.threads = 1;
    RenderOptions three;
    three.threads = 3;
    const Image a = render_image(render_scene, one);
    const Image b = render_image(render_scene, three);
    for (int j = 0; j < scene.height; ++j) {
        for (int i = 0; i < scene.width; ++i) {
            CAPTURE(i, j);
            REQUIRE(a.at(i, j) == b.at(i, j));
        }
    }
}

TEST_CASE("render_pixel: another seed gives other noise in a penumbra, the same seed the same",
          "[app]") {
    Scene scene = scene_from(kSoftShadow);
    int differing = 0;
    for (int i = 0; i < scene.width; ++i) {
        const Color first = pixel_of(scene, View::full, i, 12);
        CHECK(pixel_of(scene, View::full, i, 12) == first);
        Scene other = scene;
        other.seed = 8;
        if (pixel_of(other, View::full, i, 12) != first) ++differing;
    }
    CHECK(differing > 0);
}

TEST_CASE("render_pixel: a floor point under a quad light, no blocker, as stage 8 integrates it",
          "[app]") {
    // A 1 x 1 image looking down at the origin from the side; a 0.2 x 0.2 light 2 units above.
    // Small against its distance, the light gives close to L A cos cos / (pi d^2) Kd:
    // 20 0.04 / (4 pi) 0.5 = 0.0318, ambient 0 added.
    const std::string text =
        "size 1 1\ncamera 3 5 0 0 0 0 0 1 0 10\nambient 0 0 0\ndiffuse 0.5 0.5 0.5\n"
        "lightsamples 16\nlightstratify on\nquadLight -0.1 2 -0.1 0 0 0.2 0.2 0 0 20 20 20\n"
        "vertex -4 0 -4\nvertex 4 0 -4\nvertex 4 0 4\nvertex -4 0 4\ntri 0 3 2\ntri 0 2 1\n";
    const Color lit = pixel_of(scene_from(text), View::shaded, 0, 0);
    CHECK(lit.r == Approx(20.0 * 0.04 / (4.0 * 3.14159265358979) * 0.5).epsilon(0.01));
    // A blocker between them, out of the eye ray's way: every light sample is occluded.
    const Color shadowed = pixel_of(scene_from(text + "sphere 0 1 0 0.3\n"), View::shaded, 0, 0);
    CHECK(shadowed == Color(0.0));
}

TEST_CASE("render_pixel: a diffuse floor under a quad light renders alike in both dialects",
          "[app]") {
    // The same light samples shaded by Blinn-Phong or by the Phong lobe: with no specular, the
    // same diffuse term. With a specular, the lobes differ.
    const std::string floor =
        "size 8 8\ncamera 3 5 0 0 0 0 0 1 0 30\nambient 0 0 0\ndiffuse 0.5 0.5 0.5\nseed 3\n"
        "lightsamples 4\nlightstratify on\nquadLight -2 2 -1 0 0 2 1 0 0 5 5 5\n"
        "vertex -4 0 -4\nvertex 4 0 -4\nvertex 4 0 4\nvertex -4 0 4\ntri 0 3 2\ntri 0 2 1\n"
        "sphere 0 0.5 0 0.3\n";
    const Scene cse167 = scene_from(floor);
    const Scene cse168 = scene_from(floor + "integrator direct\n");
    for (int i = 0; i < 8; ++i) {
        CAPTURE(i);
        CHECK(pixel_of(cse168, View::full, i, 5) == pixel_of(cse167, View::full, i, 5));
    }
    const std::string shiny = "specular 0.5 0.5 0.5\nshininess 20\n";
    const Scene shiny_cse167 = scene_from(shiny + floor);
    const Scene shiny_cse168 = scene_from(shiny + floor + "integrator direct\n");
    int differing = 0;
    for (int i = 0; i < 8; ++i) {
        if (pixel_of(shiny_cse168, View::full, i, 5) != pixel_of(shiny_cse167, View::full, i, 5))
            ++differing;
    }
    CHECK(differing > 0);
}

TEST_CASE("render_pixel: integrator analyticdirect integrates a quad light exactly, unshadowed",
          "[app]") {
    // The floor point at the image's centre, under the light of the test above: Kd / pi L E, with
    // no noise whatever the seed, and no shadow from a blocker.
    const std::string text =
        "size 1 1\ncamera 3 5 0 0 0 0 0 1 0 10\nambient 0 0 0\ndiffuse 0.5 0.5 0.5\n"
        "integrator analyticdirect\nquadLight -0.1 2 -0.1 0 0 0.2 0.2 0 0 20 20 20\n"
        "vertex -4 0 -4\nvertex 4 0 -4\nvertex 4 0 4\nvertex -4 0 4\ntri 0 3 2\ntri 0 2 1\n";
    const Scene scene = scene_from(text);
    const RenderScene render_scene = prepare_render_scene(scene);
    const std::optional<PrimitiveHit> hit =
        scene_closest_hit(render_scene, camera_ray(render_scene, 0, 0), nullptr);
    REQUIRE(hit);
    const Vec3 point = camera_ray(render_scene, 0, 0).at(hit->hit.t);
    const double expected = 0.5 / glm::pi<double>() * 20.0 *
                            quad_light_irradiance(scene.quad_lights[0], point, Vec3(0, 1, 0));
    CHECK(expected == Approx(20.0 * 0.04 / (4.0 * glm::pi<double>()) * 0.5).epsilon(0.01));
    const Color lit = pixel_of(scene, View::full, 0, 0);
    CHECK(lit.r == Approx(expected).epsilon(1e-12));
    Scene reseeded = scene;
    reseeded.seed = 11;
    CHECK(pixel_of(reseeded, View::full, 0, 0) == lit);
    CHECK(pixel_of(scene_from(text + "sphere 0 1 0 0.3\n"), View::full, 0, 0) == lit);
}

TEST_CASE("render_pixel: in the CSE168 dialect specular is no mirror, even beside glass", "[app]") {
    // Looking straight down at a specular floor under a glowing ceiling; a glass sphere out of view
    // turns stage 9's recursion on. CSE167 sees the ceiling in the floor, CSE168 the floor alone.
    const std::string text =
        "size 1 1\ncamera 0 5 0 0 0 0 0 0 -1 10\nambient 0 0 0\nspecular 0.8 0.8 0.8\n"
        "plane 0 0 0 0 1 0\nspecular 0 0 0\nemission 1 1 1\nplane 0 10 0 0 1 0\n"
        "emission 0 0 0\ntransmission 1 1 1\nior 1.5\nsphere 20 0 0 1\n";
    CHECK(pixel_of(scene_from(text), View::full, 0, 0) == Color(0.8));
    CHECK(pixel_of(scene_from(text + "integrator direct\n"), View::full, 0, 0) == Color(0.0));
}

TEST_CASE("render_pixel: the CSE168 dialect draws quad lights, bright in front and black behind",
          "[app]") {
    // The 4 x 4 orthographic view over a wall that glows 0.5, with two lights between: over
    // column 0 one that faces the camera (ac x ab = +z), over column 3 one that faces the wall.
    const std::string walls_and_lights =
        "size 4 4\ncamera 0 0 5 0 0 0 0 1 0 45\northo -2 2 -2 2\nambient 0 0 0\n"
        "emission 0.5 0.5 0.5\nvertex -9 -9 0\nvertex 9 -9 0\nvertex 9 9 0\nvertex -9 9 0\n"
        "tri 0 1 2\ntri 0 2 3\nquadLight -2 -2 1  0 4 0  1 0 0  3 2 1\n"
        "quadLight 1 -2 1  1 0 0  0 4 0  3 2 1\n";
    const Scene cse168 = scene_from(walls_and_lights + "integrator direct\n");
    for (const View view : {View::full, View::shaded}) {
        CHECK(pixel_of(cse168, view, 0, 1) == Color(3, 2, 1));
        CHECK(pixel_of(cse168, view, 3, 1) == Color(0.0));
        CHECK(pixel_of(cse168, view, 1, 1) == Color(0.5));
    }
    // The views of one stage each still see the wall: the depth view its t of 5.
    CHECK(pixel_of(cse168, View::depth, 0, 1) == Color(5.0));
    const Scene cse167 = scene_from(walls_and_lights);
    CHECK(pixel_of(cse167, View::full, 0, 1) == Color(0.5));
    CHECK(pixel_of(cse167, View::full, 3, 1) == Color(0.5));
}

TEST_CASE("pixel_stream: no two (pixel, use) pairs of an image share a stream", "[app]") {
    // The low half is the use, the high half the pixel: neighbours in either never collide, and
    // the last use of a pixel stays below the first of the next.
    CHECK(pixel_stream(640, 0, 0, kFilmStream) != pixel_stream(640, 0, 0, light_stream_use(0)));
    CHECK(pixel_stream(640, 1, 0, kFilmStream) != pixel_stream(640, 0, 1, kFilmStream));
    CHECK(pixel_stream(640, 0, 0, light_stream_use(65535)) < pixel_stream(640, 1, 0, kFilmStream));
    CHECK(pixel_stream(640, 639, 0, kFilmStream) + (1ull << 32) ==
          pixel_stream(640, 0, 1, kFilmStream));
}
