// What the detail layer (gab_format.h, flag "detail") reads of the
// connectivity, built the same way by the encoder and the decoder from the
// triangles both hold: the order in which the layer visits the vertices, and
// at each step what is decoded around the vertex.
//
// The order is a maximum cardinality search on the edge graph (Tarjan &
// Yannakakis 1984): the next vertex is one with the most decoded neighbours,
// the longest waiting among those (first in, first out per count), and a
// component's first vertex is its smallest not yet visited. The walk grows
// a compact front, so that almost every vertex finds three decoded
// neighbours and two parallelograms (on igea 96% of them); a breadth-first
// walk over triangles, which mostly gives one parallelogram, coded 4.5%
// larger on igea and 2.4% on horse at 1e-4. Everything is integer: both
// sides get the same order. Internal to the codec.
#pragma once

#include <cstdint>
#include <vector>

#include "gab/mesh/edge_graph.h"

namespace gab {

// At most this many parallelograms per vertex (the first found): a manifold
// vertex has at most one per triangle, and non-manifold fans (a forged
// triangle list) must not make the lists quadratic.
constexpr int32_t kMaxParallelograms = 16;

struct DetailTopology {
  int32_t num_vertices = 0;
  const std::vector<int32_t>* triangles = nullptr;  // 3 per triangle, owned by the caller
  std::vector<int32_t> order;  // every vertex once: the visiting order
  // Step i (vertex order[i]): parallelograms [parallelogram_offsets[i],
  // parallelogram_offsets[i + 1]) of `parallelograms`, 3 vertices a, b, c
  // each (the rule's a + b - c: a triangle (v, a, b) of the vertex and a
  // triangle (a, b, c) across ab, all three decoded). The first is the
  // one whose a or b was decoded earliest: its edge orients the residual's
  // frame (detail_predictor.h).
  std::vector<int32_t> parallelogram_offsets, parallelograms;
  // Step i: the vertex's decoded neighbours [known_offsets[i], known_offsets[i + 1]), ascending.
  std::vector<int32_t> known_offsets, known;
};

// `triangles` must outlive the result; `graph` is build_edge_graph of the
// same triangles. O(sum over vertices of degree squared).
DetailTopology build_detail_topology(int32_t num_vertices, const std::vector<int32_t>& triangles,
                                     const EdgeGraph& graph);

}  // namespace gab
