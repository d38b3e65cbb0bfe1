#include "app/compare/reference_trace.h"

#include <cmath>
#include <fstream>

#include "app/compare/reference_image.h"
#include "base/errors/input_error.h"
#include "base/image/image_io.h"
#include "base/scene/scene_loader.h"
#include "base/testing/catch.h"
#include "base/testing/filled_image.h"
#include "base/testing/scratch_folder.h"
#include "renderer/tile_renderer.h"

using namespace raystep;
namespace fs = std::filesystem;

namespace {

// A hit on triangle 3 and a miss, with values a float32 keeps to 10 bits exactly, so that they
// read back equal; two lights, one reaching and one blocked; a full colour that differs from the
// local one (a reflection), so that both are stored.
std::vector<PixelRecord> two_pixels() {
    PixelRecord hit;
    hit.camera_ray = Ray{Vec3(0.0, 0.0, 4.0), Vec3(0.5, -0.25, -1.0)};
    hit.hit_searched = true;
    hit.hit = PrimitiveHit{Hit{4.25, Vec3(0.0, 0.0, 1.0), 0.125, 0.5}, PrimitiveKind::triangle, 3};
    hit.lights = {{LightReach::reaches, Color(0.5, 0.25, 0.0)}, {LightReach::blocked, Color(0.0)}};
    hit.local = Color(0.75, 0.5, 0.25);
    hit.full = Color(1.0, 0.5, 0.25);
    PixelRecord miss;
    miss.camera_ray = Ray{Vec3(0.0, 0.0, 4.0), Vec3(-0.5, 0.25, -1.0)};
    miss.hit_searched = true;
    miss.full = Color(0.0);
    return {hit, miss};
}

}  // namespace

TEST_CASE("reference_trace_path: <scene>.trace.exr in the reference folder beside the scene",
          "[app]") {
    CHECK(reference_trace_path("scenes/stage2/orthographic.test") ==
          fs::path("scenes/stage2/reference/orthographic.trace.exr"));
}

TEST_CASE("reference trace: every value written reads back exactly", "[app]") {
    const raystep::testing::ScratchFolder folder("reference-trace");
    const fs::path path = folder.path() / "two.trace.exr";
    write_reference_trace(path, 2, 1, View::full, 2, two_pixels(), "0123456789abcdef");

    const ReferenceTrace trace = read_reference_trace(path);
    CHECK(trace.width == 2);
    CHECK(trace.height == 1);
    CHECK(trace.view == View::full);
    CHECK(trace.lights == 2);
    CHECK(trace.scene_digest == "0123456789abcdef");
    const PixelRecord& hit = trace.at(0, 0);
    REQUIRE(hit.camera_ray);
    CHECK(hit.camera_ray->origin == Vec3(0.0, 0.0, 4.0));
    CHECK(hit.camera_ray->direction == Vec3(0.5, -0.25, -1.0));
    REQUIRE(hit.hit);
    CHECK(hit.hit->kind == PrimitiveKind::triangle);
    CHECK(hit.hit->index == 3);
    CHECK(hit.hit->hit.t == 4.25);
    CHECK(hit.hit->hit.normal == Vec3(0.0, 0.0, 1.0));
    CHECK(hit.hit->hit.beta == 0.125);
    CHECK(hit.hit->hit.gamma == 0.5);
    REQUIRE(hit.lights.size() == 2);
    CHECK(hit.lights[0].reach == LightReach::reaches);
    CHECK(hit.lights[0].term == Color(0.5, 0.25, 0.0));
    CHECK(hit.lights[1].reach == LightReach::blocked);
    CHECK(hit.local == Color(0.75, 0.5, 0.25));
    CHECK(hit.full == Color(1.0, 0.5, 0.25));

    const PixelRecord& miss = trace.at(1, 0);
    CHECK(miss.hit_searched);
    CHECK_FALSE(miss.hit);
    CHECK(miss.lights.empty());
    CHECK_FALSE(miss.local);
    CHECK(miss.full == Color(0.0));
}

TEST_CASE("reference trace: a value is rounded to nearest within its stored roundoff", "[app]") {
    const raystep::testing::ScratchFolder folder("reference-trace");
    const fs::path path = folder.path() / "third.trace.exr";
    std::vector<PixelRecord> pixels = two_pixels();
    const double third = 1.0 / 3.0;
    pixels[0].hit->hit.t = third;
    pixels[0].local = Color(third);
    write_reference_trace(path, 2, 1, View::full, 2, pixels, "");

    const PixelRecord read = read_reference_trace(path).at(0, 0);
    const double t = read.hit->hit.t;
    CHECK(t != third);
    CHECK(std::abs(t - third) <= stored_roundoff(TraceQuantity::t) * third);
    CHECK(std::abs(read.local->r - third) <= stored_roundoff(TraceQuantity::local_colour) * third);
    // Kept to fewer bits, a colour is coarser than t.
    CHECK(std::abs(read.local->r - third) > std::abs(t - third));
}

TEST_CASE("reference trace: a full colour equal to the local one reads back as it", "[app]") {
    const raystep::testing::ScratchFolder folder("reference-trace");
    const fs::path path = folder.path() / "local.trace.exr";
    std::vector<PixelRecord> pixels = two_pixels();
    pixels[0].full = pixels[0].local;
    write_reference_trace(path, 2, 1, View::full, 2, pixels, "");

    const ReferenceTrace trace = read_reference_trace(path);
    CHECK(trace.at(0, 0).full == Color(0.75, 0.5, 0.25));
    CHECK(trace.at(1, 0).full == Color(0.0));
}

TEST_CASE("reference trace: a view's reach bounds what is stored and read back", "[app]") {
    const raystep::testing::ScratchFolder folder("reference-trace");
    const fs::path path = folder.path() / "normal.trace.exr";
    write_reference_trace(path, 2, 1, View::normal, 2, two_pixels(), "");

    const ReferenceTrace trace = read_reference_trace(path);
    CHECK(trace.view == View::normal);
    CHECK(trace.at(0, 0).hit->hit.t == 4.25);
    CHECK(trace.at(0, 0).lights.empty());
    CHECK_FALSE(trace.at(0, 0).local);
    CHECK_FALSE(trace.at(0, 0).full);
}

TEST_CASE("reference trace: a truncated file is an InputError naming it", "[app]") {
    const raystep::testing::ScratchFolder folder("reference-trace");
    const fs::path path = folder.path() / "cut.trace.exr";
    const Scene scene =
        parse_scene("size 40 30\ncamera 0 0 5 0 0 0 0 1 0 45\nsphere 0 0 0 1\npoint 0 5 5 1 1 1\n",
                    "cut.test", RAYSTEP_TEST_DATA);
    std::vector<PixelRecord> records;
    RenderOptions options;
    options.records = &records;
    render_image(prepare_render_scene(scene), options);
    write_reference_trace(path, 40, 30, View::full, 1, records, "");
    fs::resize_file(path, fs::file_size(path) / 2);

    try {
        read_reference_trace(path);
        FAIL("a truncated file was read");
    } catch (const InputError& error) {
        CHECK(error.file() == path.string());
    }
}

TEST_CASE("reference trace: an image that is not one is an InputError saying so", "[app]") {
    const raystep::testing::ScratchFolder folder("reference-trace");
    const fs::path path = folder.path() / "image.trace.exr";
    write_image(raystep::testing::filled_image(2, 1, Color(0.5)), path);

    try {
        read_reference_trace(path);
        FAIL("an image was read as a reference trace");
    } catch (const InputError& error) {
        CHECK(std::string(error.what()).find("image.trace.exr: not a raystep reference trace") !=
              std::string::npos);
    }
}

TEST_CASE("reference trace: a missing file is an InputError naming it", "[app]") {
    CHECK_THROWS_AS(read_reference_trace("no/such/file.trace.exr"), InputError);
}
