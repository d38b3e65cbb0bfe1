// Stage 10: a path, extended hit by hit. Handout: docs/stage10.md.

#include "base/errors/not_implemented.h"
#include "stages/10_path_tracing/path_tracing.h"

namespace raystep {

Color path_radiance(const Ray& ray, const PathScene& scene, const PathSettings& settings,
                    RandomStream& random) {
    // L = 0, throughput = 1. At each hit: L += weight throughput Le; stop after max_depth
    // bounces; add each light's sample (next event estimation); draw wi with density p;
    // throughput *= f cos / p; Russian roulette; follow wi.
    RAYSTEP_TODO(10, "path_radiance", "The path");
}

}  // namespace raystep
