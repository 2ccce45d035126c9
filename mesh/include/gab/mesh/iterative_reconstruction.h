// The relaxed geometry-aware basis (relaxed_reconstruction.h) evaluated at a
// cost linear in n: the system (L^T L + w^2 S) x = w^2 S c, L = D - A the
// uniform Laplacian, S the anchors' indicator, c their coefficients, is
// approached by a given number of Jacobi-preconditioned conjugate-gradient
// steps, matrix-free (L applied twice per product), three independent
// recurrences (x, y, z) sharing each pass over the mesh, their vectors in
// single precision (the shape and the first residual in double). No factor,
// no ordering: memory is about 130 bytes per vertex beside the graph.
//
// The result is a fixed computation, not "the solution to a tolerance": the
// steps start from the previous shape (the first time, and after restart,
// from each vertex at its nearest anchor's coefficients, breadth-first from
// the anchors in increasing vertex order, a vertex taking the anchor of the
// first frontier vertex that reaches it, so the order anchors were given in
// does not matter; then kStartSweeps harmonic sweeps), and every
// floating-point operation happens in one order. Sums over vertices add
// runs of 64 vertices, then fixed blocks of kBlock vertices in vertex
// order, then the blocks in block order, whatever the thread count; so two
// programs making the same calls get the same bits on any machine with IEEE
// arithmetic and no contraction, which is what lets an encoder and a
// decoder share the shape (docs/format.md 5.2.1 spells out every operation).
//
// As the steps grow the shape tends to the global least squares, to about
// 1e-7 of the correction the steps add (single precision); how many a use
// needs depends on the anchors' spacing (about 2 n / k steps reach it to
// 1e-3 of the error, bench/reconstruction_candidates).
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "gab/mesh/edge_graph.h"
#include "gab/status.h"

namespace gab {

class IterativeReconstruction {
 public:
  // Vertices per block of every sum over vertices.
  static constexpr int32_t kBlock = 4096;
  // Harmonic sweeps that smooth the nearest-anchor start.
  static constexpr int kStartSweeps = 8;

  // Starts over on `graph` (kept by reference: it must outlive this) with
  // weight w and the initial anchors (distinct vertices; every connected
  // component needs one) and their coefficients (3 per anchor). No shape
  // yet. O(n + anchors).
  Status init(const EdgeGraph& graph, double weight, const std::vector<int32_t>& anchors,
              const std::vector<double>& coefficients);

  // Adds anchors (distinct, not anchored yet) with their coefficients; the
  // shape so far stays the next solve's start. O(anchors).
  Status add_anchors(const std::vector<int32_t>& anchors, const std::vector<double>& coefficients);

  // Replaces the coefficients of anchors first.. (in anchors() order). O(k).
  Status set_coefficients(int32_t first, const std::vector<double>& coefficients);

  // `steps` conjugate-gradient steps (>= 0) from the shape so far (or, the
  // first time and after restart, from the nearest-anchor start);
  // *positions receives the shape (x0 y0 z0 x1 ...). O(steps (n + edges)).
  Status solve(int32_t steps, std::vector<double>* positions);
  // Threads for solve (default 1); the shape is the same bits for any count.
  void set_threads(int32_t threads) { threads_ = std::max(1, threads); }
  // The next solve starts from `positions` (3 per vertex, finite) instead
  // of the shape so far. O(n).
  Status set_start(const std::vector<double>& positions);
  // Each vertex at its nearest anchor's coefficients (3 per vertex): the
  // start before its harmonic sweeps. Changes nothing. O(n + edges).
  std::vector<double> nearest_anchor_shape() const;
  // Forgets the shape: the next solve starts from the nearest-anchor start,
  // so its result depends on the anchors and coefficients alone. O(1).
  void restart() { shape_.clear(); }

  double weight() const { return weight_; }
  int32_t num_vertices() const { return n_; }
  int32_t num_anchors() const { return static_cast<int32_t>(anchors_.size()); }
  const std::vector<int32_t>& anchors() const { return anchors_; }
  const std::vector<double>& coefficients() const { return coefficients_; }
  bool is_anchor(int32_t v) const { return anchor_of_[v] >= 0; }
  // Whether solve has made a shape yet.
  bool has_shape() const { return !shape_.empty(); }

 private:
  Status check_new(const std::vector<int32_t>& anchors, const std::vector<double>& coefficients);
  void record(const std::vector<int32_t>& anchors, const std::vector<double>& coefficients);

  const EdgeGraph* graph_ = nullptr;
  int32_t n_ = 0;
  double weight_ = 0.0;
  int32_t threads_ = 1;
  std::vector<int32_t> anchors_;
  std::vector<double> coefficients_;  // 3 per anchor
  std::vector<int32_t> anchor_of_;    // vertex -> index in anchors_, or -1
  std::vector<double> shape_;         // 3 per vertex once solved
};

}  // namespace gab
