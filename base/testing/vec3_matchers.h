#pragma once

// How tests compare and print vectors: a failed check shows both vectors in full precision
// instead of "{?}" or "false".

#include <cstdio>
#include <string>

#include <glm/geometric.hpp>

#include "base/math/types.h"
#include "base/testing/catch.h"

namespace Catch {
template <>
struct StringMaker<raystep::Vec3> {
    static std::string convert(const raystep::Vec3& v) {
        char text[96];
        std::snprintf(text, sizeof text, "(%.17g, %.17g, %.17g)", v.x, v.y, v.z);
        return text;
    }
};
}  // namespace Catch

namespace raystep::testing {

/// Matches vectors within `tolerance` of `expected`, measured as |got - expected| relative to
/// max(1, |expected|).
class NearVec3 : public MatcherBase<Vec3> {
  public:
    NearVec3(const Vec3& expected, double tolerance) : expected_(expected), tolerance_(tolerance) {}

    bool match(const Vec3& got) const override {
        const double scale = std::max(1.0, glm::length(expected_));
        return glm::length(got - expected_) <= tolerance_ * scale;  // false for NaN
    }

    std::string describe() const override {
        return "is within " + Catch::StringMaker<double>::convert(tolerance_) + " of " +
               Catch::StringMaker<Vec3>::convert(expected_);
    }

  private:
    Vec3 expected_;
    double tolerance_;
};

inline NearVec3 IsNear(const Vec3& expected, double tolerance) {
    return {expected, tolerance};
}

}  // namespace raystep::testing
