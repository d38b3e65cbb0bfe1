#include "grading/9_refraction/refraction_json.h"

#include <limits>
#include <stdexcept>

namespace raystep::probe {

namespace {

// A solid's number as the renderer numbers it: a whole number that fits 32 bits, nothing else.
std::uint32_t solid_from(const Json& j) {
    if (!j.is_number_unsigned() ||
        j.get<std::uint64_t>() > std::numeric_limits<std::uint32_t>::max())
        throw std::invalid_argument("expected a solid's number, a whole number below 2^32");
    return j.get<std::uint32_t>();
}

}  // namespace

Json medium(const Medium& m) {
    return {{"solid", m.solid}, {"index", number(m.index)}};
}

Medium medium_from(const Json& j) {
    return {solid_from(field(j, "solid")), number_from(field(j, "index"))};
}

Json media(const MediumStack& stack) {
    Json list = Json::array();
    for (const Medium& m : stack)
        list.push_back(medium(m));
    return list;
}

MediumStack media_from(const Json& j) {
    if (!j.is_array()) throw std::invalid_argument("expected a list of media");
    MediumStack stack;
    for (const Json& m : j)
        stack.push_back(medium_from(m));
    return stack;
}

Json medium_hit(const MediumHit& hit) {
    return {{"point", surface_point(hit.shaded.point)},
            {"local", vec3(hit.shaded.local)},
            {"reflectance", vec3(hit.shaded.reflectance)},
            {"transmission", vec3(hit.transmission)},
            {"solid", medium(hit.solid)},
            {"entering", hit.entering}};
}

MediumHit medium_hit_from(const Json& j) {
    const Json& entering = field(j, "entering");
    if (!entering.is_boolean()) throw std::invalid_argument("expected \"entering\" true or false");
    return {{surface_point_from(field(j, "point")), vec3_from(field(j, "local")),
             vec3_from(field(j, "reflectance"))},
            vec3_from(field(j, "transmission")),
            medium_from(field(j, "solid")),
            entering.get<bool>()};
}

}  // namespace raystep::probe
