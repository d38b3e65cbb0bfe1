// Stage 11 checks: interpolation, the tangent frame, texture lookup and the perturbed normals,
// each function against the long-double oracle (grading/11_surface_detail/surface_detail_oracle.h)
// on hand-worked cases (public), on the contract's edges (hidden: a vertex's own normal,
// opposing normals, near the poles and either side of the seam, uvs with no area, dp/du along the
// normal, negative and far texel indices, v = 0 and 1, a one-texel image, the grey texel,
// parallel derivatives) and on seeded random ones, each of the contract's four parts an oracle
// check of its own. Every case is judged by a data judge, so the public ones go into
// the student release as data and the others are judged by the same code. The renders that show
// each map are render checks (grader/grade/checks/render_checks.cpp).

#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

#include "app/grade/value_judges.h"
#include "app/grade/value_text.h"
#include "base/math/portable_random.h"
#include "grader/grade/checks/case_text.h"
#include "grader/grade/checks/cpp_literal.h"
#include "grader/grade/checks/data_judged.h"
#include "grader/grade/checks/judging.h"
#include "grader/grade/checks/stage_checks.h"
#include "grading/11_surface_detail/surface_detail_calls.h"
#include "grading/11_surface_detail/surface_detail_judges.h"
#include "grading/11_surface_detail/surface_detail_oracle.h"

namespace raystep::grade {

namespace {

constexpr const char* kPublicName =
    "interpolation, the tangent frame, texture lookup and perturbed normals on hand-worked cases";

// --- How a case reads, and how a student reruns it

std::string cpp(const Vec2& v) {
    return "Vec2{" + grade::cpp(v.x) + ", " + grade::cpp(v.y) + "}";
}

std::string wrap_name(WrapMode wrap) {
    return probe::JsonCodec<WrapMode>::write(wrap).get<std::string>();
}

std::string cpp(WrapMode wrap) {
    return "WrapMode::" + wrap_name(wrap);
}

std::string cpp(const SurfaceDerivatives& d) {
    return "SurfaceDerivatives{" + grade::cpp(d.dpdu) + ", " + grade::cpp(d.dpdv) + "}";
}

std::string cpp(const TangentFrame& f) {
    return "TangentFrame{" + grade::cpp(f.tangent) + ", " + grade::cpp(f.bitangent) + ", " +
           grade::cpp(f.normal) + "}";
}

// An image as its texels, row by row from the top: "2 x 1 [(1, 0, 0) (0, 1, 0)]".
std::string image_text(const Image& image) {
    std::string text =
        std::to_string(image.width()) + " x " + std::to_string(image.height()) + " [";
    for (int j = 0; j < image.height(); ++j) {
        for (int i = 0; i < image.width(); ++i)
            text += (i + j == 0 ? "" : " ") + full_text(image.at(i, j));
    }
    return text + "]";
}

// An image as a C++ expression that builds it.
std::string image_code(const Image& image) {
    std::string code = "[] { Image t(" + std::to_string(image.width()) + ", " +
                       std::to_string(image.height()) + ");";
    for (int j = 0; j < image.height(); ++j) {
        for (int i = 0; i < image.width(); ++i) {
            code += " t.set(" + std::to_string(i) + ", " + std::to_string(j) + ", " +
                    grade::cpp(image.at(i, j)) + ");";
        }
    }
    return code + " return t; }()";
}

std::string frame_text(const TangentFrame& f) {
    return "frame T " + full_text(f.tangent) + " B " + full_text(f.bitangent) + " N " +
           full_text(f.normal);
}

std::string derivatives_text(const SurfaceDerivatives& d) {
    return "dp/du " + full_text(d.dpdu) + ", dp/dv " + full_text(d.dpdv);
}

// An image from its texels, row by row from the top.
Image image_of(int width, int height, const std::vector<Color>& texels) {
    Image image(width, height);
    for (int j = 0; j < height; ++j) {
        for (int i = 0; i < width; ++i)
            image.set(i, j, texels[static_cast<std::size_t>(j * width + i)]);
    }
    return image;
}

// --- One call, one case

PublicCase interpolate_normal_case(const Vec3& n0, const Vec3& n1, const Vec3& n2, double beta,
                                   double gamma) {
    const auto e = expected_interpolate_normal(n0, n1, n2, beta, gamma);
    return {"interpolate_normal(" + vectors_text({n0, n1, n2}) + ", beta " + full_text(beta) +
                ", gamma " + full_text(gamma) + ")",
            probe::query(probe::interpolate_normal_call, {n0, n1, n2, beta, gamma}),
            e ? near_vec3_judge(e->value, e->tolerance) : threw_judge("domain_error"),
            "interpolate_normal(" + grade::cpp(n0) + ", " + grade::cpp(n1) + ", " + grade::cpp(n2) +
                ", " + grade::cpp(beta) + ", " + grade::cpp(gamma) + ")"};
}

PublicCase interpolate_uv_case(const Vec2& uv0, const Vec2& uv1, const Vec2& uv2, double beta,
                               double gamma) {
    const Expected<Vec2> e = expected_interpolate_uv(uv0, uv1, uv2, beta, gamma);
    return {"interpolate_uv(" + full_text(uv0) + ", " + full_text(uv1) + ", " + full_text(uv2) +
                ", beta " + full_text(beta) + ", gamma " + full_text(gamma) + ")",
            probe::query(probe::interpolate_uv_call, {uv0, uv1, uv2, beta, gamma}),
            near_vec2_judge(e.value, e.tolerance),
            "interpolate_uv(" + cpp(uv0) + ", " + cpp(uv1) + ", " + cpp(uv2) + ", " +
                grade::cpp(beta) + ", " + grade::cpp(gamma) + ")"};
}

PublicCase sphere_uv_case(const Vec3& normal) {
    const Expected<Vec2> e = expected_sphere_uv(normal);
    return {"sphere_uv(" + full_text(normal) + ")", probe::query(probe::sphere_uv_call, {normal}),
            near_vec2_judge(e.value, e.tolerance), "sphere_uv(" + grade::cpp(normal) + ")"};
}

PublicCase surface_derivatives_case(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec2& uv0,
                                    const Vec2& uv1, const Vec2& uv2) {
    const auto e = expected_surface_derivatives(p0, p1, p2, uv0, uv1, uv2);
    return {"surface_derivatives(" + vectors_text({p0, p1, p2}) + ", uvs " + full_text(uv0) + ", " +
                full_text(uv1) + ", " + full_text(uv2) + ")",
            probe::query(probe::surface_derivatives_call, {p0, p1, p2, uv0, uv1, uv2}),
            surface_derivatives_judge(e.value, e.tolerance),
            "surface_derivatives(" + grade::cpp(p0) + ", " + grade::cpp(p1) + ", " +
                grade::cpp(p2) + ", " + cpp(uv0) + ", " + cpp(uv1) + ", " + cpp(uv2) + ")"};
}

PublicCase tangent_frame_case(const SurfaceDerivatives& d, const Vec3& normal) {
    const auto e = expected_tangent_frame(d, normal);
    return {"tangent_frame(" + derivatives_text(d) + ", normal " + full_text(normal) + ")",
            probe::query(probe::tangent_frame_call, {d, normal}),
            tangent_frame_judge(e.value, e.tolerance),
            "tangent_frame(" + cpp(d) + ", " + grade::cpp(normal) + ")"};
}

PublicCase wrap_texel_case(int i, int size, WrapMode wrap) {
    return {
        "wrap_texel(" + std::to_string(i) + ", size " + std::to_string(size) + ", " +
            wrap_name(wrap) + ")",
        probe::query(probe::wrap_texel_call, {i, size, wrap}),
        near_number_judge(expected_wrap_texel(i, size, wrap), 0.0),
        "wrap_texel(" + std::to_string(i) + ", " + std::to_string(size) + ", " + cpp(wrap) + ")"};
}

// A lookup's case, nearest or bilinear by `call` and `e`.
template <class Call>
PublicCase lookup_case(const Call& call, const Expected<Color>& e, const Image& image,
                       const Vec2& uv, WrapMode wrap) {
    const std::string name = call.name;
    return {name + "(image " + image_text(image) + ", uv " + full_text(uv) + ", " +
                wrap_name(wrap) + ")",
            probe::query(call, {image, uv, wrap}), near_vec3_judge(e.value, e.tolerance),
            name + "(" + image_code(image) + ", " + cpp(uv) + ", " + cpp(wrap) + ")"};
}

PublicCase nearest_case(const Image& image, const Vec2& uv, WrapMode wrap) {
    return lookup_case(probe::texture_nearest_call, expected_texture_nearest(image, uv, wrap),
                       image, uv, wrap);
}

PublicCase bilinear_case(const Image& image, const Vec2& uv, WrapMode wrap) {
    return lookup_case(probe::texture_bilinear_call, expected_texture_bilinear(image, uv, wrap),
                       image, uv, wrap);
}

PublicCase normal_from_map_case(const TangentFrame& frame, const Color& texel) {
    const auto e = expected_normal_from_map(frame, texel);
    return {"normal_from_map(" + frame_text(frame) + ", texel " + full_text(texel) + ")",
            probe::query(probe::normal_from_map_call, {frame, texel}),
            e ? near_vec3_judge(e->value, e->tolerance) : threw_judge("domain_error"),
            "normal_from_map(" + cpp(frame) + ", " + grade::cpp(texel) + ")"};
}

PublicCase height_slopes_case(const Image& map, const Vec2& uv, WrapMode wrap, double scale) {
    const Expected<Vec2> e = expected_height_slopes(map, uv, wrap, scale);
    return {"height_slopes(image " + image_text(map) + ", uv " + full_text(uv) + ", " +
                wrap_name(wrap) + ", scale " + full_text(scale) + ")",
            probe::query(probe::height_slopes_call, {map, uv, wrap, scale}),
            near_vec2_judge(e.value, e.tolerance),
            "height_slopes(" + image_code(map) + ", " + cpp(uv) + ", " + cpp(wrap) + ", " +
                grade::cpp(scale) + ")"};
}

PublicCase bump_normal_case(const SurfaceDerivatives& d, const Vec3& normal, const Vec2& slopes) {
    const auto e = expected_bump_normal(d, normal, slopes);
    return {"bump_normal(" + derivatives_text(d) + ", normal " + full_text(normal) + ", slopes " +
                full_text(slopes) + ")",
            probe::query(probe::bump_normal_call, {d, normal, slopes}),
            e ? near_vec3_judge(e->value, e->tolerance) : threw_judge("domain_error"),
            "bump_normal(" + cpp(d) + ", " + grade::cpp(normal) + ", " + cpp(slopes) + ")"};
}

// --- The cases' textures: every texel a colour of its own, so that a texel read from the wrong
// column, the wrong row or the wrong end shows.

const Color kRed{1, 0, 0};
const Color kGreen{0, 1, 0};
const Color kBlue{0, 0, 1};
const Color kWhite{1, 1, 1};

// 2 x 2: red and green on the top row, blue and white below.
Image quad_image() {
    return image_of(2, 2, {kRed, kGreen, kBlue, kWhite});
}

// 3 x 2, no two texels alike and no symmetry.
Image strip_image() {
    return image_of(3, 2,
                    {{0.1, 0.2, 0.3},
                     {0.4, 0.5, 0.6},
                     {0.7, 0.8, 0.9},
                     {0.9, 0.1, 0.5},
                     {0.3, 0.7, 0.2},
                     {0.6, 0.0, 1.0}});
}

// A height ramp 4 texels wide, grey, rising left to right.
Image ramp_image() {
    return image_of(4, 1, {Color(0.0), Color(0.25), Color(0.75), Color(1.0)});
}

// A height map 3 x 3 with a peak in the middle.
Image peak_image() {
    return image_of(3, 3,
                    {Color(0.0), Color(0.2), Color(0.0), Color(0.4), Color(1.0), Color(0.1),
                     Color(0.0), Color(0.6), Color(0.0)});
}

const Vec3 kX{1, 0, 0};
const Vec3 kY{0, 1, 0};
const Vec3 kZ{0, 0, 1};
const TangentFrame kFlatFrame{kX, kY, kZ};
// A frame whose tangent is -z and normal +x: a texel read in the wrong space points elsewhere.
const TangentFrame kTurnedFrame{{0, 0, -1}, kY, kX};

std::vector<PublicCase> public_cases() {
    const double third = 1.0 / 3.0;
    return {
        interpolate_normal_case(kZ, kX, kY, 0.25, 0.5),
        interpolate_normal_case(kZ, {0, 2, 0}, kX, 1.0, 0.0),
        interpolate_normal_case({0, 0, 2}, kX, kY, third, third),
        interpolate_uv_case({0, 0}, {1, 0}, {0, 1}, 0.25, 0.5),
        interpolate_uv_case({0.5, 1}, {2, 0}, {-1, 3}, 0.125, 0.625),
        sphere_uv_case(kZ),
        sphere_uv_case(kX),
        sphere_uv_case(glm::normalize(Vec3{-1, 1, 0})),
        surface_derivatives_case({0, 0, 0}, {2, 0, 0}, {0, 3, 0}, {0, 0}, {1, 0}, {0, 1}),
        surface_derivatives_case({0, 0, 0}, {1, 0, 1}, {0, 1, 0}, {0, 0}, {1, 0.5}, {0, 1}),
        surface_derivatives_case({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0}, {1, 1}, {2, 2}),
        tangent_frame_case({{1, 0, 0.5}, {0, 1, 0}}, kZ),
        tangent_frame_case({{2, 0, 0}, {0, -1, 0}}, kZ),
        tangent_frame_case({{0, 0, 3}, {0, 1, 0}}, kZ),
        wrap_texel_case(-1, 4, WrapMode::repeat),
        wrap_texel_case(7, 4, WrapMode::clamp),
        wrap_texel_case(4, 4, WrapMode::mirror),
        wrap_texel_case(-1, 4, WrapMode::mirror),
        nearest_case(quad_image(), {0.25, 0.75}, WrapMode::repeat),
        nearest_case(quad_image(), {0.75, 0.25}, WrapMode::repeat),
        nearest_case(quad_image(), {1.25, -0.25}, WrapMode::repeat),
        nearest_case(quad_image(), {-0.5, 1.5}, WrapMode::clamp),
        bilinear_case(quad_image(), {0.25, 0.75}, WrapMode::repeat),
        bilinear_case(quad_image(), {0.5, 0.5}, WrapMode::repeat),
        bilinear_case(quad_image(), {0.0, 0.75}, WrapMode::repeat),
        bilinear_case(quad_image(), {0.0, 0.75}, WrapMode::clamp),
        normal_from_map_case(kFlatFrame, {0.5, 0.5, 1.0}),
        normal_from_map_case(kTurnedFrame, {1.0, 0.5, 0.5}),
        normal_from_map_case(kTurnedFrame, {0.75, 0.25, 1.0}),
        height_slopes_case(ramp_image(), {0.5, 0.5}, WrapMode::repeat, 1.0),
        height_slopes_case(ramp_image(), {0.375, 0.5}, WrapMode::clamp, 0.1),
        bump_normal_case({kX, kY}, kZ, {0.5, 0.0}),
        bump_normal_case({kX, {0, -1, 0}}, kZ, {0.0, 0.25}),
    };
}

std::vector<PublicCase> hidden_cases() {
    const Vec3 tilted = glm::normalize(Vec3{1, 2, 3});
    const Vec3 north = glm::normalize(Vec3{1e-9, 1, 0});
    const Vec3 south = glm::normalize(Vec3{0, -1, 3e-10});
    const Image one = image_of(1, 1, {{0.2, 0.4, 0.8}});
    return {
        // Interpolation: each vertex's own normal, normals that cancel, weights outside the
        // triangle, far uvs
        interpolate_normal_case(kX, kY, kZ, 0.0, 0.0),
        interpolate_normal_case(kX, kY, kZ, 0.0, 1.0),
        interpolate_normal_case(kX, -kX, kY, 0.5, 0.0),
        interpolate_normal_case({0, 0, 1e-3}, {5, 0, 0}, kY, 0.5, 0.25),
        interpolate_normal_case(tilted, kX, -kZ, 1.5, -0.25),
        interpolate_uv_case({1000.5, -999.25}, {1001, -999}, {1000, -998}, 0.3, 0.6),
        interpolate_uv_case({0, 0}, {1, 0}, {0, 1}, 1.0, 0.0),
        // Sphere uvs: near each pole (where acos loses the angle), either side of the seam, the
        // axes
        sphere_uv_case(north),
        sphere_uv_case(south),
        sphere_uv_case({-1e-12, 0, -1}),
        sphere_uv_case({1e-12, 0, -1}),
        sphere_uv_case(-kX),
        sphere_uv_case(tilted),
        // The derivatives: uvs mirrored, sheared, far from the origin, of no area; a far, small
        // triangle
        surface_derivatives_case({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0}, {-1, 0}, {0, 1}),
        surface_derivatives_case({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0}, {0, 1}, {1, 0}),
        surface_derivatives_case({1, 2, 3}, {2, 2, 3}, {1, 3, 4}, {500.25, 500}, {500.75, 500},
                                 {500.25, 500.5}),
        surface_derivatives_case({1e4, 1e4, 0}, {1e4 + 1e-3, 1e4, 0}, {1e4, 1e4 + 2e-3, 0}, {0, 0},
                                 {1, 0}, {0, 1}),
        surface_derivatives_case({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.5, 0.5}, {0.5, 0.5}, {1, 0}),
        // The frame: dp/du nearly along the normal, mirrored, zero; a normal off the axes
        tangent_frame_case({{1e-3, 0, 1}, {0, 1, 0}}, kZ),
        tangent_frame_case({{1, 1, 1}, {-1, 1, 0}}, tilted),
        tangent_frame_case({{0, 0, 0}, {0, 1, 0}}, kZ),
        tangent_frame_case({{3, 0, 0}, {1, -1, 1}}, kZ),
        // Wrapping: negative and far indices, one texel, both ends of each mode's period
        wrap_texel_case(-5, 4, WrapMode::repeat),
        wrap_texel_case(-8, 4, WrapMode::repeat),
        wrap_texel_case(1000000000, 7, WrapMode::repeat),
        wrap_texel_case(-1000000000, 7, WrapMode::repeat),
        wrap_texel_case(-3, 4, WrapMode::clamp),
        wrap_texel_case(3, 1, WrapMode::clamp),
        wrap_texel_case(-1, 1, WrapMode::mirror),
        wrap_texel_case(7, 4, WrapMode::mirror),
        wrap_texel_case(8, 4, WrapMode::mirror),
        wrap_texel_case(-8, 4, WrapMode::mirror),
        wrap_texel_case(-9, 4, WrapMode::mirror),
        wrap_texel_case(-1000000001, 3, WrapMode::mirror),
        wrap_texel_case(5, 1, WrapMode::repeat),
        // Nearest: u and v at 0 and 1 where each mode reads one texel either side of the edge
        // (under repeat, floor's texel and the edge's other one differ: the oracle refuses),
        // far uvs, one texel
        nearest_case(strip_image(), {0, 0}, WrapMode::clamp),
        nearest_case(strip_image(), {1, 1}, WrapMode::clamp),
        nearest_case(strip_image(), {1, 1}, WrapMode::mirror),
        nearest_case(strip_image(), {-0.1, 1.3}, WrapMode::mirror),
        nearest_case(strip_image(), {999.9, -999.3}, WrapMode::repeat),
        nearest_case(one, {-3.7, 12.1}, WrapMode::mirror),
        // Bilinear: at a texel's centre, between two across the wrap, mirrored at an edge,
        // far, one texel
        bilinear_case(strip_image(), {0.5, 0.25}, WrapMode::repeat),
        bilinear_case(strip_image(), {1.0, 0.5}, WrapMode::repeat),
        bilinear_case(strip_image(), {1.0, 0.5}, WrapMode::clamp),
        bilinear_case(strip_image(), {1.0, 0.5}, WrapMode::mirror),
        bilinear_case(strip_image(), {-0.05, 0.9}, WrapMode::mirror),
        bilinear_case(strip_image(), {0.1, 1.1}, WrapMode::repeat),
        bilinear_case(strip_image(), {-500.4, 250.65}, WrapMode::repeat),
        bilinear_case(one, {0.3, -7.9}, WrapMode::clamp),
        // Normal maps: the grey texel, the black one, a frame off the axes
        normal_from_map_case(kFlatFrame, {0.5, 0.5, 0.5}),
        normal_from_map_case(kTurnedFrame, {0, 0, 0}),
        normal_from_map_case(kTurnedFrame, {0.5, 1.0, 0.5}),
        normal_from_map_case({glm::normalize(Vec3{1, -1, 0}), glm::normalize(Vec3{1, 1, -1}),
                              glm::normalize(Vec3{1, 1, 2})},
                             {0.6, 0.45, 0.9}),
        // Height slopes: a peak, at the map's edge in each mode, one texel, a negative scale
        height_slopes_case(peak_image(), {0.5, 0.5}, WrapMode::clamp, 1.0),
        height_slopes_case(peak_image(), {0.4, 0.6}, WrapMode::repeat, 2.0),
        height_slopes_case(ramp_image(), {0.05, 0.5}, WrapMode::repeat, 1.0),
        height_slopes_case(ramp_image(), {0.05, 0.5}, WrapMode::clamp, 1.0),
        height_slopes_case(ramp_image(), {0.95, 0.5}, WrapMode::mirror, 1.0),
        height_slopes_case(one, {0.3, 0.7}, WrapMode::repeat, 5.0),
        height_slopes_case(peak_image(), {0.6, 0.3}, WrapMode::clamp, -0.5),
        // Bumps: no slope, steep slopes, parallel derivatives, a tilted surface
        bump_normal_case({kX, kY}, kZ, {0, 0}),
        bump_normal_case({kX, kY}, kZ, {100, -50}),
        bump_normal_case({kX, {2, 0, 0}}, kZ, {0, 0}),
        bump_normal_case({{0.5, 0, 0}, {0, 0, -2}}, kY, {0.3, 0.4}),
        bump_normal_case({{1, 1, 0}, {0, 1, 1}}, glm::normalize(Vec3{1, -1, 1}), {-0.2, 0.7}),
    };
}

// --- Generated cases

constexpr std::uint64_t kOracleSeed = 11211;

WrapMode random_wrap(PortableRandom& random) {
    const WrapMode modes[] = {WrapMode::repeat, WrapMode::clamp, WrapMode::mirror};
    return modes[random.integer(0, 2)];
}

Vec2 random_uv(PortableRandom& random, double reach) {
    return {random.uniform(-reach, reach), random.uniform(-reach, reach)};
}

// Barycentrics inside the triangle, now and then outside it.
Vec2 random_barycentrics(PortableRandom& random) {
    const double beta = random.unit();
    const double gamma = random.unit() * (1 - beta);
    if (random.unit() < 0.2) return {beta * 2 - 0.5, gamma * 2 - 0.5};
    return {beta, gamma};
}

Image random_image(PortableRandom& random) {
    const int width = static_cast<int>(random.integer(1, 6));
    const int height = static_cast<int>(random.integer(1, 6));
    Image image(width, height);
    for (int j = 0; j < height; ++j) {
        for (int i = 0; i < width; ++i)
            image.set(i, j, {random.unit(), random.unit(), random.unit()});
    }
    return image;
}

// A unit normal and derivatives across it, now and then leaning towards it.
SurfaceDerivatives random_derivatives(PortableRandom& random, const Vec3& normal) {
    const double scale = random.decade(-2, 2);
    return {scale * (random.unit_vector() + random.uniform(0, 2) * normal),
            scale * random.decade(-1, 1) * random.unit_vector()};
}

// Each generator redraws until its case is clear of the oracle's ill-conditioned places
// (surface_detail_oracle.h). A generator that draws a hundred such cases in a row is broken.
template <class Make>
PublicCase clear_case(Make make) {
    for (int draw = 0; draw < 100; ++draw) {
        try {
            return make();
        } catch (const IllConditioned&) {
        }
    }
    throw std::logic_error("a case generator of stage 11 draws only ill-conditioned cases");
}

PublicCase random_normal_case(PortableRandom& random, int) {
    return clear_case([&] {
        const double size = random.decade(-3, 3);
        const Vec2 b = random_barycentrics(random);
        return interpolate_normal_case(size * random.unit_vector(),
                                       size * random.decade(-1, 1) * random.unit_vector(),
                                       size * random.unit_vector(), b.x, b.y);
    });
}

PublicCase random_uv_case(PortableRandom& random, int) {
    const double reach = random.decade(0, 3);
    const Vec2 b = random_barycentrics(random);
    return interpolate_uv_case(random_uv(random, reach), random_uv(random, reach),
                               random_uv(random, reach), b.x, b.y);
}

PublicCase random_sphere_uv_case(PortableRandom& random, int) {
    return clear_case([&] { return sphere_uv_case(random.unit_vector()); });
}

PublicCase random_derivatives_case(PortableRandom& random, int) {
    return clear_case([&] {
        const Vec3 origin = random.unit_vector() * random.decade(-1, 3);
        const double size = random.decade(-2, 1);
        const Vec2 uv0 = random_uv(random, random.decade(0, 2));
        return surface_derivatives_case(origin, origin + size * random.unit_vector(),
                                        origin + size * random.unit_vector(), uv0,
                                        uv0 + random_uv(random, 1), uv0 + random_uv(random, 1));
    });
}

PublicCase random_frame_case(PortableRandom& random, int) {
    return clear_case([&] {
        const Vec3 normal = random.unit_vector();
        return tangent_frame_case(random_derivatives(random, normal), normal);
    });
}

PublicCase random_wrap_case(PortableRandom& random, int) {
    const int size = static_cast<int>(random.integer(1, 9));
    const int reach = random.unit() < 0.5 ? 3 * size : 1000000000;
    return wrap_texel_case(static_cast<int>(random.integer(-reach, reach)), size,
                           random_wrap(random));
}

PublicCase random_texture_case(PortableRandom& random, int k) {
    return clear_case([&] {
        const Image image = random_image(random);
        const Vec2 uv = random_uv(random, random.unit() < 0.7 ? 1.5 : 1000);
        const WrapMode wrap = random_wrap(random);
        return k % 2 == 1 ? bilinear_case(image, uv, wrap) : nearest_case(image, uv, wrap);
    });
}

PublicCase random_normal_map_case(PortableRandom& random, int) {
    return clear_case([&] {
        const Vec3 normal = random.unit_vector();
        const auto frame = expected_tangent_frame(random_derivatives(random, normal), normal);
        if (!frame.value) throw IllConditioned("dp/du along the normal: no frame");
        return normal_from_map_case(*frame.value, {random.unit(), random.unit(), random.unit()});
    });
}

PublicCase random_slopes_case(PortableRandom& random, int) {
    return height_slopes_case(random_image(random), random_uv(random, 2), random_wrap(random),
                              random.uniform(-2, 2));
}

PublicCase random_bump_case(PortableRandom& random, int) {
    return clear_case([&] {
        const Vec3 normal = random.unit_vector();
        const double steep = random.decade(-2, 1);
        return bump_normal_case(random_derivatives(random, normal), normal,
                                {random.uniform(-steep, steep), random.uniform(-steep, steep)});
    });
}

// The contract's four parts, each an oracle check of its own, so that a wrong formula costs its
// part's points whole rather than a twelfth of one check (grader/rubric/rubric.json).
enum class Part { interpolation, tangent_frame, lookup, perturbed_normals };

// Each family's cases drawn from its own generators: case k of a family from
// PortableRandom(seed + family, k), so that `--case` rebuilds a case alone on any platform.
std::vector<PublicCase> generated_cases(std::uint64_t seed, int count, Part part) {
    std::vector<PublicCase> cases;
    const auto family = [&](std::uint64_t offset, int n, auto make) {
        for (int k = 0; k < n; ++k) {
            PortableRandom random(seed + offset, k);
            cases.push_back(make(random, k));
        }
    };
    switch (part) {
        case Part::interpolation:
            family(0, count, random_normal_case);
            family(1, count, random_uv_case);
            family(2, count, random_sphere_uv_case);
            break;
        case Part::tangent_frame:
            family(3, count, random_derivatives_case);
            family(4, count, random_frame_case);
            break;
        case Part::lookup:
            family(5, count, random_wrap_case);
            family(6, 2 * count, random_texture_case);
            break;
        case Part::perturbed_normals:
            family(7, count, random_normal_map_case);
            family(8, count, random_slopes_case);
            family(9, count, random_bump_case);
            break;
    }
    return cases;
}

struct OraclePart {
    Part part;
    const char* id;
    const char* name;
};

const OraclePart kOracleParts[] = {
    {Part::interpolation, "stage11.oracle.interpolation",
     "random normals, uvs and sphere uvs interpolated, against long double"},
    {Part::tangent_frame, "stage11.oracle.tangent_frame",
     "random surface derivatives and tangent frames, against long double"},
    {Part::lookup, "stage11.oracle.lookup",
     "random texel wraps and nearest and bilinear lookups, against long double"},
    {Part::perturbed_normals, "stage11.oracle.perturbed_normals",
     "random normal-map texels, height slopes and bumped normals, against long double"},
};

constexpr int kOracleCasesPerFamily = 40;
constexpr int kSampleCasesPerFamily = 3;

}  // namespace

PublicCheck stage11_public_check() {
    return {"stage11.unit", 11, "unit", kPublicName, public_cases()};
}

PublicCheck stage11_sample_check() {
    std::vector<PublicCase> cases;
    for (const OraclePart& part : kOracleParts) {
        for (PublicCase& c :
             generated_cases(kOracleSeed + kSampleSeedOffset, kSampleCasesPerFamily, part.part))
            cases.push_back(std::move(c));
    }
    return sample_check(11,
                        "random interpolations, frames, lookups and perturbed normals, against "
                        "long double",
                        std::move(cases));
}

std::vector<CheckDefinition> stage11_checks() {
    std::vector<CheckDefinition> checks = {
        case_check("stage11.unit", 11, "unit", kPublicName,
                   [] { return data_judged_cases(public_cases()); }),
        case_check("stage11.hidden", 11, "unit",
                   "a vertex's own normal, opposing normals, the poles and the seam, uvs of no "
                   "area, dp/du along the normal, far and negative texels, v at 0 and 1, the grey "
                   "texel, parallel derivatives",
                   [] { return data_judged_cases(hidden_cases()); })};
    for (const OraclePart& part : kOracleParts) {
        checks.push_back(case_check(part.id, 11, "oracle", part.name, [part] {
            return data_judged_cases(
                generated_cases(kOracleSeed, kOracleCasesPerFamily, part.part));
        }));
    }
    return checks;
}

}  // namespace raystep::grade
