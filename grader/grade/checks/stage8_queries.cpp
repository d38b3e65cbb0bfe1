#include "grader/grade/checks/stage8_queries.h"

#include "app/grade/value_text.h"

namespace raystep::grade {

using probe::Json;

Json quad_light_json(const QuadLight& light) {
    return {{"corner", probe::vec3(light.corner)},
            {"edge1", probe::vec3(light.edge1)},
            {"edge2", probe::vec3(light.edge2)},
            {"radiance", probe::vec3(light.radiance)}};
}

Json perspective_camera_json(const PerspectiveCamera& c) {
    return {{"eye", probe::vec3(c.eye)},
            {"u", probe::vec3(c.frame.u)},
            {"v", probe::vec3(c.frame.v)},
            {"w", probe::vec3(c.frame.w)},
            {"half_width", probe::number(c.half_width)},
            {"half_height", probe::number(c.half_height)},
            {"width", c.width},
            {"height", c.height}};
}

Json orthographic_camera_json(const OrthographicCamera& c) {
    return {{"eye", probe::vec3(c.eye)},
            {"u", probe::vec3(c.frame.u)},
            {"v", probe::vec3(c.frame.v)},
            {"w", probe::vec3(c.frame.w)},
            {"left", probe::number(c.left)},
            {"right", probe::number(c.right)},
            {"bottom", probe::number(c.bottom)},
            {"top", probe::number(c.top)},
            {"width", c.width},
            {"height", c.height}};
}

Json point_json(const Vec2& p) {
    return Json::array({probe::number(p.x), probe::number(p.y)});
}

Vec2 point_from(const Json& j) {
    if (!j.is_array() || j.size() != 2) throw std::invalid_argument("a point is [x, y]");
    return {probe::number_from(j.at(0)), probe::number_from(j.at(1))};
}

std::vector<Vec2> points_from(const Json& j) {
    std::vector<Vec2> points;
    for (const Json& p : j.get_ref<const Json::array_t&>())
        points.push_back(point_from(p));
    return points;
}

Json stream_numbers(std::uint64_t first, int count) {
    Json streams = Json::array();
    for (int k = 0; k < count; ++k)
        streams.push_back(first + static_cast<std::uint64_t>(k));
    return streams;
}

std::string point_text(const Vec2& p) {
    return "(" + full_text(p.x) + ", " + full_text(p.y) + ")";
}

}  // namespace raystep::grade
