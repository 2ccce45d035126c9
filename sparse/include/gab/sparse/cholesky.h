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
#include "gab/sparse/status.h"
#include "gab/sparse/symbolic.h"

namespace gab {

class Cholesky {
 public:
  // Ordering and symbolic analysis of the lower triangle's pattern.
  Status analyze(const CscMatrix& lower, const AnalyzeOptions& options = AnalyzeOptions());
  // Numeric factorization of a matrix with the analyzed pattern. Uses the
  // dense kernels of the best SIMD level unless set_kernels() chose others.
  Status factorize(const CscMatrix& lower);
  // Solves A X = B in place: b is n x nrhs column-major, leading dimension
  // ldb >= n, in the original numbering. Requires a successful factorize().
  Status solve(double* b, int32_t nrhs, int32_t ldb);

  void set_kernels(const DenseKernels& kernels) { kernels_ = &kernels; }
  bool factorized() const { return factorized_; }
  const SymbolicFactor& symbolic() const { return symbolic_; }
  // The supernode blocks (see SymbolicFactor): for inspection and updates.
  const std::vector<double>& values() const { return values_; }
  std::vector<double>& mutable_values() { return values_; }

 private:
  SymbolicFactor symbolic_;
  const DenseKernels* kernels_ = nullptr;
  bool analyzed_ = false;
  bool factorized_ = false;
  std::vector<double> values_;
  std::vector<double> work_;       // multifrontal stack
  std::vector<int32_t> iwork_;
  std::vector<double> solve_rhs_;  // permuted right-hand sides
  std::vector<double> solve_work_;
};

}  // namespace gab
