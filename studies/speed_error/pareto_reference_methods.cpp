#include "studies/speed_error/pareto_reference_methods.h"

#include "solutions/3_intersect/intersect_methods.h"
#include "solutions/3_intersect/single_precision.h"

namespace raystep {

namespace {

using TriangleTest = std::optional<Hit> (*)(const Ray&, const Triangle&);
using SphereTest = std::optional<Hit> (*)(const Ray&, const Sphere&);
using PlaneTest = std::optional<Hit> (*)(const Ray&, const Plane&);

ParetoMethod triangle_method(const char* name, const char* label, const char* precision,
                             TriangleTest test) {
    ParetoMethod entry{{name, Stage3Method::Kind::triangle}, label, precision};
    entry.method.triangle = test;
    return entry;
}

ParetoMethod plane_method(const char* name, const char* label, const char* precision,
                          PlaneTest test) {
    ParetoMethod entry{{name, Stage3Method::Kind::plane}, label, precision};
    entry.method.plane = test;
    return entry;
}

ParetoMethod sphere_method(const char* name, const char* label, const char* precision,
                           SphereTest test) {
    ParetoMethod entry{{name, Stage3Method::Kind::sphere}, label, precision};
    entry.method.sphere = test;
    return entry;
}

}  // namespace

std::vector<ParetoMethod> reference_pareto_methods() {
    return {
        triangle_method("intersect_triangle_projection", "projection", "double",
                        intersect_triangle_projection),
        triangle_method("intersect_triangle_projection_float", "projection", "float",
                        intersect_triangle_projection_float),
        triangle_method("intersect_triangle_halfspaces", "half-spaces", "double",
                        intersect_triangle_halfspaces),
        triangle_method("intersect_triangle_halfspaces_float", "half-spaces", "float",
                        intersect_triangle_halfspaces_float),
        triangle_method("intersect_triangle_cramer", "Cramer", "double", intersect_triangle_cramer),
        triangle_method("intersect_triangle_cramer_float", "Cramer", "float",
                        intersect_triangle_cramer_float),
        triangle_method("intersect_triangle_moller_trumbore", "Moller-Trumbore", "double",
                        intersect_triangle_moller_trumbore),
        triangle_method("intersect_triangle_moller_trumbore_float", "Moller-Trumbore", "float",
                        intersect_triangle_moller_trumbore_float),
        triangle_method("intersect_triangle_watertight", "watertight", "double",
                        intersect_triangle_watertight),
        triangle_method("intersect_triangle_watertight_float", "watertight", "float",
                        intersect_triangle_watertight_float),
        sphere_method("intersect_sphere_textbook", "textbook sphere", "double",
                      intersect_sphere_textbook),
        sphere_method("intersect_sphere_textbook_float", "textbook sphere", "float",
                      intersect_sphere_textbook_float),
        sphere_method("intersect_sphere_stable_roots", "stable roots", "double",
                      intersect_sphere_stable_roots),
        sphere_method("intersect_sphere_stable_roots_float", "stable roots", "float",
                      intersect_sphere_stable_roots_float),
        sphere_method("intersect_sphere", "stable sphere", "double", intersect_sphere),
        sphere_method("intersect_sphere_float", "stable sphere", "float", intersect_sphere_float),
        plane_method("intersect_plane", "plane", "double", intersect_plane),
        plane_method("intersect_plane_float", "plane", "float", intersect_plane_float),
    };
}

}  // namespace raystep
