// A mesh under a new vertex numbering: what a decoder that numbers vertices
// its own way (a reordered .gab file) gives back.
#pragma once

#include <cstdint>
#include <vector>

#include "gab/mesh/mesh.h"

namespace gab {

// Vertex v of `mesh` becomes vertex new_index[v] (a permutation of
// 0..n-1): positions and per-vertex attributes move, triangle indices are
// renamed, triangle order and corner order (and so per-corner attributes) stay. O(V + T).
Mesh renumber_vertices(const Mesh& mesh, const std::vector<int32_t>& new_index);

}  // namespace gab
