#pragma once

#include "base/scene/scene.h"

namespace raystep::grade {

// The light and the surface stage 8's shading checks sample (stage8_mean_statistics.cpp,
// stage8_film_light_statistics.cpp): a 2 x 2 light 2 above the floor y = 0, facing down, over a
// surface with a diffuse and a specular term, so that where a light sample falls changes the
// colour it adds.

inline const QuadLight kShadingCheckLight{{-1, 2, -1}, {0, 0, 2}, {2, 0, 0}, {5, 2.5, 1.25}, 0};

inline Material shading_check_material() {
    Material m;
    m.diffuse = {0.6, 0.5, 0.4};
    m.specular = {0.3, 0.3, 0.3};
    m.shininess = 20;
    return m;
}

}  // namespace raystep::grade
