// Vertices at exactly the same position merged into one: what a file that
// splits its vertices along seams (a PLY export with per-vertex texture
// coordinates, a triangle soup) needs before it is coded, so that the
// triangles share vertices again and no crack opens between copies that
// would be reconstructed apart. The data that differed between the copies
// stays, per corner.
#pragma once

#include <cstdint>
#include <vector>

#include "gab/mesh/mesh.h"

namespace gab {

// Merges the vertices of `mesh` with equal coordinates (compared exactly)
// into one, numbered by their first copy's index, into *welded; triangles
// keep their order and corners (a triangle may become degenerate).
// Per-vertex attributes become per-corner, each corner keeping its own
// copy's value (the codec codes a per-corner attribute without seams per
// vertex). Sets new_index[v] (the merged vertex of input vertex v) and
// returns the vertices removed. Returns 0 and leaves *welded and *new_index
// alone when no two vertices coincide, or when a vertex in no triangle
// carries per-vertex attributes (a per-corner value could not keep it).
// O(V log V + T).
int32_t weld_coincident_vertices(const Mesh& mesh, Mesh* welded, std::vector<int32_t>* new_index);

}  // namespace gab
