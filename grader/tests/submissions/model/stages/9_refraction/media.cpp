// Stage 9: the solids a ray is inside. Handout: docs/stage9.md.

#include "stages/9_refraction/refraction.h"

namespace raystep {

double current_index(const MediumStack& inside) {
    if (inside.empty()) return 1.0;
    return inside.back().index;
}

MediumStack after_crossing(const MediumStack& inside, const Medium& solid, bool entering) {
    MediumStack after = inside;
    if (entering) {
        after.push_back(solid);
        return after;
    }
    // Leave the last entry of this solid, wherever it sits: another solid entered later (an
    // overlap) stays.
    for (auto it = after.end(); it != after.begin();) {
        --it;
        if (it->solid == solid.solid) {
            after.erase(it);
            break;
        }
    }
    return after;
}

}  // namespace raystep
