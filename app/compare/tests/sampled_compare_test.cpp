// A sampled scene as `raystep compare` and `raystep trace --compare` judge it: one render against
// the reference's mean over kSampledReferenceRenders seeds and its tile spread
// (compare_render_with_spread, sampled_reference.h), and a sampled pixel's record, which holds its
// centre ray whatever order its samples come in (render_pixel.h).

#include <string>
#include <vector>

#include "app/compare/noisy_render_comparison.h"
#include "app/compare/sampled_reference.h"
#include "base/scene/scene_loader.h"
#include "base/testing/catch.h"
#include "renderer/pixel_record.h"
#include "renderer/render_pixel.h"
#include "renderer/tile_renderer.h"

using namespace raystep;

namespace {

// A sphere on a floor under a quad light, four samples per pixel: a penumbra, a lit floor and a
// background, each noisy in its own way.
const std::string kSoftShadowScene =
    "size 64 48\ncamera 0 2 6 0 0.5 0 0 1 0 40\nspp 4\nlightsamples 4\nlightstratify on\n"
    "quadLight -0.5 3 -0.5 0 0 1 1 0 0 20 20 20\nambient 0.05 0.05 0.05\n"
    "diffuse 0.6 0.6 0.6\nvertex -4 0 -4\nvertex 4 0 -4\nvertex 4 0 4\nvertex -4 0 4\n"
    "tri 0 3 2\ntri 0 2 1\nsphere 0 1 0 0.8\n";

Image render_at(Scene scene, std::uint64_t seed) {
    scene.seed = seed;
    RenderOptions options;
    options.threads = 1;
    return render_image(prepare_render_scene(scene), options);
}

NoisyComparison judge(const Image& render, const Image& mean, const Image& spread) {
    return compare_render_with_spread(render, mean, spread, kSampledReferenceRenders, kSampledTile,
                                      kSampledTileBound, kSampledDeviationFloor);
}

PixelRecord record_of(const Scene& scene, int i, int j) {
    PixelRecord record;
    PixelRecorder recorder(record, scene.dialect);
    render_pixel(prepare_render_scene(scene), View::full, i, j, recorder);
    return record;
}

}  // namespace

TEST_CASE("compare_render_with_spread: the reference at other seeds passes, a brighter light fails",
          "[app]") {
    const Scene scene = parse_scene(kSoftShadowScene, "soft.test", ".");
    REQUIRE(is_sampled_view(scene, View::full));
    std::vector<Image> reference;
    for (int k = 0; k < kSampledReferenceRenders; ++k)
        reference.push_back(render_at(scene, kSampledReferenceSeeds + static_cast<unsigned>(k)));
    const Image mean = mean_image(reference);
    const Image spread = tile_deviations(reference, kSampledTile);

    // 48 tiles a render: at 4 standard errors a right render has a tile apart now and then, and
    // never a tenth of them.
    int apart = 0;
    for (std::uint64_t seed = 1; seed <= 8; ++seed) {
        CAPTURE(seed);
        const NoisyComparison right = judge(render_at(scene, seed), mean, spread);
        CHECK(right.tiles == 48);
        CHECK(right.tiles_apart <= 2);
        apart += right.tiles_apart;
    }
    CHECK(apart <= 3);

    // The light a quarter too bright, as a quad light without its cosine is at these angles:
    // every lit tile moves.
    Scene brighter = scene;
    brighter.quad_lights.front().radiance *= 1.25;
    const NoisyComparison biased = judge(render_at(brighter, 1), mean, spread);
    CHECK(biased.tiles_apart >= 12);
}

TEST_CASE("render_pixel: a sampled pixel's record is its centre ray's, whatever the seed",
          "[app]") {
    Scene scene = parse_scene(kSoftShadowScene, "soft.test", ".");
    scene.quad_lights.clear();
    scene.point_lights.push_back(PointLight{});
    scene.point_lights.back().position = Vec3(0.0, 3.0, 0.0);
    scene.point_lights.back().color = Color(1.0);
    const PixelRecord sampled = record_of(scene, 30, 30);
    scene.seed = 99;
    const PixelRecord reseeded = record_of(scene, 30, 30);
    scene.samples_per_pixel = 1;
    const PixelRecord centre = record_of(scene, 30, 30);
    for (const PixelRecord* record : {&sampled, &reseeded}) {
        REQUIRE(record->camera_ray);
        CHECK(record->camera_ray->direction == centre.camera_ray->direction);
        REQUIRE(record->hit);
        CHECK(record->hit->hit.t == centre.hit->hit.t);
        REQUIRE(record->lights.size() == 1);
        CHECK(record->lights.front().term == centre.lights.front().term);
        CHECK(*record->full == *centre.full);
    }
}
