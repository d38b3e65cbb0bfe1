#include "grader/grade/build_locations.h"

namespace raystep::grade {

std::filesystem::path built_probe_toolchain() {
    return RAYSTEP_PROBE_TOOLCHAIN;
}

std::filesystem::path built_unpack_program() {
    return RAYSTEP_UNPACK_PROGRAM;
}

std::filesystem::path built_reference_probe() {
    return RAYSTEP_REFERENCE_PROBE;
}

std::filesystem::path built_rubric() {
    return RAYSTEP_RUBRIC;
}

std::filesystem::path built_pareto_reference() {
    return RAYSTEP_PARETO_REFERENCE;
}

std::string built_chart_python() {
    return RAYSTEP_CHART_PYTHON;
}

std::filesystem::path built_chart_script() {
    return RAYSTEP_DRAW_CHARTS;
}

}  // namespace raystep::grade
