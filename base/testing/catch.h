#pragma once

// Catch2 v2 is Debian's; Homebrew and vcpkg ship v3. Tests include this header so they build
// with either.
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
