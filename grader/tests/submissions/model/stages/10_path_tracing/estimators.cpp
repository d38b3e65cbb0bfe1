// Stage 10: multiple importance sampling's weights and Russian roulette. Handout: docs/stage10.md.

#include <algorithm>

#include "stages/10_path_tracing/path_tracing.h"

namespace raystep {

double balance_heuristic(double pdf, double other_pdf) {
    if (pdf <= 0.0) return 0.0;
    return pdf / (pdf + other_pdf);
}

double power_heuristic(double pdf, double other_pdf) {
    if (pdf <= 0.0) return 0.0;
    // Divided through by pdf^2, so that no square overflows.
    const double ratio = other_pdf / pdf;
    return 1.0 / (1.0 + ratio * ratio);
}

std::optional<Color> russian_roulette(const Color& throughput, double u) {
    const double survival = std::min(1.0, std::max({throughput.x, throughput.y, throughput.z}));
    if (!(u < survival)) return std::nullopt;
    return throughput / survival;
}

}  // namespace raystep
