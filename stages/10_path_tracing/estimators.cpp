// Stage 10: multiple importance sampling's weights and Russian roulette. Handout:
// docs/stage10.md.

#include "base/errors/not_implemented.h"
#include "stages/10_path_tracing/path_tracing.h"

namespace raystep {

double balance_heuristic(double pdf, double other_pdf) {
    // pdf / (pdf + other_pdf).
    RAYSTEP_TODO(10, "balance_heuristic", "Multiple importance sampling");
}

double power_heuristic(double pdf, double other_pdf) {
    // pdf^2 / (pdf^2 + other_pdf^2).
    RAYSTEP_TODO(10, "power_heuristic", "Multiple importance sampling");
}

std::optional<Color> russian_roulette(const Color& throughput, double u) {
    // q = min(1, max component); on with throughput / q when u < q.
    RAYSTEP_TODO(10, "russian_roulette", "Russian roulette");
}

}  // namespace raystep
