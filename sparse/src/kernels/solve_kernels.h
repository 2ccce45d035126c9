// Dense kernels of the supernodal solves (internal): small numbers of
// right-hand sides, so these stream the factor block once for all of them.
// X blocks are column-major with leading dimension ldx; W blocks are
// p x nrhs column-major with leading dimension p.
#pragma once

#include <cstdint>

#include "gab/sparse/dense_kernels.h"

namespace gab {
namespace solve_detail {

struct SolveKernels {
  SimdLevel level;
  // X (k x nrhs) := L^{-1} X, L k x k lower (ldl).
  void (*trsm_lower)(int32_t k, int32_t nrhs, const double* l, int32_t ldl, double* x,
                     int32_t ldx);
  // X (k x nrhs) := L^{-T} X.
  void (*trsm_lower_trans)(int32_t k, int32_t nrhs, const double* l, int32_t ldl, double* x,
                           int32_t ldx);
  // W (p x nrhs, ld p) := -B X, B p x k (ldb), X k x nrhs (ldx).
  void (*gemm_nn_neg)(int32_t p, int32_t k, int32_t nrhs, const double* b, int32_t ldb,
                  const double* x, int32_t ldx, double* w);
  // X (k x nrhs) -= B^T W, B p x k (ldb), W p x nrhs (ld p).
  void (*gemm_tn_sub)(int32_t p, int32_t k, int32_t nrhs, const double* b, int32_t ldb,
                      const double* w, double* x, int32_t ldx);
};

// Kernels of the given level (clamped to what the CPU supports).
const SolveKernels& solve_kernels(SimdLevel level);

}  // namespace solve_detail
}  // namespace gab
