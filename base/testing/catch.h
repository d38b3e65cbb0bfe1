#pragma once

// Catch2 v2 is Debian's; Homebrew and vcpkg ship v3. Tests include this header so they build
// with either, and so that a Vec3 prints as its exact components (number_text.h) in every test:
// a specialization of StringMaker must come before any check that prints a Vec3, whatever order a
// unity build joins the test files in, or those checks print "{?}".
#if __has_include(<catch2/catch_all.hpp>)
#include <catch2/catch_all.hpp>
using Catch::Approx;
namespace raystep::testing {
template <class T>
using MatcherBase = Catch::Matchers::MatcherBase<T>;
}
#else
#include <catch2/catch.hpp>
namespace raystep::testing {
template <class T>
using MatcherBase = Catch::MatcherBase<T>;
}
#endif

#include "base/math/types.h"
#include "base/testing/number_text.h"

namespace Catch {
template <>
struct StringMaker<raystep::Vec3> {
    static std::string convert(const raystep::Vec3& v) { return raystep::testing::exact_text(v); }
};
}  // namespace Catch
