// Stage 9: entering and leaving solids. Handout: docs/stage9.md.

#include "base/errors/not_implemented.h"
#include "stages/9_refraction/refraction.h"

namespace raystep {

double current_index(const MediumStack& inside) {
    // The index of the last solid entered; air (1) when the stack is empty.
    RAYSTEP_TODO(9, "current_index", "Entering and leaving");
}

MediumStack after_crossing(const MediumStack& inside, const Medium& solid, bool entering) {
    // Entering: append the solid. Leaving: remove it (the latest entry of that solid), and
    // change nothing when the stack does not hold it.
    RAYSTEP_TODO(9, "after_crossing", "Entering and leaving");
}

}  // namespace raystep
