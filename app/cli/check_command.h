#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace raystep {

/// `raystep check --stage 3 [FILE...] [--family NAME] [--method NAME] [--case N]`
struct CheckArguments {
    int stage = 0;
    std::vector<std::string> files;  ///< case files; none means the stage's cases/ folder
    std::string family;              ///< empty: every family
    std::string method;              ///< empty: every method
    std::int64_t case_index = -1;    ///< -1: every case
};

/// Adds the `check` subcommand to `app`; parsing fills `arguments`. --stage other than 3 and an
/// unknown --method are command-line errors (exit 2), listing what is accepted.
CLI::App* add_check_command(CLI::App& app, CheckArguments& arguments);

/// Runs the selected methods on the selected cases and prints the report; with --case, also each
/// primitive's expectation beside each method's answer. Exit code 0 when every scored case passed
/// and no method is a stub, 1 otherwise. Throws InputError for a bad case file, and
/// std::runtime_error when there are no case files or a filter selects nothing.
int run_check(const CheckArguments& arguments);

}  // namespace raystep
