#include "app/protocol/wide_json.h"

#include <cmath>
#include <stdexcept>

namespace raystep::probe {

Json wide(const DoubleDouble& x) {
    return Json::array({number(x.hi), number(x.lo)});
}

DoubleDouble wide_from(const Json& j) {
    if (!j.is_array() || j.size() != 2) {
        throw std::invalid_argument("expected a double-double as the pair [hi, lo]");
    }
    const double hi = number_from(j[0]);
    const double lo = number_from(j[1]);
    if (!std::isfinite(lo)) {
        throw std::invalid_argument("expected a double-double's rest lo to be finite");
    }
    // An infinite or NaN hi is the value alone; a zero rest adds nothing, and adding it would lose
    // a negative zero's sign (-0 + 0 is +0).
    if (!std::isfinite(hi) || lo == 0) return DoubleDouble(hi);
    return two_sum(hi, lo);
}

Json wide_vec3(const DoubleDoubleVec3& v) {
    return Json::array({wide(v.x), wide(v.y), wide(v.z)});
}

DoubleDoubleVec3 wide_vec3_from(const Json& j) {
    if (!j.is_array() || j.size() != 3) {
        throw std::invalid_argument("expected a double-double vector as three [hi, lo] pairs");
    }
    return {wide_from(j[0]), wide_from(j[1]), wide_from(j[2])};
}

Json wide_mat4(const DoubleDoubleMat4& m) {
    Json entries = Json::array();
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r)
            entries.push_back(wide(m[c][r]));
    }
    return entries;
}

DoubleDoubleMat4 wide_mat4_from(const Json& j) {
    if (!j.is_array() || j.size() != 16) {
        throw std::invalid_argument("expected a double-double matrix as sixteen [hi, lo] pairs");
    }
    DoubleDoubleMat4 m;
    for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r)
            m[c][r] = wide_from(j[4 * c + r]);
    }
    return m;
}

}  // namespace raystep::probe
