// Stage 8 calls: sample patterns, rays through film points, a pixel's mean and a quad light's
// soft shadow. The random calls take the render's seed and a list of stream numbers and answer
// one result per stream, each from its own RandomStream(seed, stream): the grader asks for
// hundreds of streams in one query and judges the distribution of what comes back, never the
// values, since a student may consume a stream in any order. The film radiance and the occluder
// are the probe's own, made from the query's parameters, so that the grader knows the exact
// integral each mean estimates. Where the student's code asks them something, the answer hands
// back what it asked (the film points, the shadow rays) as data, never a count: the grader checks
// that data against its own scene and derives every figure from it, since a count kept in this
// process is only what the student's code, which runs here too, lets it be.

#include <cmath>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>

#include "app/probe/call_table.h"
#include "stages/8_sampling/sampling.h"

namespace raystep::probe {

namespace {

Json point(const Vec2& p) {
    return Json::array({number(p.x), number(p.y)});
}

Vec2 point_from(const Json& j) {
    return {number_from(j.at(0)), number_from(j.at(1))};
}

Json points(const std::vector<Vec2>& list) {
    Json all = Json::array();
    for (const Vec2& p : list)
        all.push_back(point(p));
    return all;
}

SamplePattern pattern_from(const Json& j) {
    const std::string name = j.get<std::string>();
    if (const auto pattern = parse_sample_pattern(name)) return *pattern;
    throw std::invalid_argument("unknown sample pattern \"" + name + "\"");
}

QuadLight quad_light_from(const Json& j) {
    QuadLight light;
    light.corner = vec3_from(j.at("corner"));
    light.edge1 = vec3_from(j.at("edge1"));
    light.edge2 = vec3_from(j.at("edge2"));
    light.radiance = vec3_from(j.at("radiance"));
    return light;
}

// One answer per stream of "streams", each from RandomStream(seed, stream).
template <class PerStream>
Json per_stream(const Json& a, PerStream answer) {
    const auto seed = a.at("seed").get<std::uint64_t>();
    Json answers = Json::array();
    for (const Json& stream : a.at("streams")) {
        RandomStream random(seed, stream.get<std::uint64_t>());
        answers.push_back(answer(random));
    }
    return answers;
}

// The film radiance a pixel_colour query names, all three channels alike:
// - constant: `value` everywhere;
// - edge: `bright` where (film - through) . normal >= 0, `dark` elsewhere;
// - ramp: value + gradient . film.
FilmRadiance film_radiance_from(const Json& j) {
    const std::string kind = j.at("kind").get<std::string>();
    if (kind == "constant") {
        const double value = number_from(j.at("value"));
        return [value](const Vec2&) { return Color(value); };
    }
    if (kind == "edge") {
        const Vec2 through = point_from(j.at("through"));
        const Vec2 normal = point_from(j.at("normal"));
        const double bright = number_from(j.at("bright"));
        const double dark = number_from(j.at("dark"));
        return [=](const Vec2& film) {
            const Vec2 d = film - through;
            return Color(d.x * normal.x + d.y * normal.y >= 0.0 ? bright : dark);
        };
    }
    if (kind == "ramp") {
        const double value = number_from(j.at("value"));
        const Vec2 gradient = point_from(j.at("gradient"));
        return [=](const Vec2& film) {
            return Color(value + gradient.x * film.x + gradient.y * film.y);
        };
    }
    throw std::invalid_argument("unknown film radiance \"" + kind + "\"");
}

// A parallelogram in front of the light: a shadow ray is blocked when it meets it within its
// [t_min, t_max]. Null: nothing blocks.
// One parallelogram {"corner", "edge1", "edge2"} that blocks the rays crossing it within their
// t range.
OccludedFunction parallelogram_from(const Json& j) {
    const Vec3 corner = vec3_from(j.at("corner"));
    const Vec3 e1 = vec3_from(j.at("edge1"));
    const Vec3 e2 = vec3_from(j.at("edge2"));
    return [=](const Ray& ray) {
        const Vec3 normal = glm::cross(e1, e2);
        const double facing = glm::dot(ray.direction, normal);
        if (facing == 0.0) return false;
        const double t = glm::dot(corner - ray.origin, normal) / facing;
        if (!(t >= ray.t_min && t <= ray.t_max)) return false;
        // The point's coordinates along the two edges, by the dual basis of (e1, e2).
        const Vec3 p = ray.origin + t * ray.direction - corner;
        const double g11 = glm::dot(e1, e1), g12 = glm::dot(e1, e2), g22 = glm::dot(e2, e2);
        const double det = g11 * g22 - g12 * g12;
        const double s = (glm::dot(p, e1) * g22 - glm::dot(p, e2) * g12) / det;
        const double r = (glm::dot(p, e2) * g11 - glm::dot(p, e1) * g12) / det;
        return s >= 0.0 && s <= 1.0 && r >= 0.0 && r <= 1.0;
    };
}

// null (nothing blocks), one parallelogram, or a list of them.
OccludedFunction occluder_from(const Json& j) {
    if (j.is_null()) return [](const Ray&) { return false; };
    if (!j.is_array()) return parallelogram_from(j);
    std::vector<OccludedFunction> parts;
    for (const Json& part : j)
        parts.push_back(parallelogram_from(part));
    return [parts](const Ray& ray) {
        for (const OccludedFunction& part : parts) {
            if (part(ray)) return true;
        }
        return false;
    };
}

// A shadow ray as it was traced, and what the blocker answered.
Json traced_shadow_ray(const Ray& shadow, bool blocked) {
    return Json{{"ray", ray(shadow)}, {"blocked", blocked}};
}

// `occluded` that also writes each ray it is asked about, and its answer, into `traced`.
OccludedFunction recording(const OccludedFunction& occluded, Json& traced) {
    return [&occluded, &traced](const Ray& shadow) {
        const bool blocked = occluded(shadow);
        traced.push_back(traced_shadow_ray(shadow, blocked));
        return blocked;
    };
}

PerspectiveCamera perspective_camera_from(const Json& j) {
    PerspectiveCamera c;
    c.eye = vec3_from(j.at("eye"));
    c.frame = {vec3_from(j.at("u")), vec3_from(j.at("v")), vec3_from(j.at("w"))};
    c.half_width = number_from(j.at("half_width"));
    c.half_height = number_from(j.at("half_height"));
    c.width = integer_from(j.at("width"));
    c.height = integer_from(j.at("height"));
    return c;
}

OrthographicCamera orthographic_camera_from(const Json& j) {
    OrthographicCamera c;
    c.eye = vec3_from(j.at("eye"));
    c.frame = {vec3_from(j.at("u")), vec3_from(j.at("v")), vec3_from(j.at("w"))};
    c.left = number_from(j.at("left"));
    c.right = number_from(j.at("right"));
    c.bottom = number_from(j.at("bottom"));
    c.top = number_from(j.at("top"));
    c.width = integer_from(j.at("width"));
    c.height = integer_from(j.at("height"));
    return c;
}

template <class Camera, class RayThrough>
Json rays_through(const Camera& camera, const Json& films, RayThrough through) {
    Json rays = Json::array();
    for (const Json& film : films)
        rays.push_back(ray(through(camera, point_from(film))));
    return rays;
}

}  // namespace

void add_sampling_calls(CallTable& table) {
    table["regular_samples"] = [](const Json& a) {
        return points(regular_samples(integer_from(a.at("strata"))));
    };
    table["jittered_samples"] = [](const Json& a) {
        const int strata = integer_from(a.at("strata"));
        return per_stream(a, [&](RandomStream& r) { return points(jittered_samples(strata, r)); });
    };
    table["random_samples"] = [](const Json& a) {
        const int count = integer_from(a.at("count"));
        return per_stream(a, [&](RandomStream& r) { return points(random_samples(count, r)); });
    };
    table["samples"] = [](const Json& a) {
        const SamplePattern pattern = pattern_from(a.at("pattern"));
        const int count = integer_from(a.at("count"));
        return per_stream(a, [&](RandomStream& r) { return points(samples(pattern, count, r)); });
    };
    table["perspective_ray_through"] = [](const Json& a) {
        return rays_through(perspective_camera_from(a.at("camera")), a.at("films"),
                            perspective_ray_through);
    };
    table["orthographic_ray_through"] = [](const Json& a) {
        return rays_through(orthographic_camera_from(a.at("camera")), a.at("films"),
                            orthographic_ray_through);
    };
    // Per stream the colour and the film points the radiance was asked about, in order.
    table["pixel_colour"] = [](const Json& a) {
        const FilmRadiance radiance = film_radiance_from(a.at("radiance"));
        const int i = integer_from(a.at("i"));
        const int j = integer_from(a.at("j"));
        const SamplePattern pattern = pattern_from(a.at("pattern"));
        const int count = integer_from(a.at("count"));
        return per_stream(a, [&](RandomStream& r) {
            Json films = Json::array();
            const FilmRadiance recorded = [&](const Vec2& film) {
                films.push_back(point(film));
                return radiance(film);
            };
            const Color colour = pixel_colour(recorded, i, j, pattern, count, r);
            return Json{{"colour", vec3(colour)}, {"films", std::move(films)}};
        });
    };
    table["sample_quad_light"] = [](const Json& a) {
        return light_sample(sample_quad_light(quad_light_from(a.at("light")),
                                              vec3_from(a.at("point")), point_from(a.at("u")),
                                              integer_from(a.at("sample_count"))));
    };
    // Per stream the colour and the shadow rays traced, in order.
    table["quad_light_shading"] = [](const Json& a) {
        const Material material = material_from(a.at("material"));
        const SurfacePoint p = surface_point_from(a.at("point"));
        const QuadLight light = quad_light_from(a.at("light"));
        const SamplePattern pattern = pattern_from(a.at("pattern"));
        const int count = integer_from(a.at("count"));
        const OccludedFunction blocker = occluder_from(a.at("blocker"));
        const RayOffset offset = ray_offset_from(a.at("offset"));
        return per_stream(a, [&](RandomStream& r) {
            Json traced = Json::array();
            const Color colour = quad_light_shading(material, p, light, pattern, count, r,
                                                    recording(blocker, traced), offset);
            return Json{{"colour", vec3(colour)}, {"shadow_rays", std::move(traced)}};
        });
    };
    // A pixel of a floor under a quad light: pixel_colour over a film radiance that shades the
    // floor point under each film point with quad_light_shading, nothing blocking. The film point
    // (i + x, j + y) is the point corner + x edge1 + y edge2, its normal edge1 x edge2 normalized.
    // Each stream is the pixel's one stream, handed to pixel_colour and then to every
    // quad_light_shading in turn, as a RandomStream& parameter promises a caller may: right code
    // draws new numbers for every film sample's light samples. Per stream the colour, and per
    // film sample, in order, its film point and the shadow rays its shading traced.
    table["pixel_colour_with_quad_light"] = [](const Json& a) {
        const int i = integer_from(a.at("i"));
        const int j = integer_from(a.at("j"));
        const SamplePattern pattern = pattern_from(a.at("pattern"));
        const int count = integer_from(a.at("count"));
        const Json& floor = a.at("floor");
        const Vec3 corner = vec3_from(floor.at("corner"));
        const Vec3 edge1 = vec3_from(floor.at("edge1"));
        const Vec3 edge2 = vec3_from(floor.at("edge2"));
        const Vec3 normal = glm::normalize(glm::cross(edge1, edge2));
        const Vec3 to_eye = vec3_from(a.at("to_eye"));
        const Material material = material_from(a.at("material"));
        const QuadLight light = quad_light_from(a.at("light"));
        const SamplePattern light_pattern = pattern_from(a.at("light_pattern"));
        const int light_count = integer_from(a.at("light_count"));
        const RayOffset offset = ray_offset_from(a.at("offset"));
        const OccludedFunction nothing = [](const Ray&) { return false; };
        return per_stream(a, [&](RandomStream& r) {
            Json films = Json::array();
            const FilmRadiance radiance = [&](const Vec2& film) {
                const SurfacePoint p{corner + (film.x - i) * edge1 + (film.y - j) * edge2,
                                     Vec3(0.0), normal, normal, to_eye};
                Json traced = Json::array();
                const Color colour =
                    quad_light_shading(material, p, light, light_pattern, light_count, r,
                                       recording(nothing, traced), offset);
                films.push_back(Json{{"film", point(film)}, {"shadow_rays", std::move(traced)}});
                return colour;
            };
            const Color colour = pixel_colour(radiance, i, j, pattern, count, r);
            return Json{{"colour", vec3(colour)}, {"films", std::move(films)}};
        });
    };
}

}  // namespace raystep::probe
