// The mesh `gab demo` uses when no real one is at hand: a bumpy sphere
// (subdivided icosahedron, radius modulated by a few smooth waves), so the
// demo always runs, even on a machine without libcgal-demo.
#pragma once

#include "gab/mesh/mesh.h"

namespace gab {
namespace cli {

// About 10 * 4^levels + 2 vertices. O(output size).
Mesh bumpy_sphere(int levels);

}  // namespace cli
}  // namespace gab
