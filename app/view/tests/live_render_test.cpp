// LiveRender (app/view/live_render.h): a view that averages samples converges in passes of 1, 4,
// 16, ... samples, the last of them the scene's own render.

#include "app/view/live_render.h"

#include <chrono>
#include <string>
#include <thread>
#include <vector>

#include "base/scene/scene_loader.h"
#include "base/testing/catch.h"

using namespace raystep;

TEST_CASE("progressive_passes: squares of four below spp, then spp itself", "[app]") {
    CHECK(progressive_passes(1) == std::vector<int>{1});
    CHECK(progressive_passes(4) == std::vector<int>{1, 4});
    CHECK(progressive_passes(64) == std::vector<int>{1, 4, 16, 64});
    CHECK(progressive_passes(100) == std::vector<int>{1, 4, 16, 64, 100});
    CHECK(progressive_passes(5) == std::vector<int>{1, 4, 5});
}

namespace {

// A sphere under a light, w x h pixels, `spp` samples each.
Scene small_scene(int w, int h, int spp) {
    return parse_scene("size " + std::to_string(w) + " " + std::to_string(h) +
                           "\ncamera 0 0 4 0 0 0 0 1 0 45\nspp " + std::to_string(spp) +
                           "\npoint 1 1 3 1 1 1\ndiffuse 0.5 0.5 0.5\nsphere 0 0 0 1\n",
                       "small.test", ".");
}

// The render's changes once it is done.
LiveRender::Changes finished(LiveRender& live, std::uint64_t generation) {
    LiveRender::Changes changes;
    do {
        changes = live.changes_since(generation, 0);
        std::this_thread::sleep_for(std::chrono::microseconds(200));
    } while (changes.state == LiveRender::State::rendering);
    return changes;
}

}  // namespace

TEST_CASE("LiveRender: a sampled full view shows each pass, and ends on the scene's spp", "[app]") {
    LiveRender live;
    // One pass at 1 spp: its tiles and the whole image that ends it.
    const LiveRender::Changes one =
        finished(live, live.start(small_scene(32, 24, 1), View::full, 1));
    REQUIRE(one.state == LiveRender::State::done);

    const std::uint64_t generation = live.start(small_scene(32, 24, 16), View::full, 1);
    const LiveRender::Changes changes = finished(live, generation);
    REQUIRE(changes.state == LiveRender::State::done);
    CHECK(changes.samples == 16);
    CHECK(changes.target_samples == 16);
    // Three passes, 1, 4 and 16 spp, each its tiles and the whole image that ends it.
    CHECK(changes.sequence - one.sequence == 3 * one.sequence);
    REQUIRE(changes.tiles.size() == 1);
    CHECK(changes.tiles.front().rect.x1 == 32);
    CHECK(changes.tiles.front().rect.y1 == 24);
}

TEST_CASE("LiveRender: a view of one ray per pixel renders once, whatever the spp", "[app]") {
    LiveRender live;
    const LiveRender::Changes one =
        finished(live, live.start(small_scene(16, 16, 1), View::depth, 1));
    const LiveRender::Changes changes =
        finished(live, live.start(small_scene(16, 16, 64), View::depth, 1));
    REQUIRE(changes.state == LiveRender::State::done);
    CHECK(changes.samples == 1);
    CHECK(changes.target_samples == 1);
    CHECK(changes.sequence - one.sequence == one.sequence);
}
