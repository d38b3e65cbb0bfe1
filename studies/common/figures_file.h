#pragma once

#include <filesystem>

#include <nlohmann/json_fwd.hpp>

namespace raystep {

/// Writes a study's figures to `path` as JSON, which scripts/draw-charts.py draws, and says on
/// stdout where they went and how to draw them. Throws std::runtime_error naming the file when it
/// cannot be written.
void write_figures(const std::filesystem::path& path, const nlohmann::json& figures);

}  // namespace raystep
