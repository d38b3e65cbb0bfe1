#pragma once

#include <filesystem>
#include <string>

namespace raystep::grade {

// Where this build keeps what a grade runs and reads beside raystep-grade, fixed when CMake
// configures. Only build_locations.cpp is compiled with these paths, outside the unity build: they
// differ between copies of the tree (the Gradescope test's autograder, unpacked under build/), and
// the files that hold none compile to the same object in every copy, which ccache then shares
// (scripts/use-ccache.sh).

/// probe-toolchain.json: how this build compiles and links a submission's probes.
std::filesystem::path built_probe_toolchain();

/// raystep-unpack, which reads a submission's bytes in the sandbox.
std::filesystem::path built_unpack_program();

/// The reference probe, which the speed checks time.
std::filesystem::path built_reference_probe();

/// The rubric a grade uses unless told another: grader/rubric/rubric.json.
std::filesystem::path built_rubric();

/// The reference's speed-against-error measurements the report's chart draws
/// (docs/measurements/pareto/pareto.json).
std::filesystem::path built_pareto_reference();

/// The Python that has matplotlib, chosen when CMake configured; empty where there is none.
std::string built_chart_python();

/// scripts/draw-charts.py, which draws every chart.
std::filesystem::path built_chart_script();

}  // namespace raystep::grade
