// The interpolatory geometry-aware basis (Sorkine et al. 2005, section 3)
// as a reconstruction object: hard anchors are kept
// exactly, x_A = c, and the free vertices F minimize ||L x||^2, i.e. solve
//   (L^T L)_FF x_F = -(L^T L)_FA c.
// Relaxed anchors can be added on top (the paper: relaxed anchors refine an
// interpolatory basis too): each adds w^2 e_a e_a^T to (L^T L)_FF and w^2 c_a
// to the right-hand side, entering through the engine's Givens updater on
// the factor of the free system (no refactorization).
#pragma once

#include <cstdint>
#include <vector>

#include "gab/mesh/edge_graph.h"
#include "gab/mesh/interpolatory_system.h"
#include "gab/sparse/cholesky.h"
#include "gab/status.h"

namespace gab {

class InterpolatoryReconstruction {
 public:
  // Analyzes and factors (L^T L)_FF for the hard anchors (distinct
  // vertices) with their coefficients (3 per anchor: x y z). Every connected
  // component needs a hard anchor (the error names a vertex of one without).
  // Resets any earlier state. Cost: one AMD ordering, analysis and
  // factorization of the free system.
  Status init(const EdgeGraph& graph, const std::vector<int32_t>& hard_anchors,
              const std::vector<double>& hard_coefficients);

  // Adds relaxed anchors (distinct free vertices: neither hard nor already
  // relaxed) with weight w and their coefficients, by rank-one updates of
  // the factor. Cost: the factor's entries on each anchor's elimination-tree
  // path (batched 8 at a time).
  Status add_relaxed_anchors(const std::vector<int32_t>& anchors, const std::vector<double>& coefficients,
                             double weight);

  // The current shape, 3 coordinates per vertex (x0 y0 z0 x1 ...), the hard
  // anchors exactly at their coefficients. Cost: one solve with three
  // right-hand sides on the free system.
  Status reconstruct(std::vector<double>* positions);

  int32_t num_vertices() const { return static_cast<int32_t>(kind_.size()); }
  int32_t num_free() const { return static_cast<int32_t>(system_.free_vertices.size()); }
  int32_t num_hard_anchors() const { return static_cast<int32_t>(hard_anchors_.size()); }
  int32_t num_relaxed_anchors() const { return static_cast<int32_t>(relaxed_anchors_.size()); }
  // Anchors in the order they were given.
  const std::vector<int32_t>& hard_anchors() const { return hard_anchors_; }
  const std::vector<int32_t>& relaxed_anchors() const { return relaxed_anchors_; }
  bool is_hard_anchor(int32_t v) const { return kind_[v] == kHard; }
  bool is_relaxed_anchor(int32_t v) const { return kind_[v] == kRelaxed; }
  // The free system: free_vertices / free_index map rows to vertices.
  const InterpolatorySystem& system() const { return system_; }
  const Cholesky& cholesky() const { return chol_; }

 private:
  enum : char { kFree = 0, kHard = 1, kRelaxed = 2, kChecking = 3 };
  Status check_new(const std::vector<int32_t>& anchors, const std::vector<double>& coefficients);

  bool ready_ = false;
  InterpolatorySystem system_;
  Cholesky chol_;
  std::vector<int32_t> hard_anchors_, relaxed_anchors_;
  std::vector<double> hard_coefficients_;
  std::vector<char> kind_;   // per vertex: kFree, kHard or kRelaxed
  std::vector<double> rhs_;  // -(L^T L)_FA c + sum w^2 e_a c_a: |F| x 3 column-major
};

}  // namespace gab
