// The least-squares system of geometry-aware bases (Sorkine et al. 2005, eq. 1):
// M = L^T L + w^2 sum_a e_a e_a^T with L = D - A the uniform Laplacian of
// the edge graph, assembled straight into the engine's lower-triangle CSC.
#pragma once

#include <cstdint>
#include <vector>

#include "gab/mesh/edge_graph.h"
#include "gab/mesh/mesh.h"
#include "gab/sparse/csc.h"
#include "gab/status.h"

namespace gab {

// Lower triangle of L^T L + w^2 sum_a e_a e_a^T. The pattern is the 2-ring
// of every vertex plus the full diagonal (kept even where a value is zero,
// e.g. isolated vertices, so the pattern never depends on the anchors).
// Anchors must be distinct and in range. O(sum of squared degrees).
// threads >= 2 splits the columns between two threads on large meshes; the
// matrix is bit-identical either way.
Status assemble_normal_matrix(const EdgeGraph& graph, const std::vector<int32_t>& anchors,
                              double weight, CscMatrix* lower, int32_t threads = 1);

// The benchmark anchor rule (docs/cli.md, "gab factor"): k0 anchors at vertices
// floor(j n / k0), j = 0..k0-1 (distinct), then the smallest vertex of each
// connected component that has none. O(V + E).
std::vector<int32_t> benchmark_anchors(const EdgeGraph& graph, int32_t k0);

// The benchmark update rule (docs/cli.md, "gab study"):
// v_t = t * 2654435761 mod n for t = 1, 2, ..., skipping vertices in
// `initial` or already taken; min(count, vertices not in initial) of them.
// O(n + the steps taken).
std::vector<int32_t> benchmark_update_sequence(int32_t n, const std::vector<int32_t>& initial, int64_t count);

// Right-hand sides w^2 E^T c for x, y, z: n x 3 column-major, the anchors'
// coordinates at their rows, zero elsewhere.
std::vector<double> anchor_right_hand_sides(const Mesh& mesh, const std::vector<int32_t>& anchors,
                                            double weight);

}  // namespace gab
