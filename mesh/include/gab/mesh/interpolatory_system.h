// The interpolatory variant of the geometry-aware least-squares system
// (Sorkine et al. 2005, section 3): anchors are hard constraints x_a = c_a, and the free
// vertices F solve (L^T L)_FF x_F = -(L^T L)_FA c, a principal submatrix of
// the relaxed system's L^T L.
#pragma once

#include <cstdint>
#include <vector>

#include "gab/mesh/edge_graph.h"
#include "gab/sparse/csc.h"
#include "gab/status.h"

namespace gab {

struct InterpolatorySystem {
  CscMatrix lower;                     // lower triangle of (L^T L)_FF, full diagonal kept
  std::vector<int32_t> free_vertices;  // row / column i is vertex free_vertices[i] (increasing)
  std::vector<int32_t> free_index;     // vertex -> its row, or -1 for an anchor
};

// Assembles (L^T L)_FF for F = all vertices but `anchors` (distinct, in
// range). It is positive definite iff every connected component has an
// anchor. O(sum of squared degrees).
Status assemble_interpolatory_matrix(const EdgeGraph& graph, const std::vector<int32_t>& anchors,
                                     InterpolatorySystem* system);

// Right-hand sides -(L^T L)_FA c: |F| x 3 column-major (x, y, z columns).
// `coefficients` holds x y z per anchor, in the order of `anchors` (the
// anchors the system was built with). O(V + E).
Status interpolatory_right_hand_sides(const EdgeGraph& graph, const InterpolatorySystem& system,
                                      const std::vector<int32_t>& anchors, const std::vector<double>& coefficients,
                                      std::vector<double>* rhs);

// Positions of all vertices (x y z per vertex, as Mesh::positions) from the
// free solution (|F| x 3 column-major) and the anchors' coefficients. O(V).
std::vector<double> interpolatory_positions(const InterpolatorySystem& system, const std::vector<int32_t>& anchors,
                                            const std::vector<double>& coefficients, const std::vector<double>& free_solution);

}  // namespace gab
