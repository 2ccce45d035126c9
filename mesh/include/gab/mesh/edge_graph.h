// The edge graph of a triangle mesh (CSR, deduplicated, no self loops) and
// its connected components. Isolated vertices are components of their own.
#pragma once

#include <cstdint>
#include <vector>

#include "gab/mesh/mesh.h"

namespace gab {

struct EdgeGraph {
  std::vector<int32_t> offsets;    // num_vertices + 1
  std::vector<int32_t> neighbors;  // sorted within each vertex

  int32_t num_vertices() const { return static_cast<int32_t>(offsets.size()) - 1; }
  int32_t degree(int32_t v) const { return offsets[v + 1] - offsets[v]; }
};

// Edges of every triangle, duplicates and degenerate (repeated-vertex)
// edges removed. O(triangles + vertices).
EdgeGraph build_edge_graph(const Mesh& mesh);
// The same from the triangles (3 indices each, in [0, num_vertices)) alone.
EdgeGraph build_edge_graph(int32_t num_vertices, const std::vector<int32_t>& triangles);

// component[v] in 0..count-1, numbered by smallest vertex. O(V + E).
std::vector<int32_t> connected_components(const EdgeGraph& graph, int32_t* count);

}  // namespace gab
