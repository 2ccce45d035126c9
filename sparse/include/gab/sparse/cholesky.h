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
#include <memory>

#include "gab/sparse/csc.h"
#include "gab/sparse/symbolic.h"
#include "gab/status.h"

namespace gab {

struct DenseKernels;    // the SIMD kernels (internal: dense_kernels.h)
struct FactorSchedule;  // the threads' split of the tree (internal: factor_schedule.h)

// What one anchor update cost.
struct UpdateStats {
  int32_t path_columns = 0;     // columns of L on the path (rotations)
  int32_t path_supernodes = 0;  // supernodes the path crosses
  int64_t touched = 0;          // entries of L read and written
  double flops = 0.0;           // floating-point operations
};

class Cholesky {
 public:
  Cholesky();
  ~Cholesky();
  Cholesky(const Cholesky&) = delete;  // owns large buffers and a helper thread
  Cholesky& operator=(const Cholesky&) = delete;

  // Ordering and symbolic analysis of the lower triangle's pattern; also
  // reserves the factor's storage (kOutOfMemory when it cannot be had).
  Status analyze(const CscMatrix& lower, const AnalyzeOptions& options = AnalyzeOptions());
  // Numeric factorization of a matrix with the analyzed pattern. Uses the
  // dense kernels of the best SIMD level unless set_kernels() chose others.
  Status factorize(const CscMatrix& lower);
  // The same with only the values: the count values of the analyzed
  // matrix's lower triangle, in the order of its entries (its values
  // array). For a caller that refactors with new values and need not keep
  // the pattern (its row indices are not read).
  Status factorize_values(const double* values, int64_t count);
  // Solves A X = B in place: b is n x nrhs column-major, leading dimension
  // ldb >= n, in the original numbering. Requires a successful factorize().
  // The first call with a given nrhs reserves nrhs * n doubles of workspace.
  Status solve(double* b, int32_t nrhs, int32_t ldb);

  // In place, the factor of A + w^2 e_j e_j^T (j in the original
  // numbering): Givens rotations along the elimination-tree path, no change
  // of structure, no allocation (the first update after a factorize()
  // prepares its workspace: prepare_updates).
  // Cost: the entries of L on the path (reported in *stats when given).
  // Solves afterwards see the updated matrix.
  Status add_anchor(int32_t j, double weight, UpdateStats* stats = nullptr);
  // Batch form of add_anchor: count anchors, swept over the union of their
  // paths up to 8 at a time (stats sum the sweeps).
  Status add_anchors(const int32_t* j, int32_t count, double weight, UpdateStats* stats = nullptr);
  // The factor of A - w^2 e_j e_j^T; if that matrix would not be positive
  // definite, kNotPositiveDefinite and the factor is unchanged.
  Status remove_anchor(int32_t j, double weight, UpdateStats* stats = nullptr);
  // Sets up the updaters' workspace (about 11 n doubles, in the buffer of
  // the factorization's stacks) now; otherwise the first update after a
  // factorize() does (9 n zeros), so a caller timing updates calls this
  // first. Requires a successful factorize().
  Status prepare_updates();

  // The kernels of another SIMD level than the best one (tests compare them).
  void set_kernels(const DenseKernels& kernels);
  // The SIMD level of the kernels factorize() uses: "scalar", "avx2" or
  // "avx512" (the best the CPU has, capped by the environment's GAB_SIMD).
  const char* simd_level() const;
  bool factorized() const;
  const SymbolicFactor& symbolic() const;
  const FactorSchedule& schedule() const;        // the factorization's split (flops)
  const FactorSchedule& solve_schedule() const;  // the solves' split (entries)
  // The supernode blocks (see SymbolicFactor), symbolic().value_ptr.back()
  // doubles: for inspection and in-place updates. nullptr before analyze().
  const double* values() const;
  double* mutable_values();

 private:
  struct State;  // buffers, schedules and flags (cholesky.cpp)
  std::unique_ptr<State> state_;
};

}  // namespace gab
