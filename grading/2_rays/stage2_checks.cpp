// Stage 2 checks: Ray::at and both cameras on hand-worked values (public and hidden), and the
// rays of random cameras against the same rays computed in long double
// (grading/2_rays/camera_oracle.h).

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <string>

#include <glm/geometric.hpp>

#include "app/grade/value_judges.h"
#include "base/math/portable_random.h"
#include "base/math/unit_roundoff.h"
#include "grader/grade/checks/cpp_literal.h"
#include "grader/grade/checks/data_judged.h"
#include "grader/grade/checks/judging.h"
#include "grader/grade/checks/stage_checks.h"
#include "grading/2_rays/camera_judges.h"
#include "grading/2_rays/camera_oracle.h"
#include "grading/2_rays/ray_calls.h"

namespace raystep::grade {

namespace {

using probe::Json;

const double kInf = std::numeric_limits<double>::infinity();
const double kNaN = std::numeric_limits<double>::quiet_NaN();

CameraCase perspective(const Vec3& lookfrom, const Vec3& lookat, const Vec3& up, double fovy,
                       int width, int height) {
    CameraCase c{lookfrom, lookat, up, width, height};
    c.fovy = fovy;
    return c;
}

CameraCase orthographic(const Vec3& lookfrom, const Vec3& lookat, const Vec3& up, double left,
                        double right, double bottom, double top, int width, int height) {
    CameraCase c{lookfrom, lookat, up, width, height};
    c.orthographic = true;
    c.left = left;
    c.right = right;
    c.bottom = bottom;
    c.top = top;
    return c;
}

std::string camera_text(const CameraCase& c, int i, int j) {
    std::string text = c.orthographic ? "orthographic camera" : "perspective camera";
    text +=
        " from " + full_text(c.lookfrom) + " at " + full_text(c.lookat) + " up " + full_text(c.up);
    text += c.orthographic ? ", window [" + full_text(c.left) + ", " + full_text(c.right) +
                                 "] x [" + full_text(c.bottom) + ", " + full_text(c.top) + "]"
                           : ", fovy " + full_text(c.fovy);
    return text + ", " + std::to_string(c.width) + " x " + std::to_string(c.height) +
           " pixels, pixel (" + std::to_string(i) + ", " + std::to_string(j) + ")";
}

// The camera's rays of the pixels asked, through the call of its projection.
ProbeQuery camera_query(const CameraCase& c, const std::vector<probe::PixelIndex>& pixels) {
    if (!c.orthographic) {
        return probe::query(probe::perspective_rays_call,
                            {c.lookfrom, c.lookat, c.up, c.fovy, c.width, c.height, pixels});
    }
    return probe::query(
        probe::orthographic_rays_call,
        {c.lookfrom, c.lookat, c.up, c.left, c.right, c.bottom, c.top, c.width, c.height, pixels});
}

// The camera's maker called as a student would: make_perspective_camera(...) or
// make_orthographic_camera(...).
std::string camera_code(const CameraCase& c) {
    const std::string frame = cpp(c.lookfrom) + ", " + cpp(c.lookat) + ", " + cpp(c.up) + ", ";
    const std::string size = std::to_string(c.width) + ", " + std::to_string(c.height) + ")";
    if (!c.orthographic) return "make_perspective_camera(" + frame + cpp(c.fovy) + ", " + size;
    return "make_orthographic_camera(" + frame + cpp(c.left) + ", " + cpp(c.right) + ", " +
           cpp(c.bottom) + ", " + cpp(c.top) + ", " + size;
}

// Every case of stage 2 is judged by a data judge (grading/2_rays/camera_judges.h,
// app/grade/value_judges.h): the public ones go into the student release as data, and the others
// are judged by the same code.
PublicCase camera_ray(const CameraCase& c, int i, int j) {
    const ExpectedCameraRay e =
        c.orthographic ? expected_orthographic(c, i, j) : expected_perspective(c, i, j);
    return {camera_text(c, i, j), camera_query(c, {{i, j}}),
            camera_ray_judge(e.origin, e.origin_tolerance, e.direction, e.direction_tolerance),
            std::string(c.orthographic ? "orthographic_ray(" : "perspective_ray(") +
                camera_code(c) + ", " + std::to_string(i) + ", " + std::to_string(j) + ")"};
}

// No pixels asked: the camera's maker must throw, not the rays it would make later.
PublicCase no_camera(const CameraCase& c) {
    const ProbeQuery query = camera_query(c, {});
    const std::string text = camera_text(c, 0, 0);
    return {text.substr(0, text.rfind(", pixel")) + ": no such camera", query,
            threw_judge("domain_error"), camera_code(c)};
}

// R(t) = A + t D, within `tolerance` of `expected` per coordinate.
PublicCase ray_at(const Ray& ray, double t, const Vec3& expected, double tolerance = 0.0) {
    return {"Ray{" + ray_text(ray) + "}.at(" + full_text(t) + ")",
            probe::query(probe::ray_at_call, {ray, t}), near_vec3_judge(expected, tolerance),
            cpp(ray) + ".at(" + cpp(t) + ")"};
}

std::vector<PublicCase> public_cases() {
    // From the origin looking down -z, +y up: u = +x, v = +y, w = +z.
    const auto front = [](double fovy, int width, int height) {
        return perspective({0, 0, 0}, {0, 0, -3}, {0, 1, 0}, fovy, width, height);
    };
    // From (2, 0, 0) looking down +x with +z up: w = (-1, 0, 0), u = up x w = (0, -1, 0),
    // v = w x u = (0, 0, 1).
    const CameraCase along_x = perspective({2, 0, 0}, {7, 0, 0}, {0, 0, 1}, 60, 3, 3);
    return {
        // (1, -2, 0.5) + 1.5 (2, 0.25, -4) = (4, -1.625, -5.5); every step exact.
        ray_at({{1, -2, 0.5}, {2, 0.25, -4}}, 1.5, {4, -1.625, -5.5}),
        // (0.5, 0, 3) - 2 (0, 1.25, -0.5) = (0.5, -2.5, 4): t may be negative.
        ray_at({{0.5, 0, 3}, {0, 1.25, -0.5}}, -2.0, {0.5, -2.5, 4}),
        // fovy 90 over 4 x 4: the image plane spans [-1, 1]^2 and pixel centres sit at
        // +-0.25 and +-0.75. Pixel (0, 0), top left: normalize(-0.75, 0.75, -1).
        camera_ray(front(90, 4, 4), 0, 0),
        // Pixel (3, 3), bottom right: normalize(0.75, -0.75, -1).
        camera_ray(front(90, 4, 4), 3, 3),
        // Pixel (1, 2): alpha = 2 * 1.5 / 4 - 1 = -0.25, beta = 1 - 2 * 2.5 / 4 = -0.25.
        camera_ray(front(90, 4, 4), 1, 2),
        // 6 x 2 at fovy 90: half_width = 3. Pixel (5, 0): alpha = 2 * 5.5 / 6 - 1 = 5/6, so
        // x = 2.5; beta = 1 - 2 * 0.5 / 2 = 0.5: normalize(2.5, 0.5, -1).
        camera_ray(front(90, 6, 2), 5, 0),
        camera_ray(front(90, 6, 2), 0, 1),
        // Pixel (2, 0) of 3 x 3 at fovy 60: alpha = beta = 2/3, half extents tan 30 = 1/sqrt 3:
        // (2/3)(1/sqrt 3) u + (2/3)(1/sqrt 3) v - w, a direction along +x, to the right (-y)
        // and up (+z).
        camera_ray(along_x, 2, 0),
        camera_ray(along_x, 1, 1),
        no_camera(front(180, 4, 4)),
        no_camera(front(-45, 4, 4)),
        no_camera(front(60, 0, 4)),
        // up along the view direction (backwards here): no frame.
        no_camera(perspective({0, 0, 5}, {0, 0, 0}, {0, 0, -2}, 60, 4, 4)),
        // Window [-2, 2] x [-1, 1] over 4 x 2 pixels: pixel (0, 0) starts at
        // x = -2 + 4 * 0.5 / 4 = -1.5, y = 1 - 2 * 0.5 / 2 = 0.5, so at (-1.5, 0.5, 5), along -z.
        camera_ray(orthographic({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, -2, 2, -1, 1, 4, 2), 0, 0),
        camera_ray(orthographic({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, -2, 2, -1, 1, 4, 2), 3, 1),
        // Looking down +y with +z up: w = (0, -1, 0), u = (1, 0, 0), v = (0, 0, 1). Window
        // [0, 2]^2 over 2 x 2, pixel (1, 0): x = 1.5, y = 1.5, origin (2.5, 2, 4.5), along +y.
        camera_ray(orthographic({1, 2, 3}, {1, 7, 3}, {0, 0, 1}, 0, 2, 0, 2, 2, 2), 1, 0),
        no_camera(orthographic({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, 2, -2, -1, 1, 4, 2)),
    };
}

// The hidden ones: the contract's edge cases a student's own tests may not reach.
std::vector<PublicCase> hidden_cases() {
    const auto front = [](double fovy, int width, int height) {
        return perspective({0, 0, 0}, {0, 0, -3}, {0, 1, 0}, fovy, width, height);
    };
    return {
        // A far point along a long ray: t D and the sum each round once, at ulps of 1e10.
        ray_at({{1e6, -3, 0.1}, {0.1, 0.7, -0.3}}, 1e10,
               narrow(widen({1e6, -3, 0.1}) + Wide(1e10) * widen({0.1, 0.7, -0.3})),
               2 * kUnitRoundoff * 1e10),
        // fovy near 0: distinct, finite, nearly parallel rays, their sideways parts ~1e-9.
        camera_ray(front(1e-7, 64, 48), 0, 0),
        camera_ray(front(1e-7, 64, 48), 63, 47),
        // fovy near 180: the image plane is ~1e6 across, the corner rays nearly sideways.
        camera_ray(front(179.9999, 64, 64), 0, 0),
        camera_ray(front(179.9999, 64, 64), 40, 10),
        no_camera(front(180.0001, 4, 4)),
        no_camera(front(std::nan(""), 4, 4)),
        no_camera(front(kInf, 4, 4)),
        // One pixel: its centre is the image's, straight down -w.
        camera_ray(front(75, 1, 1), 0, 0),
        // One column: alpha = 0; row 4 of 5: beta = 1 - 2 * 4.5 / 5 = -0.8.
        camera_ray(front(75, 1, 5), 0, 4),
        no_camera(front(60, 5, 0)),
        no_camera(front(60, -3, 5)),
        // up not perpendicular to the view: only its part across the view counts.
        camera_ray(perspective({0, 0, 0}, {0, 0, -1}, {0, 3, 3}, 90, 4, 4), 0, 0),
        // up 1e-6 off the view direction: well clear of kParallelSine (1e-8), a valid frame
        // (u = (0, -1, 0), v = (1, 0, 0)).
        camera_ray(perspective({0, 0, 0}, {0, 0, -1}, {1e-6, 0, 1}, 90, 4, 2), 3, 0),
        // 1e-12 off: parallel as orthonormal_frame counts it.
        no_camera(perspective({0, 0, 0}, {0, 0, -1}, {1e-12, 0, 1}, 90, 4, 4)),
        no_camera(perspective({-2, 3, 0.5}, {-2, 3, 0.5}, {0, 1, 0}, 90, 4, 4)),
        // A wide image's last column: x = -1 + 2 * 999.5 / 1000 = 0.999.
        camera_ray(orthographic({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, -1, 1, -0.5, 0.5, 1000, 1), 999,
                   0),
        // Far from the origin, a window of one unit: the origin rounds at the eye's ulps.
        camera_ray(
            orthographic({1e6, -1e6, 5e5}, {0, 0, 0}, {0, 0, 1}, -0.5, 0.5, -0.25, 0.25, 8, 4), 5,
            3),
        no_camera(orthographic({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, -1, 1, 0.5, 0.5, 4, 2)),
        no_camera(orthographic({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, -1, 1, -1, 1, 0, 2)),
        // A NaN edge fails every comparison, so "left >= right" lets it through to NaN origins;
        // an infinite edge, or a width beyond the largest double, gives infinite or NaN ones.
        no_camera(orthographic({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, kNaN, 1, -1, 1, 4, 2)),
        no_camera(orthographic({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, -1, kNaN, -1, 1, 4, 2)),
        no_camera(orthographic({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, -1, 1, kNaN, 1, 4, 2)),
        no_camera(orthographic({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, -1, 1, -1, kNaN, 4, 2)),
        no_camera(orthographic({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, -kInf, 1, -1, 1, 4, 2)),
        no_camera(orthographic({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, -1, 1, -1, kInf, 4, 2)),
        no_camera(orthographic({0, 0, 5}, {0, 0, 0}, {0, 1, 0}, -1e308, 1e308, -1, 1, 4, 2)),
        // The orthographic camera's frame is orthonormal_frame's, with its errors.
        no_camera(orthographic({0, 0, 5}, {0, 0, 0}, {0, 0, 1}, -1, 1, -1, 1, 4, 2)),
        no_camera(orthographic({1, 2, 3}, {1, 2, 3}, {0, 1, 0}, -1, 1, -1, 1, 4, 2)),
        no_camera(orthographic({0, 0, 5}, {0, 0, 0}, {kInf, 1, 0}, -1, 1, -1, 1, 4, 2)),
        no_camera(perspective({0, 0, 0}, {kNaN, 0, -1}, {0, 1, 0}, 60, 4, 4)),
    };
}

// A random camera at a random scale: lookat 0.1 to 10 scales away, up at least 3 degrees off
// the view direction.
CameraCase random_camera(PortableRandom& random, bool ortho) {
    const double scale = std::pow(10.0, static_cast<double>(random.integer(-3, 4)));
    for (;;) {
        // One draw per statement: the order of two draws in one expression is the compiler's.
        const Vec3 from = scale * uniform(random, -1, 1);
        const double distance = scale * random.uniform(0.1, 10.0);
        const Vec3 at = from + distance * random.unit_vector();
        const Vec3 up = uniform(random, -1, 1);
        const double sine = glm::length(glm::cross(glm::normalize(up), glm::normalize(from - at)));
        if (!(sine > 0.05)) continue;
        const int width = static_cast<int>(random.integer(1, 4000));
        const int height = random.unit() < 0.2 ? width : static_cast<int>(random.integer(1, 4000));
        if (!ortho) {
            // Mostly ordinary fields of view, some nearly 0, some nearly 180.
            const double pick = random.unit();
            const double fovy = pick < 0.1   ? std::pow(10.0, -6 + 6 * random.unit())
                                : pick < 0.2 ? 179.99 - std::pow(10.0, -2 + 3 * random.unit())
                                             : 1 + 178 * random.unit();
            return perspective(from, at, up, fovy, width, height);
        }
        const double l = scale * random.uniform(-2.0, 2.0);
        const double b = scale * random.uniform(-2.0, 2.0);
        const double r = l + scale * random.uniform(0.1, 10.0);
        const double t = b + scale * random.uniform(0.1, 10.0);
        return orthographic(from, at, up, l, r, b, t, width, height);
    }
}

// Case k is drawn from PortableRandom(seed, k), so that it is rebuilt without the others; the
// grader's from kCameraSeed, a release's sample from kCameraSeed + kSampleSeedOffset.
constexpr std::uint64_t kCameraSeed = 0x5EED'0002;

// `count` camera rays, the last quarter through orthographic cameras.
std::vector<PublicCase> generated_cases(std::uint64_t seed, int count) {
    std::vector<PublicCase> cases;
    for (int k = 0; k < count; ++k) {
        PortableRandom random(seed, k);
        const CameraCase c = random_camera(random, 4 * k >= 3 * count);
        const int i = static_cast<int>(random.integer(0, c.width - 1));
        const int j = static_cast<int>(random.integer(0, c.height - 1));
        cases.push_back(camera_ray(c, i, j));
    }
    return cases;
}

std::vector<ProbeCase> oracle_cases() {
    return data_judged_cases(generated_cases(kCameraSeed, 400));
}

// The stage's public name, shared by the grader's check and the release's case file.
constexpr const char* kPublicName = "Ray::at and camera rays on hand-worked values";

}  // namespace

PublicCheck stage2_public_check() {
    return {"stage2.unit", 2, "unit", kPublicName, public_cases()};
}

PublicCheck stage2_sample_check() {
    return sample_check(2,
                        "perspective and orthographic rays of random cameras against long double",
                        generated_cases(kCameraSeed + kSampleSeedOffset, 20));
}

std::vector<CheckDefinition> stage2_checks() {
    return stage_case_checks(
        {2, kPublicName, [] { return data_judged_cases(public_cases()); },
         "camera rays on the contract's edge cases",
         [] { return data_judged_cases(hidden_cases()); },
         "perspective and orthographic rays of random cameras against long double", oracle_cases});
}

}  // namespace raystep::grade
