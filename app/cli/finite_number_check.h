#pragma once

#include <functional>
#include <string>

#include <CLI/CLI.hpp>

namespace raystep {

/// A CLI11 check of an option's number: the whole text a finite number (strtod's syntax) that
/// `accept` takes, any finite one where `accept` is empty. Otherwise the option is refused with
/// `problem` and the text: "the offset distance must be a number above 0, not '0'". `name` is
/// what CLI11's help shows for the value ("EPSILON").
CLI::Validator finite_number_check(std::string name, std::string problem,
                                   std::function<bool(double)> accept = {});

}  // namespace raystep
