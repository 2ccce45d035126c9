// Cholesky: the engine's front door. Analyze a pattern once, factor (and
// refactor) values with that pattern, solve for one or several right-hand
// sides. Owns its buffers: all allocation happens in analyze() and the first
// factorize(); later factorize() and solve() calls allocate nothing.
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
#include "gab/sparse/large_buffer.h"
#include "gab/sparse/status.h"
#include "gab/sparse/symbolic.h"

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

  void set_kernels(const DenseKernels& kernels) { kernels_ = &kernels; }
  bool factorized() const { return factorized_; }
  const SymbolicFactor& symbolic() const { return symbolic_; }
  // The supernode blocks (see SymbolicFactor), symbolic().value_ptr.back()
  // doubles: for inspection and in-place updates.
  const double* values() const { return values_.data(); }
  double* mutable_values() { return values_.data(); }

 private:
  SymbolicFactor symbolic_;
  const DenseKernels* kernels_ = nullptr;
  bool analyzed_ = false;
  bool factorized_ = false;
  LargeBuffer<double> values_;
  LargeBuffer<double> work_;        // multifrontal update stacks
  LargeBuffer<int32_t> iwork_;
  LargeBuffer<double> solve_rhs_;   // permuted right-hand sides
  LargeBuffer<double> solve_work_;
};

}  // namespace gab
