// Tests of stage 11's long-double oracle (grading/11_surface_detail/surface_detail_oracle.h): the
// reference's answers in double lie within each tolerance on random cases, the contract's
// mistakes land outside it, hand-worked values, and the places where a right answer is not one
// refused.

#include <cmath>
#include <cstdint>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "base/math/portable_random.h"
#include "base/testing/catch.h"
#include "grading/11_surface_detail/surface_detail_oracle.h"
#include "stages/11_surface_detail/surface_detail.h"

using namespace raystep;
using namespace raystep::grade;

namespace {

bool within(const Vec2& got, const Expected<Vec2>& e) {
    return std::abs(got.x - e.value.x) <= e.tolerance && std::abs(got.y - e.value.y) <= e.tolerance;
}

bool within(const Vec3& got, const Vec3& expected, double tolerance) {
    return std::abs(got.x - expected.x) <= tolerance && std::abs(got.y - expected.y) <= tolerance &&
           std::abs(got.z - expected.z) <= tolerance;
}

Image random_image(PortableRandom& random) {
    Image image(static_cast<int>(random.integer(1, 6)), static_cast<int>(random.integer(1, 6)));
    for (int j = 0; j < image.height(); ++j) {
        for (int i = 0; i < image.width(); ++i)
            image.set(i, j, {random.unit(), random.unit(), random.unit()});
    }
    return image;
}

WrapMode random_wrap(PortableRandom& random) {
    const WrapMode modes[] = {WrapMode::repeat, WrapMode::clamp, WrapMode::mirror};
    return modes[random.integer(0, 2)];
}

constexpr int kRandomCases = 2000;

}  // namespace

TEST_CASE("stage 11 oracle: the reference's normals and uvs lie within the tolerances") {
    for (int k = 0; k < kRandomCases; ++k) {
        PortableRandom random(1101, static_cast<std::uint64_t>(k));
        const Vec3 n0 = random.unit_vector(), n1 = 3.0 * random.unit_vector(),
                   n2 = random.unit_vector();
        const double beta = random.unit(), gamma = random.unit() * (1 - beta);
        try {
            const auto e = expected_interpolate_normal(n0, n1, n2, beta, gamma);
            REQUIRE(e);
            CHECK(within(interpolate_normal(n0, n1, n2, beta, gamma), e->value, e->tolerance));
        } catch (const IllConditioned&) {
        }
        const Vec2 uv0{random.uniform(-9, 9), random.uniform(-9, 9)};
        const Vec2 uv1{random.uniform(-9, 9), random.uniform(-9, 9)};
        const Vec2 uv2{random.uniform(-9, 9), random.uniform(-9, 9)};
        CHECK(within(interpolate_uv(uv0, uv1, uv2, beta, gamma),
                     expected_interpolate_uv(uv0, uv1, uv2, beta, gamma)));
        const Vec3 n = random.unit_vector();
        CHECK(within(sphere_uv(n), expected_sphere_uv(n)));
    }
}

TEST_CASE("stage 11 oracle: the reference's derivatives and frames lie within the tolerances") {
    int frames = 0;
    for (int k = 0; k < kRandomCases; ++k) {
        PortableRandom random(1102, static_cast<std::uint64_t>(k));
        const Vec3 p0 = 100.0 * random.unit_vector();
        const Vec3 p1 = p0 + random.unit_vector(), p2 = p0 + random.unit_vector();
        const Vec2 uv0{random.uniform(-5, 5), random.uniform(-5, 5)};
        const Vec2 uv1 = uv0 + Vec2{random.uniform(-1, 1), random.uniform(-1, 1)};
        const Vec2 uv2 = uv0 + Vec2{random.uniform(-1, 1), random.uniform(-1, 1)};
        try {
            const auto e = expected_surface_derivatives(p0, p1, p2, uv0, uv1, uv2);
            const auto got = surface_derivatives(p0, p1, p2, uv0, uv1, uv2);
            REQUIRE(got.has_value() == e.value.has_value());
            if (!got) continue;
            CHECK(within(got->dpdu, e.value->dpdu, e.tolerance));
            CHECK(within(got->dpdv, e.value->dpdv, e.tolerance));
            // A shading normal leaning from the face's, as an interpolated one does, so that dp/du
            // leans towards it and the Gram-Schmidt step matters.
            const Vec3 n = glm::normalize(glm::normalize(glm::cross(p1 - p0, p2 - p0)) +
                                          0.5 * random.unit_vector());
            const auto frame = expected_tangent_frame(*got, n);
            const auto got_frame = tangent_frame(*got, n);
            REQUIRE(got_frame.has_value() == frame.value.has_value());
            if (!got_frame) continue;
            CHECK(within(got_frame->tangent, frame.value->tangent, frame.tolerance));
            CHECK(within(got_frame->bitangent, frame.value->bitangent, frame.tolerance));
            ++frames;
        } catch (const IllConditioned&) {
        }
    }
    CHECK(frames > kRandomCases * 9 / 10);
}

TEST_CASE("stage 11 oracle: the reference's lookups and perturbed normals lie within tolerance") {
    for (int k = 0; k < kRandomCases; ++k) {
        PortableRandom random(1103, static_cast<std::uint64_t>(k));
        const Image image = random_image(random);
        const WrapMode wrap = random_wrap(random);
        const double reach = k % 4 == 0 ? 1000 : 2;
        const Vec2 uv{random.uniform(-reach, reach), random.uniform(-reach, reach)};
        const auto bilinear = expected_texture_bilinear(image, uv, wrap);
        CHECK(within(texture_bilinear(image, uv, wrap), bilinear.value, bilinear.tolerance));
        try {
            const auto nearest = expected_texture_nearest(image, uv, wrap);
            CHECK(texture_nearest(image, uv, wrap) == nearest.value);
        } catch (const IllConditioned&) {
        }
        const double scale = random.uniform(-2, 2);
        CHECK(within(height_slopes(image, uv, wrap, scale),
                     expected_height_slopes(image, uv, wrap, scale)));
        const Vec3 n = random.unit_vector();
        const int i = static_cast<int>(random.integer(-2000000000, 2000000000));
        const int size = static_cast<int>(random.integer(1, 1000000));
        CHECK(wrap_texel(i, size, wrap) == expected_wrap_texel(i, size, wrap));
        const Color texel{random.unit(), random.unit(), random.unit()};
        const TangentFrame frame{glm::normalize(Vec3{1, 2, -1}), glm::normalize(Vec3{1, 0, 1}),
                                 glm::normalize(Vec3{1, -1, -1})};
        try {
            const auto mapped = expected_normal_from_map(frame, texel);
            REQUIRE(mapped);
            CHECK(within(normal_from_map(frame, texel), mapped->value, mapped->tolerance));
        } catch (const IllConditioned&) {
        }
        const SurfaceDerivatives d{random.unit_vector(), random.unit_vector()};
        const Vec2 slopes{random.uniform(-3, 3), random.uniform(-3, 3)};
        try {
            const auto bumped = expected_bump_normal(d, n, slopes);
            REQUIRE(bumped);
            CHECK(within(bump_normal(d, n, slopes), bumped->value, bumped->tolerance));
        } catch (const IllConditioned&) {
        }
    }
}

TEST_CASE("stage 11 oracle: the contract's mistakes land outside the tolerances") {
    // Barycentrics swapped.
    const Vec3 x{1, 0, 0}, y{0, 1, 0}, z{0, 0, 1};
    const auto normal = expected_interpolate_normal(z, x, y, 0.25, 0.5);
    REQUIRE(normal);
    CHECK_FALSE(within(interpolate_normal(z, y, x, 0.25, 0.5), normal->value, normal->tolerance));
    // theta by acos near the north pole, where n.y rounds to 1: v off by 3e-10.
    const Vec3 north = glm::normalize(Vec3{1e-9, 1, 0});
    const Expected<Vec2> pole = expected_sphere_uv(north);
    CHECK(std::abs(1.0 - std::acos(north.y) / 3.141592653589793 - pole.value.y) > pole.tolerance);
    // dp/du taken as the tangent without the Gram-Schmidt step.
    const SurfaceDerivatives leaning{{1, 0, 0.5}, {0, 1, 0}};
    const auto frame = expected_tangent_frame(leaning, z);
    REQUIRE(frame.value);
    CHECK_FALSE(within(glm::normalize(leaning.dpdu), frame.value->tangent, frame.tolerance));
    // v read from the top: a 1 x 2 image's lower texel at v = 0.25.
    Image column(1, 2);
    column.set(0, 0, {1, 0, 0});
    column.set(0, 1, {0, 0, 1});
    CHECK(expected_texture_nearest(column, {0.5, 0.25}, WrapMode::clamp).value == Color{0, 0, 1});
    CHECK(expected_texture_bilinear(column, {0.5, 0.25}, WrapMode::clamp).value == Color{0, 0, 1});
}

TEST_CASE("stage 11 oracle: wrap_texel by hand in each mode") {
    CHECK(expected_wrap_texel(-1, 4, WrapMode::repeat) == 3);
    CHECK(expected_wrap_texel(-8, 4, WrapMode::repeat) == 0);
    CHECK(expected_wrap_texel(1000000000, 7, WrapMode::repeat) == 1000000000 % 7);
    CHECK(expected_wrap_texel(-3, 4, WrapMode::clamp) == 0);
    CHECK(expected_wrap_texel(9, 4, WrapMode::clamp) == 3);
    // Mirror, period 8: i = -8 to -1 and i = 0 to 7 each read 0 1 2 3 3 2 1 0.
    CHECK(expected_wrap_texel(4, 4, WrapMode::mirror) == 3);
    CHECK(expected_wrap_texel(7, 4, WrapMode::mirror) == 0);
    CHECK(expected_wrap_texel(8, 4, WrapMode::mirror) == 0);
    CHECK(expected_wrap_texel(-1, 4, WrapMode::mirror) == 0);
    CHECK(expected_wrap_texel(-5, 4, WrapMode::mirror) == 3);
    CHECK(expected_wrap_texel(-9, 4, WrapMode::mirror) == 0);
    CHECK(expected_wrap_texel(-10, 4, WrapMode::mirror) == 1);
}

TEST_CASE("stage 11 oracle: where a right answer is not one, the case is refused") {
    CHECK_THROWS_AS(expected_sphere_uv({0, 1, 0}), IllConditioned);
    CHECK_THROWS_AS(expected_sphere_uv({0, 0, -1}), IllConditioned);
    Image two(2, 1);
    two.set(1, 0, {1, 1, 1});
    CHECK_THROWS_AS(expected_texture_nearest(two, {0.5 + 1e-13, 0.5}, WrapMode::repeat),
                    IllConditioned);
    // u = 1 exactly: floor reads column 2, column 0 under repeat, where the right edge's own
    // texel is column 1; under clamp both read column 1.
    CHECK_THROWS_AS(expected_texture_nearest(two, {1.0, 0.5}, WrapMode::repeat), IllConditioned);
    CHECK(expected_texture_nearest(two, {1.0, 0.5}, WrapMode::clamp).value == Color{1, 1, 1});
    CHECK_THROWS_AS(expected_tangent_frame({{1, 0, 0}, {1, 0, 1}}, {0, 0, 1}), IllConditioned);
    // Exact zeros are the contract's answers, not refusals.
    CHECK_FALSE(expected_interpolate_normal({1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, 0.5, 0.0));
    CHECK_FALSE(
        expected_surface_derivatives({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0}, {1, 1}, {2, 2})
            .value);
    CHECK_FALSE(expected_tangent_frame({{0, 0, 3}, {0, 1, 0}}, {0, 0, 1}).value);
}
