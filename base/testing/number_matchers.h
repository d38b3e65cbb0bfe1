#pragma once

// How tests compare one number with a tolerance: a failed check shows the tolerance at its size
// and how far off the number was, where a plain `std::abs(x) <= 4e-16` prints as
// "0.0 <= 0.0" in Catch2's fixed notation (number_text.h).

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "base/testing/catch.h"
#include "base/testing/number_text.h"

namespace raystep::testing {

/// Matches numbers within `tolerance` of `expected`, measured as |got - expected| relative to
/// max(1, |expected|), as IsNear does for vectors.
class NearNumber : public MatcherBase<double> {
  public:
    NearNumber(double expected, double tolerance) : expected_(expected), tolerance_(tolerance) {}

    bool match(const double& got) const override {
        off_by_ = std::abs(got - expected_);
        return off_by_ <= tolerance_ * scale();  // false for NaN
    }

    /// "is within 4e-16 of 0, off by 1.1e-15": the distance the tolerance allows (scaled by
    /// |expected| above 1), and the one found. Catch prints the number itself before this, in
    /// fixed notation that shows 1.1e-15 as 0.0, so the distance is spelled out here.
    std::string describe() const override {
        std::string text =
            "is within " + size_text(tolerance_ * scale()) + " of " + exact_text(expected_);
        if (!std::isnan(off_by_)) text += ", off by " + size_text(off_by_);
        return text;
    }

  private:
    double scale() const { return std::max(1.0, std::abs(expected_)); }

    double expected_;
    double tolerance_;
    mutable double off_by_ = std::numeric_limits<double>::quiet_NaN();  ///< set by match()
};

inline NearNumber IsNear(double expected, double tolerance) {
    return {expected, tolerance};
}

}  // namespace raystep::testing
