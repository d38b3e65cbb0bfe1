#include "app/check/stage3_methods.h"

#include <exception>
#include <stdexcept>
#include <variant>

#include "base/errors/not_implemented.h"

namespace raystep {

namespace {

std::optional<Hit> test_primitive(const Stage3Method& method, const Ray& ray,
                                  const CaseShape& shape) {
    if (const auto* sphere = std::get_if<Sphere>(&shape)) return method.sphere(ray, *sphere);
    if (const auto* triangle = std::get_if<Triangle>(&shape)) {
        return method.triangle(ray, *triangle);
    }
    return method.plane(ray, std::get<Plane>(shape));
}

// closest_hit over the case's primitives, gathered by kind into a PrimitiveList; its answer is
// mapped back to the case's own numbering.
void run_closest_hit(const RayCase& ray_case, CaseAnswer& answer) {
    PrimitiveList list;
    std::vector<std::size_t> sphere_at;  // sphere_at[i]: the case index of list.spheres[i]
    std::vector<std::size_t> triangle_at;
    std::vector<std::size_t> plane_at;
    for (std::size_t k = 0; k < ray_case.primitives.size(); ++k) {
        const CaseShape& shape = ray_case.primitives[k].shape;
        if (const auto* sphere = std::get_if<Sphere>(&shape)) {
            list.spheres.push_back(*sphere);
            sphere_at.push_back(k);
        } else if (const auto* triangle = std::get_if<Triangle>(&shape)) {
            list.triangles.push_back(*triangle);
            triangle_at.push_back(k);
        } else {
            list.planes.push_back(std::get<Plane>(shape));
            plane_at.push_back(k);
        }
    }

    const std::optional<PrimitiveHit> found = closest_hit(ray_case.ray, list);
    if (!found) return;
    const bool sphere = found->kind == PrimitiveKind::sphere;
    const bool triangle = found->kind == PrimitiveKind::triangle;
    const std::vector<std::size_t>& case_index = sphere     ? sphere_at
                                                 : triangle ? triangle_at
                                                            : plane_at;
    // An index past the list is a wrong answer that must not crash the check.
    if (found->index >= case_index.size()) {
        const char* kind = sphere ? "sphere" : triangle ? "triangle" : "plane";
        throw std::out_of_range("closest_hit returned " + std::string(kind) + " " +
                                std::to_string(found->index) + " of a list of " +
                                std::to_string(case_index.size()) + " " + kind + "s");
    }
    answer.closest_primitive = case_index[found->index];
    answer.closest_hit = found->hit;
}

// An empty error means that the method returned normally, so an exception never leaves one.
std::string message_of(const std::exception& error) {
    const std::string message = error.what();
    return message.empty() ? "an exception with an empty message" : message;
}

}  // namespace

std::vector<Stage3Method> stage3_methods() {
    using Kind = Stage3Method::Kind;
    // Each entry: name, kind, then the sphere, triangle and plane functions, of which only the
    // one of its kind is set.
    return {
        {"intersect_plane", Kind::plane, nullptr, nullptr, intersect_plane},
        {"intersect_triangle_projection", Kind::triangle, nullptr, intersect_triangle_projection},
        {"intersect_triangle_halfspaces", Kind::triangle, nullptr, intersect_triangle_halfspaces},
        {"intersect_triangle_cramer", Kind::triangle, nullptr, intersect_triangle_cramer},
        {"intersect_triangle", Kind::triangle, nullptr, intersect_triangle},
        {"intersect_sphere", Kind::sphere, intersect_sphere},
        {"closest_hit", Kind::closest},
    };
}

CaseAnswer run_method(const Stage3Method& method, const RayCase& ray_case) {
    CaseAnswer answer;
    answer.hits.resize(ray_case.primitives.size());
    // The code under check is anyone's: whatever it throws becomes part of its answer.
    try {
        if (method.kind == Stage3Method::Kind::closest) {
            run_closest_hit(ray_case, answer);
        } else {
            for (std::size_t k = 0; k < ray_case.primitives.size(); ++k) {
                const CaseShape& shape = ray_case.primitives[k].shape;
                if (applies_to(method, shape)) {
                    answer.hits[k] = test_primitive(method, ray_case.ray, shape);
                }
            }
        }
    } catch (const NotImplemented& stub) {
        answer.not_implemented = true;
        answer.error = message_of(stub);
    } catch (const std::exception& error) {
        answer.error = message_of(error);
    } catch (...) {
        answer.error = "an exception that is not a std::exception";
    }
    return answer;
}

}  // namespace raystep
