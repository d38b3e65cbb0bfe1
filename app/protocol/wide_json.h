#pragma once

#include "app/protocol/probe_json.h"
#include "base/math/wide_vec.h"

namespace raystep::probe {

// A long double in JSON, for the expectations the grader's long-double oracles decide and a
// student release judges by (app/grade/data_judge.h): written as the pair [hi, lo] of doubles,
// hi the value rounded to double and lo the rest rounded again. A long double has 64 mantissa
// bits and hi holds 53 of them, so the rest fits lo exactly and hi + lo, added in long double,
// is the value itself: the release judges by the very number the grader does. Where long double
// is a double (MSVC, arm64 macOS), hi + lo rounds to hi, the expectation to within half an ulp.

Json wide(Wide x);
Wide wide_from(const Json& j);

/// Three such pairs, x, y, z.
Json wide_vec3(const WideVec& v);
WideVec wide_vec3_from(const Json& j);

/// Sixteen such pairs, column by column, as mat4 writes a double matrix.
Json wide_mat4(const WideMat& m);
WideMat wide_mat4_from(const Json& j);

}  // namespace raystep::probe
