#include "grading/8_sampling/sampling_json.h"

#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

namespace raystep::probe {

Json JsonCodec<SamplePattern>::write(SamplePattern pattern) {
    return Json(std::string(sample_pattern_name(pattern)));
}

SamplePattern JsonCodec<SamplePattern>::read(const Json& j) {
    const std::string name = JsonCodec<std::string>::read(j);
    if (const auto pattern = parse_sample_pattern(name)) return *pattern;
    throw std::invalid_argument("unknown sample pattern \"" + name + "\"");
}

namespace {

// The fields both cameras have: the eye, the frame's u, v and w, and the image size.
template <class Camera>
Json camera_common(const Camera& c) {
    return {{"eye", vec3(c.eye)},   {"u", vec3(c.frame.u)}, {"v", vec3(c.frame.v)},
            {"w", vec3(c.frame.w)}, {"width", c.width},     {"height", c.height}};
}

template <class Camera>
Camera camera_common_from(const Json& j) {
    Camera c{};
    c.eye = vec3_from(field(j, "eye"));
    c.frame = {vec3_from(field(j, "u")), vec3_from(field(j, "v")), vec3_from(field(j, "w"))};
    c.width = integer_from(field(j, "width"));
    c.height = integer_from(field(j, "height"));
    return c;
}

}  // namespace

Json perspective_camera(const PerspectiveCamera& c) {
    Json j = camera_common(c);
    j["half_width"] = number(c.half_width);
    j["half_height"] = number(c.half_height);
    return j;
}

PerspectiveCamera perspective_camera_from(const Json& j) {
    PerspectiveCamera c = camera_common_from<PerspectiveCamera>(j);
    c.half_width = number_from(field(j, "half_width"));
    c.half_height = number_from(field(j, "half_height"));
    return c;
}

Json orthographic_camera(const OrthographicCamera& c) {
    Json j = camera_common(c);
    j["left"] = number(c.left);
    j["right"] = number(c.right);
    j["bottom"] = number(c.bottom);
    j["top"] = number(c.top);
    return j;
}

OrthographicCamera orthographic_camera_from(const Json& j) {
    OrthographicCamera c = camera_common_from<OrthographicCamera>(j);
    c.left = number_from(field(j, "left"));
    c.right = number_from(field(j, "right"));
    c.bottom = number_from(field(j, "bottom"));
    c.top = number_from(field(j, "top"));
    return c;
}

namespace {

bool crosses(const Parallelogram& p, const Ray& ray) {
    const Vec3 normal = glm::cross(p.edge1, p.edge2);
    const double facing = glm::dot(ray.direction, normal);
    if (facing == 0.0) return false;
    const double t = glm::dot(p.corner - ray.origin, normal) / facing;
    if (!(t >= ray.t_min && t <= ray.t_max)) return false;
    // The crossing's coordinates along the two edges, by the dual basis of (edge1, edge2).
    const Vec3 q = ray.origin + t * ray.direction - p.corner;
    const double g11 = glm::dot(p.edge1, p.edge1);
    const double g12 = glm::dot(p.edge1, p.edge2);
    const double g22 = glm::dot(p.edge2, p.edge2);
    const double det = g11 * g22 - g12 * g12;
    const double s = (glm::dot(q, p.edge1) * g22 - glm::dot(q, p.edge2) * g12) / det;
    const double r = (glm::dot(q, p.edge2) * g11 - glm::dot(q, p.edge1) * g12) / det;
    return s >= 0.0 && s <= 1.0 && r >= 0.0 && r <= 1.0;
}

// A field the kind of film radiance needs.
template <class T>
T required(const std::optional<T>& value, const char* name, const std::string& kind) {
    if (!value) {
        throw std::invalid_argument("the film radiance \"" + kind + "\" needs \"" + name + "\"");
    }
    return *value;
}

}  // namespace

bool crosses_any(const std::vector<Parallelogram>& blockers, const Ray& ray) {
    for (const Parallelogram& p : blockers) {
        if (crosses(p, ray)) return true;
    }
    return false;
}

FilmRadiance film_radiance(const FilmRadianceModel& m) {
    if (m.kind == "constant") {
        const double value = required(m.value, "value", m.kind);
        return [value](const Vec2&) { return Color(value); };
    }
    if (m.kind == "edge") {
        const Vec2 through = required(m.through, "through", m.kind);
        const Vec2 normal = required(m.normal, "normal", m.kind);
        const double bright = required(m.bright, "bright", m.kind);
        const double dark = required(m.dark, "dark", m.kind);
        return [=](const Vec2& film) {
            const Vec2 d = film - through;
            return Color(d.x * normal.x + d.y * normal.y >= 0.0 ? bright : dark);
        };
    }
    if (m.kind == "ramp") {
        const double value = required(m.value, "value", m.kind);
        const Vec2 gradient = required(m.gradient, "gradient", m.kind);
        return [=](const Vec2& film) {
            return Color(value + gradient.x * film.x + gradient.y * film.y);
        };
    }
    throw std::invalid_argument("unknown film radiance \"" + m.kind + "\"");
}

}  // namespace raystep::probe
