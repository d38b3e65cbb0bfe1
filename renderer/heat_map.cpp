#include "renderer/heat_map.h"

#include <algorithm>

namespace raystep {

Color heat_colour(double fraction) {
    static const Color kStops[] = {
        {0, 0, 0}, {0.1, 0.1, 0.8}, {0.9, 0.1, 0.1}, {1, 0.9, 0}, {1, 1, 1}};
    const double x = std::clamp(fraction, 0.0, 1.0) * 4.0;
    const int k = std::min(3, static_cast<int>(x));
    return kStops[k] + (x - k) * (kStops[k + 1] - kStops[k]);
}

}  // namespace raystep
