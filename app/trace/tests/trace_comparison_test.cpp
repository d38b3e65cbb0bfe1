#include "app/trace/trace_comparison.h"

#include <cmath>

#include "app/compare/reference_trace.h"
#include "base/testing/catch.h"

using namespace raystep;

namespace {

PixelRecord shaded_hit() {
    PixelRecord record;
    record.camera_ray = Ray{Vec3(0.0, 0.0, 4.0), Vec3(0.6, 0.0, -0.8)};
    record.hit_searched = true;
    record.hit = PrimitiveHit{Hit{4.5, Vec3(0.0, 0.0, 1.0)}, PrimitiveKind::sphere, 1};
    record.lights = {{LightReach::reaches, Color(0.5)}};
    record.local = Color(0.6);
    record.full = Color(0.6);
    return record;
}

const std::vector<std::string> kOneLight = {"point light (line 7)"};

}  // namespace

TEST_CASE("compare_pixel: the same record is the same at every step of the view", "[app]") {
    const TraceComparison comparison =
        compare_pixel(shaded_hit(), shaded_hit(), View::full, kOneLight);
    CHECK_FALSE(comparison.first_difference);
    CHECK_FALSE(comparison.stopped);
    REQUIRE(comparison.rows.size() == 10);
    CHECK(comparison.rows[2].quantity == "the hit primitive");
    CHECK(comparison.rows[2].ours == "sphere 1");
    CHECK(comparison.rows[7].quantity == "point light (line 7): term");
    CHECK(comparison.rows[9].quantity == "the full colour");
}

TEST_CASE("compare_pixel: names the first quantity that differs, in pipeline order", "[app]") {
    PixelRecord ours = shaded_hit();
    ours.hit->hit.t = 4.25;
    ours.local = Color(0.1);
    const TraceComparison comparison = compare_pixel(ours, shaded_hit(), View::full, kOneLight);
    REQUIRE(comparison.first_difference);
    const TraceRow& row = comparison.rows[*comparison.first_difference];
    CHECK(row.quantity == "the hit's t");
    CHECK(row.ours == "4.25");
    CHECK(row.reference == "4.5");
}

TEST_CASE("compare_pixel: a difference within the stored rounding is none, beyond it is one",
          "[app]") {
    const double inside = 0.5 * stored_roundoff(TraceQuantity::t);
    const double outside = 4.0 * stored_roundoff(TraceQuantity::t);
    PixelRecord near = shaded_hit();
    near.hit->hit.t = 4.5 * (1.0 + inside);
    CHECK_FALSE(compare_pixel(near, shaded_hit(), View::depth, kOneLight).first_difference);
    PixelRecord far = shaded_hit();
    far.hit->hit.t = 4.5 * (1.0 + outside);
    CHECK(compare_pixel(far, shaded_hit(), View::depth, kOneLight).first_difference == 3u);
}

TEST_CASE("compare_pixel: the same value prints as the student wrote it, not as stored", "[app]") {
    // 3.6 and 5.6 keep 12 bits in a reference trace: 3.60010 and 5.59961. A student whose camera
    // is at (0, 3.6, 5.6) reads 3.6 and 5.6 on both sides, not a fourth digit that looks like a
    // bug.
    PixelRecord camera = shaded_hit();
    camera.camera_ray->origin = Vec3(0.0, 3.6, 5.6);
    const TraceComparison comparison = compare_pixel(camera, camera, View::rays, kOneLight);
    REQUIRE(comparison.rows.size() == 2);
    CHECK(comparison.rows[0].ours == "(0, 3.6, 5.6)");
    CHECK(comparison.rows[0].reference == "(0, 3.6, 5.6)");
}

TEST_CASE("compare_pixel: values that differ print with the digits that tell them apart", "[app]") {
    // 3.5995 and 3.6 differ by 1.4e-4 relative, beyond the 12 bits' 1.2e-4; stored, they are
    // 3.59961 and 3.60010, which at the four digits the bits carry both read 3.6.
    PixelRecord ours = shaded_hit();
    ours.camera_ray->origin = Vec3(0.0, 3.5995, 0.0);
    PixelRecord reference = shaded_hit();
    reference.camera_ray->origin = Vec3(0.0, 3.6, 0.0);
    const TraceComparison comparison = compare_pixel(ours, reference, View::rays, kOneLight);
    REQUIRE(comparison.first_difference == 0u);
    CHECK(comparison.rows[0].ours == "(0, 3.5996, 0)");
    CHECK(comparison.rows[0].reference == "(0, 3.6001, 0)");
}

TEST_CASE("compare_pixel: a component near 0 is held to its vector's precision", "[app]") {
    PixelRecord ours = shaded_hit();
    ours.camera_ray->direction.y = 1e-12;
    CHECK_FALSE(compare_pixel(ours, shaded_hit(), View::rays, kOneLight).first_difference);
}

TEST_CASE("compare_pixel: a miss against a hit differs at the primitive", "[app]") {
    PixelRecord ours = shaded_hit();
    ours.hit.reset();
    ours.lights.clear();
    ours.local.reset();
    const TraceComparison comparison = compare_pixel(ours, shaded_hit(), View::full, kOneLight);
    REQUIRE(comparison.first_difference == 2u);
    CHECK(comparison.rows[2].ours == "miss");
    CHECK(comparison.rows[3].ours == "-");
}

TEST_CASE("compare_pixel: stops at the first step this build did not reach", "[app]") {
    PixelRecord ours;
    ours.camera_ray = shaded_hit().camera_ray;
    const TraceComparison comparison = compare_pixel(ours, shaded_hit(), View::full, kOneLight);
    CHECK(comparison.stopped);
    CHECK_FALSE(comparison.first_difference);
    REQUIRE(comparison.rows.size() == 3);
    CHECK(comparison.rows[2].quantity == "the hit primitive");
    CHECK(comparison.rows[2].ours == "(not reached)");
    CHECK_FALSE(comparison.rows[2].same);
}

TEST_CASE("compare_pixel: the rays view compares the camera ray only", "[app]") {
    PixelRecord ours = shaded_hit();
    ours.hit->hit.t = 1.0;
    const TraceComparison comparison = compare_pixel(ours, shaded_hit(), View::rays, kOneLight);
    CHECK(comparison.rows.size() == 2);
    CHECK_FALSE(comparison.first_difference);
}

TEST_CASE("compare_pixel: a value is the same as itself stored, rounded twice", "[app]") {
    // Just below a tie of t's 16 stored bits at 1 + 2^-17: float32 rounding moves it onto the
    // tie, which then rounds away, a little more than half a stored step from where it was.
    PixelRecord ours = shaded_hit();
    ours.hit->hit.t = 1.0 + std::ldexp(1.0, -17) - std::ldexp(1.0, -24) + std::ldexp(1.0, -28);
    PixelRecord stored = ours;
    stored.hit->hit.t = stored_value(ours.hit->hit.t, TraceQuantity::t);
    REQUIRE(stored.hit->hit.t == 1.0 + std::ldexp(1.0, -16));
    CHECK(std::abs(stored.hit->hit.t - ours.hit->hit.t) > std::ldexp(1.0, -17) * stored.hit->hit.t);
    CHECK_FALSE(compare_pixel(ours, stored, View::depth, kOneLight).first_difference);
}

TEST_CASE("compare_pixel: with random colours it stops after the lights, whatever the colours",
          "[app]") {
    PixelRecord ours = shaded_hit();
    ours.local = Color(0.9);
    ours.full = Color(0.9);
    const TraceComparison comparison =
        compare_pixel(ours, shaded_hit(), View::full, kOneLight, true);
    CHECK_FALSE(comparison.first_difference);
    REQUIRE(comparison.rows.size() == 8);
    CHECK(comparison.rows.back().quantity == "point light (line 7): term");
    // Without it the colours are compared, and the local colour differs.
    CHECK(compare_pixel(ours, shaded_hit(), View::full, kOneLight).first_difference == 8u);
}
