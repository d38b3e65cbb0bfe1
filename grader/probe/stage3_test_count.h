#pragma once

#include <cstdint>

namespace raystep::probe {

/// How many primitive tests this thread has made through stage 3's public functions since the
/// probe began: one per intersect_sphere, intersect_plane or triangle test, and one per primitive
/// of the list for each closest_hit (a brute-force search is that many tests). Tests that stage 3
/// makes inside its own functions are not counted again. Only ever grows: a query's cost is the
/// difference between readings before and after it, and a submission has nothing to lower it with.
std::uint64_t stage3_tests_counted();

}  // namespace raystep::probe
