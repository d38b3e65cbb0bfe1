// Registers Embree as the bench's baseline. Linked, as an object, only into raystep-reference:
// the student-facing raystep never links Embree.

#include <memory>
#include <string>

#include "core/bench/baseline_registry.h"
#include "grader/embree/embree_device.h"
#include "grader/embree/embree_scene.h"

namespace raystep {

namespace {

BenchCandidate embree_candidate() {
    BenchCandidate candidate;
    candidate.name = std::string("Embree ") + RTC_VERSION_STRING;
    // Embree as it is used: its builds on every hardware thread
    candidate.make = [](const PrimitiveList& primitives) {
        return std::make_unique<EmbreeScene>(embree_device(0), primitives);
    };
    candidate.make_single_threaded = [](const PrimitiveList& primitives) {
        return std::make_unique<EmbreeScene>(embree_device(1), primitives);
    };
    return candidate;
}

const BaselineRegistration registration(embree_candidate());

}  // namespace

}  // namespace raystep
