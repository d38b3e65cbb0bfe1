#pragma once

#include <vector>

#include "base/scene/shapes.h"

namespace raystep {

/// The growth table's mesh: a torus around the y axis (radius 1 to the tube's centre, tube
/// radius 0.3) with its tube radius displaced by a fixed sum of sines, up to +-35%, so that the
/// triangles lean every way and bunch unevenly, as in a scanned model, and a hierarchy over them
/// has real choices to make. `rings` steps around the y axis times `segments` steps around the
/// tube, each quad split in two: 2 rings segments triangles, ring after ring.
std::vector<Triangle> bumpy_torus(int rings, int segments);

}  // namespace raystep
