#pragma once

#include <string>

namespace raystep {

/// `raystep bench --sampling [--quick] [--json FILE]`: measures the sampling noise study
/// (noise_measure.h) through this program's stages, prints a table per scene and the study's
/// findings (noise_findings), and with a file writes noise_json there. Returns 0 when
/// every finding holds, 1 when one does not (the sampling code is wrong, or the study is); a
/// stub's NotImplemented and a missing scene propagate.
int run_noise_study(bool quick, const std::string& json_path);

}  // namespace raystep
