#include "studies/common/figures_file.h"

#include <cstdio>
#include <fstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

namespace raystep {

void write_figures(const std::filesystem::path& path, const nlohmann::json& figures) {
    std::ofstream file(path);
    file << figures.dump(2) << "\n";
    if (!file) throw std::runtime_error("could not write the figures to " + path.string());
    std::printf("- the figures: %s (scripts/draw-charts.py %s draws them)\n", path.string().c_str(),
                path.string().c_str());
}

}  // namespace raystep
