// 1:4 midpoint subdivision: every triangle becomes four, a new vertex at the
// midpoint of every edge. Used to grow a mesh at fixed shape (study of how
// update costs scale with n).
#pragma once

#include "gab/mesh/mesh.h"

namespace gab {

// Subdivides `levels` times; vertex i of the input stays vertex i. Each level
// multiplies the triangle count by 4 and adds one vertex per edge. Degenerate
// triangles subdivide into degenerate ones. O(output size) per level.
Mesh subdivide_midpoint(const Mesh& mesh, int levels);

}  // namespace gab
