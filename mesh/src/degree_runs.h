// A block's vertices grouped by their degree, for the loops that compute
// one row per vertex from its neighbours (harmonic sweeps, products by the
// Laplacian). In vertex order a mesh's degrees change from one vertex to
// the next, and the loop over each vertex's neighbours ends where the
// branch predictor guessed wrong, about once a vertex; grouped, a loop of
// a known trip count per group has no such misses (feline's start sweeps:
// 0.42 -> 0.23 ms each). A row computed from its neighbours alone is the
// same bits in any order, so only the order of the rows changes.
#pragma once

#include <cstdint>
#include <type_traits>
#include <vector>

#include "gab/mesh/edge_graph.h"

namespace gab {

class DegreeRuns {
 public:
  // Degrees with a loop of their own; the others share one (degree 0
  // below: "any").
  static constexpr int32_t kLowest = 3, kHighest = 8;

  // Room for n vertices in blocks of `block` (a block's groups sit in its
  // own range, so blocks fill on any thread).
  void resize(int32_t n, int32_t block) {
    block_ = block;
    vertices_.resize(static_cast<size_t>(n));
    ends_.assign((static_cast<size_t>(n) + block - 1) / block * kSlots, 0);
  }

  // Block b (vertices [begin, end)): those with keep(v), by degree, each
  // group in increasing vertex order.
  template <class Keep>
  void fill(const EdgeGraph& g, int32_t b, int32_t begin, int32_t end, const Keep& keep) {
    int32_t count[kSlots] = {};
    for (int32_t v = begin; v < end; ++v) {
      if (keep(v)) ++count[slot(g.offsets[v + 1] - g.offsets[v])];
    }
    int32_t* ends = &ends_[static_cast<size_t>(b) * kSlots];
    int32_t at[kSlots];
    int32_t position = b * block_;
    for (int s = 0; s < kSlots; ++s) {
      at[s] = position;
      position += count[s];
      ends[s] = position;
    }
    for (int32_t v = begin; v < end; ++v) {
      if (keep(v)) vertices_[at[slot(g.offsets[v + 1] - g.offsets[v])]++] = v;
    }
  }

  // Vertex v's degree (offsets: the graph's), a constant when `known`
  // (visit's first argument) carries it, read when it is 0.
  template <class Known>
  static int32_t degree(Known known, const int32_t* offsets, int32_t v) {
    constexpr int32_t kKnown = decltype(known)::value;
    return kKnown > 0 ? kKnown : offsets[v + 1] - offsets[v];
  }

  // row(std::integral_constant<int32_t, D>(), v) for block b's vertices of
  // degree D = kLowest..kHighest, then row(std::integral_constant<int32_t,
  // 0>(), v) for the others.
  template <class Row>
  void visit(int32_t b, const Row& row) const {
    const int32_t* ends = &ends_[static_cast<size_t>(b) * kSlots];
    int32_t position = b * block_;
    visit_from<kLowest>(ends, &position, row);
  }

 private:
  static constexpr int kSlots = kHighest - kLowest + 2;
  static int slot(int32_t degree) {
    return degree >= kLowest && degree <= kHighest ? degree - kLowest : kSlots - 1;
  }
  template <int32_t D, class Row>
  void visit_from(const int32_t* ends, int32_t* position, const Row& row) const {
    constexpr int32_t kDegree = D <= kHighest ? D : 0;
    const int32_t end = ends[slot(kDegree)];
    for (int32_t i = *position; i < end; ++i) row(std::integral_constant<int32_t, kDegree>(), vertices_[i]);
    *position = end;
    if constexpr (D <= kHighest) visit_from<D + 1>(ends, position, row);
  }

  int32_t block_ = 1;
  std::vector<int32_t> vertices_;
  std::vector<int32_t> ends_;  // per block, kSlots ends (positions in vertices_)
};

}  // namespace gab
