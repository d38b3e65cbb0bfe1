#include "base/scene/scene_parser.h"

#include <glm/geometric.hpp>

#include "base/math/parallel_sine.h"
#include "base/math/to_text.h"
#include "base/scene/text_fields.h"

namespace raystep::scene_parsing {

// Image and camera

void SceneParser::size() {
    once();
    const long width = count(1, "the width");
    const long height = count(2, "the height");
    if (width < 1 || height < 1 || width > kMaxImageSide || height > kMaxImageSide) {
        fail("image size " + std::to_string(width) + " x " + std::to_string(height) +
             " is out of range: each side must be 1 to " + std::to_string(kMaxImageSide));
    }
    if (width * height > kMaxImagePixels) {
        fail("image size " + std::to_string(width) + " x " + std::to_string(height) +
             " has more than " + std::to_string(kMaxImagePixels) + " pixels");
    }
    scene_.width = static_cast<int>(width);
    scene_.height = static_cast<int>(height);
}

void SceneParser::maxdepth() {
    once();
    if (fields_[1] == "-1") {
        if (!cse168()) {
            fail(
                "maxdepth -1 (no limit) is the CSE168 dialect's, read in a scene whose "
                "'integrator' is direct, analyticdirect or pathtracer; give a depth of 0 or more");
        }
        scene_.max_depth = kUnboundedDepth;
        // The path tracer ends such paths by Russian roulette (finish() checks that it is on).
        if (!path_traced()) {
            note(
                "'maxdepth -1' sets no limit, for the path tracer's Russian roulette: this "
                "integrator traces no paths, and its refraction (stage 9), which has no "
                "roulette, follows " +
                std::to_string(kDefaultDepth) + " bounces");
        }
        return;
    }
    const long depth = count(1, "the depth");
    if (depth > kMaxDepth) {
        fail("maxdepth " + std::to_string(depth) + " is above the limit of " +
             std::to_string(kMaxDepth));
    }
    scene_.max_depth = static_cast<int>(depth);
}

void SceneParser::output() {
    once();
    scene_.output = std::string(fields_[1]);
}

void SceneParser::rayoffset() {
    once();
    const std::optional<OffsetRule> rule = parse_offset_rule(fields_[1]);
    if (!rule) {
        fail("unknown ray offset rule " + quoted_field(fields_[1]) +
             "; the rules are along-ray, along-normal and error-bound");
    }
    scene_.ray_offset.rule = *rule;
    if (!uses_epsilon(*rule)) {
        if (fields_.size() > 2) fail("error-bound takes no epsilon: it needs no tuning");
        return;
    }
    if (fields_.size() < 3) {
        fail(std::string(offset_rule_name(*rule)) + " needs an epsilon, the offset distance");
    }
    const double epsilon = number(2, "epsilon");
    if (!(epsilon > 0.0)) fail("epsilon " + quoted_field(fields_[2]) + " must be positive");
    scene_.ray_offset.epsilon = epsilon;
}

void SceneParser::camera() {
    once();
    CameraSpec& c = scene_.camera;
    c.lookfrom = vec3(1, "lookfrom");
    c.lookat = vec3(4, "lookat");
    c.up = direction(7, "the up vector");
    c.fovy_degrees = number(10, "fovy");
    c.line = static_cast<std::uint32_t>(line_);

    // The field of view: tan(fovy / 2) must be positive and finite.
    if (!(c.fovy_degrees > 0.0 && c.fovy_degrees < 180.0)) {
        fail("fovy " + std::string(fields_[10]) +
             " is out of range: the field of view must be strictly between 0 and 180 degrees");
    }
    // The view direction must exist and span a plane with the up hint. (Every number is at
    // most 1e100, so the difference is finite.)
    const Vec3 view = c.lookat - c.lookfrom;
    const double view_size = largest_magnitude(view);
    if (view_size == 0.0) {
        fail("lookfrom and lookat are the same point " + to_text(c.lookfrom) +
             ", so there is no view direction");
    }
    // Both scaled by their largest component, so that the products cannot overflow; written
    // so that a NaN counts as parallel.
    const Vec3 a = view / view_size;
    const Vec3 b = c.up / largest_magnitude(c.up);
    if (!(glm::length(glm::cross(a, b)) > kParallelSine * glm::length(a) * glm::length(b))) {
        fail("the up vector " + to_text(c.up) + " is parallel to the view direction " +
             to_text(view) + ", so the camera cannot tell up from down; choose another up");
    }
}

void SceneParser::ortho() {
    once();
    const OrthoWindow window{number(1, "left"), number(2, "right"), number(3, "bottom"),
                             number(4, "top")};
    if (!(window.left < window.right) || !(window.bottom < window.top)) {
        fail("ortho window must have left < right and bottom < top");
    }
    ortho_ = window;
}

}  // namespace raystep::scene_parsing
