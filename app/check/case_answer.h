#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "stages/3_intersect/hit.h"

namespace raystep {

/// What one method under check said about one case: the untrusted half of a check. A probe
/// produces these; the trusted side scores them against the expectations (case_scoring.h).
struct CaseAnswer {
    /// Primitive tests: one entry per primitive of the case, in case order; nullopt where the
    /// method reported a miss or does not test that kind of primitive.
    std::vector<std::optional<Hit>> hits;
    /// closest_hit: the primitive it chose, as an index into the case's primitives, and its hit;
    /// nullopt for a miss.
    std::optional<std::size_t> closest_primitive;
    std::optional<Hit> closest_hit;
    /// The method threw: NotImplemented (a stub), or anything else (a std::domain_error, say).
    bool not_implemented = false;
    std::string error;  ///< the exception's message; empty when it returned normally
};

}  // namespace raystep
