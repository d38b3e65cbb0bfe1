#pragma once

#include <cstddef>
#include <string>

namespace raystep {

// How the bench's tables write numbers.

/// n with its thousands separated by commas: 1,212,528.
std::string grouped(std::size_t n);

/// x with `decimals` digits after the point.
std::string fixed(double x, int decimals);

/// x with three significant digits and no exponent, for throughputs and times that span orders
/// of magnitude: 1234, 123, 12.3, 1.23, 0.123, 0.0123.
std::string three_digits(double x);

}  // namespace raystep
