#pragma once

#include <string>

#include <CLI/CLI.hpp>

namespace raystep {

/// `raystep compare IMAGE [REFERENCE] [-o HEATMAP] [--view VIEW]`, or
/// `raystep compare --scene SCENE [--view VIEW] [-o HEATMAP]` to render and compare in one go.
struct CompareArguments {
    std::string image;
    std::string reference;  ///< empty: the shipped reference for the image (reference_image.h)
    std::string scene;
    std::string view;  ///< with --scene: the scene's reference view when it has only one
    std::string heat_map;
};

CLI::App* add_compare_command(CLI::App& app, CompareArguments& arguments);

/// Prints the metrics and the verdict by the grader's rule, and writes the heat map: 0 when the
/// render passes, 1 when it does not (a different size included). Bad input (a missing or
/// unreadable image, no reference) throws; main gives it exit code 2, so that 1 always means a
/// render that fails.
int run_compare(const CompareArguments& arguments);

}  // namespace raystep
