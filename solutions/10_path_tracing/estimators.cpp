// Stage 10 reference solution: multiple importance sampling's weights and Russian roulette.

#include <algorithm>

#include "stages/10_path_tracing/path_tracing.h"

namespace raystep {

// Both heuristics divide through by pdf: 1 / (1 + r) and 1 / (1 + r^2), r = other / pdf, which
// no density overflows (an infinite other_pdf gives 0, an infinite pdf 1).

double balance_heuristic(double pdf, double other_pdf) {
    if (!(pdf > 0.0)) return 0.0;
    return 1.0 / (1.0 + other_pdf / pdf);
}

double power_heuristic(double pdf, double other_pdf) {
    if (!(pdf > 0.0)) return 0.0;
    const double ratio = other_pdf / pdf;
    return 1.0 / (1.0 + ratio * ratio);
}

std::optional<Color> russian_roulette(const Color& throughput, double u) {
    const double survival = std::min(1.0, std::max({throughput.x, throughput.y, throughput.z}));
    if (!(u < survival)) return std::nullopt;
    return throughput / survival;
}

}  // namespace raystep
