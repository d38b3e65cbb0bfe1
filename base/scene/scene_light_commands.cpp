#include "base/scene/scene_parser.h"

#include <glm/geometric.hpp>

#include "base/math/parallel_sine.h"
#include "base/math/to_text.h"

namespace raystep::scene_parsing {

// Lights: world coordinates, whatever the transform stack holds.

void SceneParser::directional() {
    const Vec3 towards_light = direction(1, "the light's direction");
    scene_.directional_lights.push_back(
        {towards_light, color(4), static_cast<std::uint32_t>(line_)});
}

void SceneParser::point() {
    scene_.point_lights.push_back(
        {vec3(1, "the position"), color(4), attenuation_, static_cast<std::uint32_t>(line_)});
}

void SceneParser::spot() {
    SpotLight light;
    light.position = vec3(1, "the position");
    light.direction = direction(4, "the spot light's axis");
    light.cutoff_degrees = number(7, "the cutoff");
    // Written so that a NaN fails too. Beyond 90 degrees the cone would light what is behind
    // the spot light, which a spot light does not do.
    if (!(light.cutoff_degrees > 0.0 && light.cutoff_degrees <= 90.0)) {
        fail("cutoff " + std::string(fields_[7]) +
             " is out of range: the cone's half-angle must be above 0 and at most 90 degrees");
    }
    light.exponent = number(8, "the exponent");
    if (!(light.exponent >= 0.0)) {
        fail("exponent " + std::string(fields_[8]) + " must not be negative");
    }
    light.color = color(9);
    light.attenuation = attenuation_;
    light.line = static_cast<std::uint32_t>(line_);
    scene_.spot_lights.push_back(light);
}

// The CSE168 area light: corner a and edges ab and ac. Sampling it divides by its area
// |ab x ac| and shades with its normal (ac x ab) / |ac x ab|, so that cross product must be a
// direction as `direction` requires one (neither zero nor beyond the range where its length
// is computed reliably), and ab and ac must not be parallel, by the camera's test.
void SceneParser::quad_light() {
    QuadLight light;
    light.corner = vec3(1, "the corner");
    light.edge1 = vec3(4, "the edge ab");
    light.edge2 = vec3(7, "the edge ac");
    light.radiance = color(10);
    light.line = static_cast<std::uint32_t>(line_);
    const double ab_size = largest_magnitude(light.edge1);
    const double ac_size = largest_magnitude(light.edge2);
    if (ab_size == 0.0 || ac_size == 0.0) {
        fail(std::string("the light's edge ") + (ab_size == 0.0 ? "ab" : "ac") +
             " is zero, so the light has no area");
    }
    // Scaled by their largest components, so that the products cannot overflow; written so
    // that a NaN counts as parallel.
    const Vec3 a = light.edge1 / ab_size;
    const Vec3 b = light.edge2 / ac_size;
    if (!(glm::length(glm::cross(a, b)) > kParallelSine * glm::length(a) * glm::length(b))) {
        fail("the light's edges ab " + to_text(light.edge1) + " and ac " + to_text(light.edge2) +
             " are parallel, so the light has no area");
    }
    const double normal_size = largest_magnitude(glm::cross(light.edge1, light.edge2));
    if (!(normal_size >= kSmallestDirection && normal_size <= kLargestDirection)) {
        fail(
            "the light's area |ab x ac| is too small or too large to compute reliably "
            "(its largest component is " +
            to_text(normal_size) + ", outside 1e-150 to 1e150); scale it towards 1");
    }
    if (cse168()) {
        note(
            "in the CSE168 dialect a quadLight is drawn: a camera ray that meets its emitting "
            "side sees its radiance (a CSE167 scene is lit by it unseen)");
    }
    scene_.quad_lights.push_back(light);
}

void SceneParser::attenuation() {
    const Attenuation a{number(1, "the constant term"), number(2, "the linear term"),
                        number(3, "the quadratic term")};
    if (a.constant < 0 || a.linear < 0 || a.quadratic < 0) {
        fail("attenuation terms must not be negative");
    }
    if (a.constant == 0 && a.linear == 0 && a.quadratic == 0) {
        fail("attenuation 0 0 0 would divide the light by zero");
    }
    attenuation_ = a;
}

void SceneParser::background() {
    once();
    scene_.background = color(1);
}

// Materials: the current state, given to every object made after it.

void SceneParser::set_material(Color Material::*field) {
    material_.*field = color(1);
    material_id_ = kUnregistered;
}

void SceneParser::ambient() {
    set_material(&Material::ambient);
    ambient_written_ = true;
}

void SceneParser::diffuse() {
    set_material(&Material::diffuse);
}

void SceneParser::specular() {
    set_material(&Material::specular);
    if (cse168() && material_.specular != Color(0.0)) {
        note(
            "in the CSE168 dialect 'specular' is the course's Phong lobe, not a mirror: no "
            "reflected ray is traced, where CSE167 traces one to maxdepth and shades with "
            "Blinn-Phong");
    }
}

void SceneParser::emission() {
    set_material(&Material::emission);
}

void SceneParser::shininess() {
    const double s = number(1, "the shininess");
    if (s < 0) fail("shininess " + std::string(fields_[1]) + " must not be negative");
    material_.shininess = s;
    material_id_ = kUnregistered;
}

// Dielectrics (stage 9): material state like the colours.

void SceneParser::transmission() {
    set_material(&Material::transmission);
}

void SceneParser::ior() {
    const double index = number(1, "the index of refraction");
    if (!(index > 0.0))
        fail("index of refraction " + std::string(fields_[1]) + " must be positive");
    material_.index = index;
    material_id_ = kUnregistered;
}

void SceneParser::fresnel() {
    once();
    scene_.schlick_fresnel = keyword(1, "exact|schlick") == 1;
}

}  // namespace raystep::scene_parsing
