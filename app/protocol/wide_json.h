#pragma once

#include "app/protocol/probe_json.h"
#include "base/math/double_double_vec.h"

namespace raystep::probe {

// A double-double in JSON (base/math/double_double.h), for the expectations the grader's oracles
// decide with more bits than a double holds and a student release judges by
// (app/grade/data_judge.h): the pair [hi, lo] of doubles, each written with the digits that read
// back to it. Reading takes the same two doubles on every platform, so a release judges by the
// very number the grader does, bit for bit.

Json wide(const DoubleDouble& x);
/// The pair [hi, lo] as a double-double: hi + lo normalized by two_sum, which leaves a pair this
/// file wrote as it is. Throws std::invalid_argument for anything else, or a rest not finite.
DoubleDouble wide_from(const Json& j);

/// Three such pairs, x, y, z.
Json wide_vec3(const DoubleDoubleVec3& v);
DoubleDoubleVec3 wide_vec3_from(const Json& j);

/// Sixteen such pairs, column by column, as mat4 writes a double matrix.
Json wide_mat4(const DoubleDoubleMat4& m);
DoubleDoubleMat4 wide_mat4_from(const Json& j);

}  // namespace raystep::probe
