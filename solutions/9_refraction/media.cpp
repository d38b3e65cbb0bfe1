// Stage 9 reference solution: the solids a ray is inside.

#include <algorithm>

#include "stages/9_refraction/refraction.h"

namespace raystep {

double current_index(const MediumStack& inside) {
    return inside.empty() ? 1.0 : inside.back().index;
}

MediumStack after_crossing(const MediumStack& inside, const Medium& solid, bool entering) {
    MediumStack after = inside;
    if (entering) {
        after.push_back(solid);
        return after;
    }
    // The most recent entry of this solid: a ray that entered it twice (rounding at a seam)
    // leaves it once.
    const auto match = std::find_if(after.rbegin(), after.rend(), [&](const Medium& medium) {
        return medium.solid == solid.solid;
    });
    if (match != after.rend()) after.erase(std::next(match).base());
    return after;
}

}  // namespace raystep
