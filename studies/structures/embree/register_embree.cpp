// Registers Embree as the bench's baseline. Linked, as an object, only into raystep-reference:
// the student-facing raystep never links Embree.

#include <memory>
#include <string>

#include "studies/structures/baseline_registry.h"
#include "studies/structures/embree/embree_device.h"
#include "studies/structures/embree/embree_scene.h"

namespace raystep {

namespace {

// Embree held to the instruction set `isa` (its device option max_isa), or at its best when
// `isa` is empty.
BenchCandidate embree_candidate(const std::string& isa) {
    BenchCandidate candidate;
    candidate.name = std::string("Embree ") + RTC_VERSION_STRING;
    if (!isa.empty()) candidate.name += " (max_isa=" + isa + ")";
    candidate.isa = isa;
    candidate.baseline = true;
    // Embree as it is used: its builds on every hardware thread
    candidate.make = [isa](const PrimitiveList& primitives) {
        return std::make_unique<EmbreeScene>(embree_device(0, isa), primitives);
    };
    candidate.make_single_threaded = [isa](const PrimitiveList& primitives) {
        return std::make_unique<EmbreeScene>(embree_device(1, isa), primitives);
    };
    candidate.held_to = embree_candidate;
    return candidate;
}

const BaselineRegistry::Registration registration(embree_candidate(""));

}  // namespace

}  // namespace raystep
