#include "grader/grade/checks/moved_eye.h"

#include <cmath>

#include <glm/geometric.hpp>

#include "app/grade/value_text.h"
#include "base/math/fnv1a.h"
#include "base/math/portable_random.h"

namespace raystep::grade {

namespace {

constexpr double kRadiansPerDegree = 3.14159265358979323846 / 180.0;

// v turned by `angle` radians about the unit axis `k` (Rodrigues' formula).
Vec3 turned(const Vec3& v, const Vec3& k, double angle) {
    return v * std::cos(angle) + glm::cross(k, v) * std::sin(angle) +
           k * (glm::dot(k, v) * (1.0 - std::cos(angle)));
}

// A magnitude in [low, high] degrees, either sign, in radians.
double signed_angle(PortableRandom& random, double low, double high) {
    const double magnitude = random.uniform(low, high) * kRadiansPerDegree;
    return random.unit() < 0.5 ? -magnitude : magnitude;
}

}  // namespace

Vec3 moved_eye(const CameraSpec& camera, std::uint64_t grade_seed, const std::string& check_id) {
    // The check's id as the generator's index.
    PortableRandom random(grade_seed, fnv1a(check_id));
    const double turn = signed_angle(random, kEyeTurnMinDegrees, kEyeTurnMaxDegrees);
    const double tilt = signed_angle(random, kEyeTiltMinDegrees, kEyeTiltMaxDegrees);
    const Vec3 up = glm::normalize(camera.up);
    Vec3 eye = turned(camera.lookfrom - camera.lookat, up, turn);
    // Tilt about the camera's right axis; an eye straight along the up hint has none, and then
    // any axis across the view will do.
    Vec3 right = glm::cross(eye, up);
    if (glm::length(right) < 1e-9 * glm::length(eye)) right = glm::cross(eye, Vec3(1, 0, 0));
    if (glm::length(right) < 1e-9 * glm::length(eye)) right = glm::cross(eye, Vec3(0, 1, 0));
    eye = turned(eye, glm::normalize(right), tilt);
    return camera.lookat + eye;
}

GradingContext with_eye_seed(const GradingContext& context) {
    GradingContext moved = context;
    moved.reproduce += " --eye-seed " + std::to_string(context.eye_seed);
    return moved;
}

std::string moved_eye_text(const Vec3& eye) {
    return "seen from " + full_text(eye) + ", not the scene's eye";
}

std::string lookfrom_arguments(const Vec3& eye) {
    return " --lookfrom " + full_text(eye.x) + " " + full_text(eye.y) + " " + full_text(eye.z);
}

}  // namespace raystep::grade
