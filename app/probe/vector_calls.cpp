// Stage 1 calls: each vector function on the vectors given.

#include "app/probe/call_table.h"
#include "stages/1_vectors/vectors.h"

namespace raystep::probe {

namespace {

Vec3 argument(const Json& arguments, std::size_t k) {
    return vec3_from(arguments.at(k));
}

}  // namespace

void add_vector_calls(CallTable& table) {
    table["dot"] = [](const Json& a) { return number(dot(argument(a, 0), argument(a, 1))); };
    table["cross"] = [](const Json& a) { return vec3(cross(argument(a, 0), argument(a, 1))); };
    table["length"] = [](const Json& a) { return number(length(argument(a, 0))); };
    table["normalize"] = [](const Json& a) { return vec3(normalize(argument(a, 0))); };
    table["reflect"] = [](const Json& a) { return vec3(reflect(argument(a, 0), argument(a, 1))); };
    table["project_onto"] = [](const Json& a) {
        return vec3(project_onto(argument(a, 0), argument(a, 1)));
    };
    table["perpendicular_to"] = [](const Json& a) {
        return vec3(perpendicular_to(argument(a, 0), argument(a, 1)));
    };
    table["orthonormal_frame"] = [](const Json& a) {
        const Frame f = orthonormal_frame(argument(a, 0), argument(a, 1));
        return Json{{"u", vec3(f.u)}, {"v", vec3(f.v)}, {"w", vec3(f.w)}};
    };
}

}  // namespace raystep::probe
