#pragma once

// How tests compare vectors: a failed check shows both vectors exactly (catch.h prints a Vec3 by
// number_text.h) and the tolerance at its size, instead of "false".

#include <algorithm>
#include <string>

#include <glm/geometric.hpp>

#include "base/math/types.h"
#include "base/testing/catch.h"
#include "base/testing/number_text.h"

namespace raystep::testing {

/// Matches vectors within `tolerance` of `expected`, measured as |got - expected| relative to
/// max(1, |expected|).
class NearVec3 : public MatcherBase<Vec3> {
  public:
    NearVec3(const Vec3& expected, double tolerance) : expected_(expected), tolerance_(tolerance) {}

    bool match(const Vec3& got) const override {
        return glm::length(got - expected_) <= tolerance_ * scale();  // false for NaN
    }

    /// "is within 1e-15 of (0, 0, 1)": the distance the tolerance allows, scaled by |expected|
    /// above 1 ("is within 1.3e-13 of (3, 4, 12)" for 1e-14).
    std::string describe() const override {
        return "is within " + size_text(tolerance_ * scale()) + " of " + exact_text(expected_);
    }

  private:
    double scale() const { return std::max(1.0, glm::length(expected_)); }

    Vec3 expected_;
    double tolerance_;
};

inline NearVec3 IsNear(const Vec3& expected, double tolerance) {
    return {expected, tolerance};
}

}  // namespace raystep::testing
