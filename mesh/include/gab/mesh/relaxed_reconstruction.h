// The relaxed geometry-aware basis (Sorkine et al. 2005, eq. 1): the shape  x~ = argmin ||L x||^2 + w^2 sum_a (x_a - c_a)^2  for
// x, y and z, L the uniform Laplacian of the connectivity. The matrix
// L^T L + w^2 E^T E is analyzed and factored once; further anchors enter
// through the engine's Givens updater (no refactorization), which is what an
// encoder's greedy loop and a progressive decoder both need.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "gab/mesh/edge_graph.h"
#include "gab/sparse/cholesky.h"
#include "gab/status.h"

namespace gab {

class RelaxedReconstruction {
 public:
  // Analyzes and factors the system for the initial anchors, whose
  // coefficients are `coefficients` (3 per anchor: x y z). Anchors must be
  // distinct vertices and every connected component needs one (otherwise
  // the system is singular: the error names a vertex of such a component).
  // Cost: one ordering (set_ordering), analysis and factorization.
  Status init(const EdgeGraph& graph, double weight, const std::vector<int32_t>& anchors,
              const std::vector<double>& coefficients);

  // Adds anchors (distinct, not anchored yet) with their coefficients, by
  // rank-one updates of the factor. Cost: the factor's entries on each
  // anchor's elimination-tree path (batched 8 at a time).
  Status add_anchors(const std::vector<int32_t>& anchors, const std::vector<double>& coefficients);

  // Same result as add_anchors up to rounding, by a fresh numeric
  // factorization of the whole matrix (the analysis and the assembled matrix
  // are reused: anchors only change its diagonal). Cost: one numeric
  // factorization, whatever the number of anchors.
  Status add_anchors_refactoring(const std::vector<int32_t>& anchors, const std::vector<double>& coefficients);

  // add_anchors or add_anchors_refactoring, whichever the cost model says
  // is cheaper for these anchors (update_cost_ratio); *refactored (when
  // given) says which. Deterministic: the choice depends on the structure
  // only, never on timings.
  Status add_anchors_cheapest(const std::vector<int32_t>& anchors, const std::vector<double>& coefficients,
                              bool* refactored = nullptr);

  // Estimated time of updating the factor with these anchors over the time
  // of refactoring it: the factor entries on each anchor's elimination-tree
  // path (what an update streams through) against the factorization's flops,
  // weighted by the rates measured on this engine (an entry of a batched
  // update costs about as much as 12 flops of the factorization). O(path
  // length in supernodes) per anchor.
  double update_cost_ratio(const std::vector<int32_t>& anchors) const;

  // Replaces the coefficients of anchors first.. (in anchors() order) by
  // `coefficients` (3 per anchor). Only the right-hand side changes. O(k).
  Status set_coefficients(int32_t first, const std::vector<double>& coefficients);
  // The coefficients, 3 per anchor in anchors() order.
  const std::vector<double>& coefficients() const { return coefficients_; }

  // The current shape, 3 coordinates per vertex (x0 y0 z0 x1 ...). Cost: one
  // solve with three right-hand sides.
  Status reconstruct(std::vector<double>* positions);

  // Solves M X = B in place for the current matrix M (b: n x 3
  // column-major, one column per coordinate). Cost: one solve.
  Status solve_system(double* b);

  // Threads for the numeric factorizations (init, add_anchors_refactoring);
  // call before init. The factor, hence every shape, is bit-identical for
  // any count (factor_schedule.h): an encoder and a decoder may differ.
  void set_threads(int32_t threads) { threads_ = threads; }
  // The fill-reducing ordering of init's analysis (kAmd or
  // kNestedDissection; default kAmd); call before init. Shapes agree with
  // any other ordering's up to rounding only, which is all a codec with
  // guarded rounding needs (quantizer.h): encoder and decoder may differ.
  void set_ordering(Ordering ordering) {
    ordering_ = ordering;
    given_perm_.clear();
  }
  // Orders by `perm` (a permutation of the vertices): the pattern of
  // L^T L + w^2 E^T E does not depend on the anchors, so a permutation an
  // earlier analysis of the same connectivity computed (cholesky().symbolic()
  // .perm) serves every later one and saves its ordering time.
  void set_given_ordering(std::vector<int32_t> perm) {
    ordering_ = Ordering::kGiven;
    given_perm_ = std::move(perm);
  }
  // A bound on the factor's stored entries, checked by init right after the
  // analysis, before the factor's storage is reserved or factored (see
  // AnalyzeOptions::max_factor_entries): over it, init fails with
  // kResourceExhausted. For decoders of untrusted files. Default: none.
  void set_max_factor_entries(int64_t entries) { max_factor_entries_ = entries; }

  double weight() const { return weight_; }
  int32_t num_vertices() const { return n_; }
  int32_t num_anchors() const { return static_cast<int32_t>(anchors_.size()); }
  // Anchors in the order they were given.
  const std::vector<int32_t>& anchors() const { return anchors_; }
  bool is_anchor(int32_t v) const { return anchored_[v] != 0; }
  const Cholesky& cholesky() const { return chol_; }

 private:
  Status check_new(const std::vector<int32_t>& anchors, const std::vector<double>& coefficients);
  void record(const std::vector<int32_t>& anchors, const std::vector<double>& coefficients);
  void add_to_matrix(const std::vector<int32_t>& anchors);

  int32_t n_ = 0;
  double weight_ = 0.0;
  int32_t threads_ = 1;
  Ordering ordering_ = Ordering::kAmd;
  std::vector<int32_t> given_perm_;  // for Ordering::kGiven
  int64_t max_factor_entries_ = INT64_MAX;
  Cholesky chol_;
  // Values of the lower triangle of L^T L + w^2 E^T E for the anchors so
  // far, in the order of the analyzed matrix's entries; its pattern is not
  // kept (only the place of each column's diagonal): refactorizations need
  // the values alone (Cholesky::factorize_values).
  std::vector<double> values_;
  std::vector<int32_t> diagonal_;
  std::vector<int32_t> anchors_;
  std::vector<double> coefficients_;  // 3 per anchor
  std::vector<char> anchored_;
};

}  // namespace gab
