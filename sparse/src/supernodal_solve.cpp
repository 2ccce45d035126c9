// Supernodal triangular solves with several right-hand sides at once.
//
// Forward (L y = b), supernode by supernode in order: solve with the dense
// diagonal block, form W = -(block below) * (solved part) in a small dense
// buffer, add W to the rows below (scatter). Backward (L^T x = y) in
// reverse order: gather the rows below into W, subtract (block below)^T W,
// solve with the transposed diagonal block. The dense kernels treat every
// right-hand side in the same sweep, so L streams from memory once per
// direction (the solves are memory-bound).
#include "gab/sparse/supernodal.h"
#include "solve_kernels.h"

namespace gab {

void solve_lower_supernodal(const SymbolicFactor& f, const double* values, double* x,
                            int32_t nrhs, int32_t ldx, double* work, SimdLevel level) {
  const solve_detail::SolveKernels& kern = solve_detail::solve_kernels(level);
  for (int32_t s = 0; s < f.num_supernodes; ++s) {
    const int32_t k = f.cols(s), m = f.rows(s), p = m - k;
    const double* l = values + f.value_ptr[s];
    double* x1 = x + f.first_col[s];
    kern.trsm_lower(k, nrhs, l, m, x1, ldx);
    if (p == 0) continue;
    kern.gemm_nn_neg(p, k, nrhs, l + k, m, x1, ldx, work);
    const int32_t* below = f.row_ind.data() + f.row_ptr[s] + k;
    for (int32_t r = 0; r < nrhs; ++r) {
      double* xr = x + static_cast<int64_t>(r) * ldx;
      const double* wr = work + static_cast<int64_t>(r) * p;
      for (int32_t t = 0; t < p; ++t) xr[below[t]] += wr[t];
    }
  }
}

void solve_upper_supernodal(const SymbolicFactor& f, const double* values, double* x,
                            int32_t nrhs, int32_t ldx, double* work, SimdLevel level) {
  const solve_detail::SolveKernels& kern = solve_detail::solve_kernels(level);
  for (int32_t s = f.num_supernodes - 1; s >= 0; --s) {
    const int32_t k = f.cols(s), m = f.rows(s), p = m - k;
    const double* l = values + f.value_ptr[s];
    double* x1 = x + f.first_col[s];
    if (p > 0) {
      const int32_t* below = f.row_ind.data() + f.row_ptr[s] + k;
      for (int32_t r = 0; r < nrhs; ++r) {
        const double* xr = x + static_cast<int64_t>(r) * ldx;
        double* wr = work + static_cast<int64_t>(r) * p;
        for (int32_t t = 0; t < p; ++t) wr[t] = xr[below[t]];
      }
      kern.gemm_tn_sub(p, k, nrhs, l + k, m, work, x1, ldx);
    }
    kern.trsm_lower_trans(k, nrhs, l, m, x1, ldx);
  }
}

}  // namespace gab
