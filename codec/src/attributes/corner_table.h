// The corners of a decoded mesh as the attribute sections walk them
// (docs/format.md 6.2): each vertex's corners, the corner across each edge
// at the same vertex, and the order vertices are visited in. Built alike by
// encoder and decoder from the triangles alone. Internal to the codec.
#pragma once

#include <cstdint>
#include <vector>

namespace gab {

struct CornerTable {
  // Corner c is corner c % 3 of triangle c / 3; next(c) and prev(c) the
  // triangle's other two, in its orientation.
  static int32_t next(int32_t c) { return c % 3 == 2 ? c - 2 : c + 1; }
  static int32_t prev(int32_t c) { return c % 3 == 0 ? c + 2 : c - 1; }

  int32_t num_vertices = 0;
  const std::vector<int32_t>* triangles = nullptr;  // the mesh's, not copied
  // Vertex v's corners, increasing: corners[corner_offsets[v] .. corner_offsets[v + 1]).
  std::vector<int32_t> corner_offsets, corners;
  // The corner at the same vertex across the edge from corner c's vertex to
  // next(c)'s: in the one triangle holding that edge the other way, when
  // exactly one triangle holds it each way; -1 otherwise (a boundary or a
  // non-manifold edge).
  std::vector<int32_t> across;
  // Vertices in the order they first appear in the triangles, then those in
  // no triangle, increasing; rank[v] its position.
  std::vector<int32_t> visit, rank;

  int32_t vertex(int32_t c) const { return (*triangles)[c]; }
};

// The table of an n-vertex mesh (indices in [0, n), checked by the caller).
// O(n + T log(degree)).
CornerTable build_corner_table(int32_t n, const std::vector<int32_t>& triangles);

}  // namespace gab
