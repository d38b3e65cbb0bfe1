#include "app/protocol/wide_json.h"

#include <cmath>
#include <stdexcept>

namespace raystep::probe {

Json wide(Wide x) {
    const double hi = static_cast<double>(x);
    // Subtracting an infinite or NaN hi would give NaN: such a value is its hi alone.
    const double lo = std::isfinite(hi) ? static_cast<double>(x - hi) : 0.0;
    return Json::array({number(hi), number(lo)});
}

Wide wide_from(const Json& j) {
    if (!j.is_array() || j.size() != 2) {
        throw std::invalid_argument("expected a long double as the pair [hi, lo]");
    }
    const double hi = number_from(j[0]);
    const double lo = number_from(j[1]);
    // -0 + 0 is +0: a zero rest adds nothing, and adding it would lose a negative zero's sign.
    return lo == 0 ? Wide(hi) : Wide(hi) + Wide(lo);
}

Json wide_vec3(const WideVec& v) {
    return Json::array({wide(v.x), wide(v.y), wide(v.z)});
}

WideVec wide_vec3_from(const Json& j) {
    if (!j.is_array() || j.size() != 3) {
        throw std::invalid_argument("expected a long-double vector as three [hi, lo] pairs");
    }
    return {wide_from(j[0]), wide_from(j[1]), wide_from(j[2])};
}

Json wide_mat4(const WideMat& m) {
    Json entries = Json::array();
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r)
            entries.push_back(wide(m[c][r]));
    }
    return entries;
}

WideMat wide_mat4_from(const Json& j) {
    if (!j.is_array() || j.size() != 16) {
        throw std::invalid_argument("expected a long-double matrix as sixteen [hi, lo] pairs");
    }
    WideMat m;
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r)
            m[c][r] = wide_from(j[4 * c + r]);
    }
    return m;
}

}  // namespace raystep::probe
