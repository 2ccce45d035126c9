// Cholesky: the engine's front door. Analyze a pattern once, factor (and
// refactor) values with that pattern, solve for one or several right-hand
// sides. Owns its buffers: all allocation happens in analyze(), the first
// factorize(), the first solve() with a given number of right-hand sides and
// the first update; later calls allocate nothing.
//
//   gab::Cholesky chol;
//   GAB_RETURN_IF_ERROR(chol.analyze(lower));      // ordering + symbolic
//   GAB_RETURN_IF_ERROR(chol.factorize(lower));    // numeric
//   chol.solve(xyz, 3, n);                         // b -> x, in place
#pragma once

#include <cstdint>
#include <vector>

#include "gab/sparse/csc.h"
#include "gab/sparse/dense_kernels.h"
#include "gab/sparse/factor_schedule.h"
#include "gab/sparse/large_buffer.h"
#include "gab/status.h"
#include "gab/sparse/symbolic.h"
#include "gab/sparse/update.h"

namespace gab {

class Cholesky {
 public:
  // Ordering and symbolic analysis of the lower triangle's pattern; also
  // reserves the factor's storage (kOutOfMemory when it cannot be had).
  Status analyze(const CscMatrix& lower, const AnalyzeOptions& options = AnalyzeOptions());
  // Numeric factorization of a matrix with the analyzed pattern. Uses the
  // dense kernels of the best SIMD level unless set_kernels() chose others.
  Status factorize(const CscMatrix& lower);
  // Solves A X = B in place: b is n x nrhs column-major, leading dimension
  // ldb >= n, in the original numbering. Requires a successful factorize().
  // The first call with a given nrhs reserves nrhs * n doubles of workspace.
  Status solve(double* b, int32_t nrhs, int32_t ldb);

  // In place, the factor of A + w^2 e_j e_j^T (j in the original
  // numbering): Givens rotations along the elimination-tree path, no change
  // of structure, no allocation after the first update (prepare_updates).
  // Cost: the entries of L on the path (reported in *stats when given).
  // Solves afterwards see the updated matrix.
  Status add_anchor(int32_t j, double weight, UpdateStats* stats = nullptr);
  // Batch form of add_anchor: count anchors, swept over the union of their
  // paths up to 8 at a time (stats sum the sweeps).
  Status add_anchors(const int32_t* j, int32_t count, double weight, UpdateStats* stats = nullptr);
  // The factor of A - w^2 e_j e_j^T; if that matrix would not be positive
  // definite, kNotPositiveDefinite and the factor is unchanged.
  Status remove_anchor(int32_t j, double weight, UpdateStats* stats = nullptr);
  // Sets up the updaters' workspace (about 11 n doubles) now; otherwise
  // the first update after analyze() does, so a caller timing updates calls
  // this first. Requires a successful factorize().
  Status prepare_updates() { return prepare_update(); }

  void set_kernels(const DenseKernels& kernels) { kernels_ = &kernels; }
  bool factorized() const { return factorized_; }
  const SymbolicFactor& symbolic() const { return symbolic_; }
  const FactorSchedule& schedule() const { return schedule_; }
  const FactorSchedule& solve_schedule() const { return solve_schedule_; }
  // The supernode blocks (see SymbolicFactor), symbolic().value_ptr.back()
  // doubles: for inspection and in-place updates.
  const double* values() const { return values_.data(); }
  double* mutable_values() { return values_.data(); }

 private:
  SymbolicFactor symbolic_;
  FactorSchedule schedule_;        // the factorization's split (flops)
  FactorSchedule solve_schedule_;  // the solves' split (entries)
  const DenseKernels* kernels_ = nullptr;
  bool analyzed_ = false;
  bool factorized_ = false;
  LargeBuffer<double> values_;
  LargeBuffer<double> work_;        // multifrontal update stacks
  LargeBuffer<int32_t> iwork_;
  LargeBuffer<double> solve_rhs_;   // permuted right-hand sides
  LargeBuffer<double> solve_work_;
  LargeBuffer<double> update_work_;  // see update_workspace_doubles
  LargeBuffer<int32_t> update_iwork_;
  PagePopulator populator_;  // after the buffers: stops before they are freed
  bool update_ready_ = false;
  Status prepare_update();
  Status prepare_update_workspace();
};

}  // namespace gab
