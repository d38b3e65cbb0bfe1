#include "app/protocol/probe_json.h"

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>

namespace raystep::probe {

const Json& field(const Json& j, const char* name) {
    if (!j.is_object() || !j.contains(name)) {
        throw std::invalid_argument(std::string("expected a field '") + name + "'");
    }
    return j.at(name);
}

namespace {

const Json& element(const Json& j, std::size_t k, std::size_t size) {
    if (!j.is_array() || j.size() != size) {
        throw std::invalid_argument("expected an array of " + std::to_string(size));
    }
    return j[k];
}

std::size_t index_from(const Json& j) {
    if (!j.is_number_unsigned()) throw std::invalid_argument("expected an index");
    return j.get<std::size_t>();
}

}  // namespace

Json number(double x) {
    if (std::isnan(x)) return "nan";
    if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
    return x;
}

double number_from(const Json& j) {
    if (j.is_number()) return j.get<double>();
    if (j == "nan") return std::nan("");
    if (j == "inf") return HUGE_VAL;
    if (j == "-inf") return -HUGE_VAL;
    throw std::invalid_argument("expected a number");
}

int integer_from(const Json& j) {
    const bool fits = j.is_number_unsigned()
                          ? j.get<std::uint64_t>() <= std::numeric_limits<int>::max()
                          : j.is_number_integer() &&
                                j.get<std::int64_t>() >= std::numeric_limits<int>::min() &&
                                j.get<std::int64_t>() <= std::numeric_limits<int>::max();
    if (!fits) throw std::invalid_argument("expected a whole number that fits an int");
    return j.get<int>();
}

Json vec2(const Vec2& v) {
    return Json::array({number(v.x), number(v.y)});
}

Vec2 vec2_from(const Json& j) {
    return {number_from(element(j, 0, 2)), number_from(element(j, 1, 2))};
}

Json vec3(const Vec3& v) {
    return Json::array({number(v.x), number(v.y), number(v.z)});
}

Vec3 vec3_from(const Json& j) {
    return {number_from(element(j, 0, 3)), number_from(element(j, 1, 3)),
            number_from(element(j, 2, 3))};
}

Json mat4(const Mat4& m) {
    Json j = Json::array();
    for (int column = 0; column < 4; ++column) {
        for (int row = 0; row < 4; ++row)
            j.push_back(number(m[column][row]));
    }
    return j;
}

Mat4 mat4_from(const Json& j) {
    Mat4 m;
    for (int column = 0; column < 4; ++column) {
        for (int row = 0; row < 4; ++row) {
            m[column][row] =
                number_from(element(j, static_cast<std::size_t>(4 * column + row), 16));
        }
    }
    return m;
}

Json ray(const Ray& r) {
    return {{"origin", vec3(r.origin)},
            {"direction", vec3(r.direction)},
            {"t_min", number(r.t_min)},
            {"t_max", number(r.t_max)}};
}

Ray ray_from(const Json& j) {
    return {vec3_from(field(j, "origin")), vec3_from(field(j, "direction")),
            number_from(field(j, "t_min")), number_from(field(j, "t_max"))};
}

std::vector<Ray> rays_from(const Json& j) {
    std::vector<Ray> rays;
    for (const Json& r : j)
        rays.push_back(ray_from(r));
    return rays;
}

Json hit(const std::optional<Hit>& h) {
    if (!h) return nullptr;
    return {{"t", number(h->t)},
            {"normal", vec3(h->normal)},
            {"beta", number(h->beta)},
            {"gamma", number(h->gamma)}};
}

std::optional<Hit> hit_from(const Json& j) {
    if (j.is_null()) return std::nullopt;
    return Hit{number_from(field(j, "t")), vec3_from(field(j, "normal")),
               number_from(field(j, "beta")), number_from(field(j, "gamma"))};
}

namespace {

const char* kind_text(PrimitiveKind kind) {
    switch (kind) {
        case PrimitiveKind::sphere:
            return "sphere";
        case PrimitiveKind::triangle:
            return "triangle";
        case PrimitiveKind::plane:
            return "plane";
    }
    throw std::invalid_argument("unknown primitive kind");
}

PrimitiveKind kind_from(const Json& j) {
    if (j == "sphere") return PrimitiveKind::sphere;
    if (j == "triangle") return PrimitiveKind::triangle;
    if (j == "plane") return PrimitiveKind::plane;
    throw std::invalid_argument("expected a primitive kind");
}

}  // namespace

Json primitive_hit(const std::optional<PrimitiveHit>& h) {
    if (!h) return nullptr;
    return {{"hit", hit(h->hit)}, {"kind", kind_text(h->kind)}, {"index", h->index}};
}

std::optional<PrimitiveHit> primitive_hit_from(const Json& j) {
    if (j.is_null()) return std::nullopt;
    const std::optional<Hit> h = hit_from(field(j, "hit"));
    if (!h) throw std::invalid_argument("a primitive hit without its hit");
    return PrimitiveHit{*h, kind_from(field(j, "kind")), index_from(field(j, "index"))};
}

Json sphere(const Sphere& s) {
    return {{"center", vec3(s.center)}, {"radius", number(s.radius)}};
}

Sphere sphere_from(const Json& j) {
    return {vec3_from(field(j, "center")), number_from(field(j, "radius"))};
}

Json triangle(const Triangle& t) {
    return Json::array({vec3(t.p0), vec3(t.p1), vec3(t.p2)});
}

Triangle triangle_from(const Json& j) {
    return {vec3_from(element(j, 0, 3)), vec3_from(element(j, 1, 3)), vec3_from(element(j, 2, 3))};
}

Json plane(const Plane& p) {
    return {{"point", vec3(p.point)}, {"normal", vec3(p.normal)}};
}

Plane plane_from(const Json& j) {
    return {vec3_from(field(j, "point")), vec3_from(field(j, "normal"))};
}

Json primitive_list(const PrimitiveList& list) {
    Json j = {{"spheres", Json::array()}, {"triangles", Json::array()}, {"planes", Json::array()}};
    for (const Sphere& s : list.spheres)
        j["spheres"].push_back(sphere(s));
    for (const Triangle& t : list.triangles)
        j["triangles"].push_back(triangle(t));
    for (const Plane& p : list.planes)
        j["planes"].push_back(plane(p));
    return j;
}

PrimitiveList primitive_list_from(const Json& j) {
    PrimitiveList list;
    for (const Json& s : field(j, "spheres"))
        list.spheres.push_back(sphere_from(s));
    for (const Json& t : field(j, "triangles"))
        list.triangles.push_back(triangle_from(t));
    for (const Json& p : field(j, "planes"))
        list.planes.push_back(plane_from(p));
    return list;
}

Json transform(const Transform& t) {
    return {{"matrix", mat4(t.matrix)}, {"inverse", mat4(t.inverse)}};
}

Transform transform_from(const Json& j) {
    return {mat4_from(field(j, "matrix")), mat4_from(field(j, "inverse"))};
}

Json transform_op(const TransformOp& op) {
    const char* kind = op.kind == TransformOp::Kind::translate ? "translate"
                       : op.kind == TransformOp::Kind::rotate  ? "rotate"
                                                               : "scale";
    return {{"kind", kind}, {"vector", vec3(op.vector)}, {"degrees", number(op.angle_degrees)}};
}

TransformOp transform_op_from(const Json& j) {
    const Json& kind = field(j, "kind");
    TransformOp op{TransformOp::Kind::translate, vec3_from(field(j, "vector")),
                   number_from(field(j, "degrees"))};
    if (kind == "rotate") {
        op.kind = TransformOp::Kind::rotate;
    } else if (kind == "scale") {
        op.kind = TransformOp::Kind::scale;
    } else if (kind != "translate") {
        throw std::invalid_argument("expected a transform op");
    }
    return op;
}

Json material(const Material& m) {
    return {{"ambient", vec3(m.ambient)},
            {"diffuse", vec3(m.diffuse)},
            {"specular", vec3(m.specular)},
            {"emission", vec3(m.emission)},
            {"shininess", number(m.shininess)}};
}

Material material_from(const Json& j) {
    Material m;
    m.ambient = vec3_from(field(j, "ambient"));
    m.diffuse = vec3_from(field(j, "diffuse"));
    m.specular = vec3_from(field(j, "specular"));
    m.emission = vec3_from(field(j, "emission"));
    m.shininess = number_from(field(j, "shininess"));
    return m;
}

Json attenuation(const Attenuation& a) {
    return Json::array({number(a.constant), number(a.linear), number(a.quadratic)});
}

Attenuation attenuation_from(const Json& j) {
    return {number_from(element(j, 0, 3)), number_from(element(j, 1, 3)),
            number_from(element(j, 2, 3))};
}

Json point_light(const PointLight& l) {
    return {{"position", vec3(l.position)},
            {"color", vec3(l.color)},
            {"attenuation", attenuation(l.attenuation)}};
}

PointLight point_light_from(const Json& j) {
    PointLight l;
    l.position = vec3_from(field(j, "position"));
    l.color = vec3_from(field(j, "color"));
    l.attenuation = attenuation_from(field(j, "attenuation"));
    return l;
}

Json directional_light(const DirectionalLight& l) {
    return {{"direction", vec3(l.direction)}, {"color", vec3(l.color)}};
}

DirectionalLight directional_light_from(const Json& j) {
    DirectionalLight l;
    l.direction = vec3_from(field(j, "direction"));
    l.color = vec3_from(field(j, "color"));
    return l;
}

Json surface_point(const SurfacePoint& p) {
    return {{"position", vec3(p.position)},
            {"error", vec3(p.error)},
            {"normal", vec3(p.normal)},
            {"shading_normal", vec3(p.shading_normal)},
            {"to_eye", vec3(p.to_eye)}};
}

SurfacePoint surface_point_from(const Json& j) {
    return {vec3_from(field(j, "position")), vec3_from(field(j, "error")),
            vec3_from(field(j, "normal")), vec3_from(field(j, "shading_normal")),
            vec3_from(field(j, "to_eye"))};
}

Json light_sample(const LightSample& l) {
    return {{"direction", vec3(l.direction)},
            {"distance", number(l.distance)},
            {"intensity", vec3(l.intensity)}};
}

LightSample light_sample_from(const Json& j) {
    return {vec3_from(field(j, "direction")), number_from(field(j, "distance")),
            vec3_from(field(j, "intensity"))};
}

Json ray_offset(const RayOffset& o) {
    return {{"rule", std::string(offset_rule_name(o.rule))}, {"epsilon", number(o.epsilon)}};
}

RayOffset ray_offset_from(const Json& j) {
    const Json& rule = field(j, "rule");
    if (!rule.is_string()) throw std::invalid_argument("expected an offset rule");
    const std::optional<OffsetRule> parsed = parse_offset_rule(rule.get<std::string>());
    if (!parsed) throw std::invalid_argument("expected an offset rule");
    return {*parsed, number_from(field(j, "epsilon"))};
}

Json case_question(const RayCase& c) {
    Json primitives = Json::array();
    for (const CasePrimitive& p : c.primitives) {
        if (const auto* s = std::get_if<Sphere>(&p.shape)) {
            primitives.push_back({{"sphere", sphere(*s)}});
        } else if (const auto* t = std::get_if<Triangle>(&p.shape)) {
            primitives.push_back({{"triangle", triangle(*t)}});
        } else {
            primitives.push_back({{"plane", plane(std::get<Plane>(p.shape))}});
        }
    }
    return {{"index", c.index},
            {"ray", ray(c.ray)},
            {"primitives", primitives},
            {"watertight", c.watertight}};
}

RayCase case_question_from(const Json& j) {
    RayCase c;
    c.index = field(j, "index").get<std::uint64_t>();
    c.ray = ray_from(field(j, "ray"));
    c.watertight = field(j, "watertight").get<bool>();
    for (const Json& p : field(j, "primitives")) {
        CasePrimitive primitive;
        if (p.contains("sphere")) {
            primitive.shape = sphere_from(p["sphere"]);
        } else if (p.contains("triangle")) {
            primitive.shape = triangle_from(p["triangle"]);
        } else {
            primitive.shape = plane_from(field(p, "plane"));
        }
        c.primitives.push_back(primitive);
    }
    return c;
}

Json case_answer(const CaseAnswer& a) {
    Json hits = Json::array();
    for (const std::optional<Hit>& h : a.hits)
        hits.push_back(hit(h));
    Json j = {{"hits", hits},
              {"closest_hit", hit(a.closest_hit)},
              {"not_implemented", a.not_implemented},
              {"error", a.error}};
    j["closest_primitive"] = a.closest_primitive ? Json(*a.closest_primitive) : Json(nullptr);
    return j;
}

CaseAnswer case_answer_from(const Json& j) {
    CaseAnswer a;
    for (const Json& h : field(j, "hits"))
        a.hits.push_back(hit_from(h));
    const Json& closest = field(j, "closest_primitive");
    if (!closest.is_null()) a.closest_primitive = index_from(closest);
    a.closest_hit = hit_from(field(j, "closest_hit"));
    a.not_implemented = field(j, "not_implemented").get<bool>();
    a.error = field(j, "error").get<std::string>();
    return a;
}

bool nested_too_deep(const std::string& text) {
    int depth = 0;
    bool in_string = false;
    bool escaped = false;
    for (const char c : text) {
        if (in_string) {
            if (escaped) {
                escaped = false;
            } else if (c == '\\') {
                escaped = true;
            } else if (c == '"') {
                in_string = false;
            }
        } else if (c == '"') {
            in_string = true;
        } else if (c == '[' || c == '{') {
            if (++depth > kDeepestNesting) return true;
        } else if (c == ']' || c == '}') {
            --depth;
        }
    }
    return false;
}

}  // namespace raystep::probe
