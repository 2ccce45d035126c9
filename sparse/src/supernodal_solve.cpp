// Supernodal triangular solves with several right-hand sides at once.
//
// Forward (L y = b), supernode by supernode in order: solve with the dense
// diagonal block, then subtract the block below times the solved part from
// the rows below. Backward (L^T x = y) in reverse order: gather the rows
// below, subtract the transposed block times them, solve with the transposed
// diagonal block. Every right-hand side is handled in the same pass, so L is
// streamed from memory once per direction (the solves are memory-bound).
// The below-block products go through a small dense buffer (`work`,
// row-interleaved: work[t * nrhs + r]) so the inner loops are contiguous.
#include "gab/sparse/supernodal.h"

namespace gab {

namespace {

// NRHS > 0: compile-time count (unrolled); NRHS == 0: run-time count.
template <int NRHS>
void lower_pass(const SymbolicFactor& f, const double* values, double* x, int32_t nrhs_rt,
                int32_t ldx, double* work) {
  const int32_t nrhs = NRHS > 0 ? NRHS : nrhs_rt;
  for (int32_t s = 0; s < f.num_supernodes; ++s) {
    const int32_t k = f.cols(s), m = f.rows(s), p = m - k, first = f.first_col[s];
    const double* l = values + f.value_ptr[s];
    const int32_t* rows = f.row_ind.data() + f.row_ptr[s];
    for (int32_t t = 0; t < p * nrhs; ++t) work[t] = 0.0;
    for (int32_t c = 0; c < k; ++c) {
      const double* lc = l + static_cast<int64_t>(c) * m;
      double xc[NRHS > 0 ? NRHS : 16];
      for (int32_t r0 = 0; r0 < nrhs; r0 += (NRHS > 0 ? NRHS : 16)) {
        const int32_t nr = NRHS > 0 ? NRHS : (nrhs - r0 < 16 ? nrhs - r0 : 16);
        for (int32_t r = 0; r < nr; ++r) {
          double* xr = x + static_cast<int64_t>(r0 + r) * ldx + first;
          xr[c] /= lc[c];
          xc[r] = xr[c];
          for (int32_t i = c + 1; i < k; ++i) xr[i] -= lc[i] * xc[r];
        }
        const double* below = lc + k;
        for (int32_t t = 0; t < p; ++t) {
          double* w = work + static_cast<int64_t>(t) * nrhs + r0;
          for (int32_t r = 0; r < nr; ++r) w[r] += below[t] * xc[r];
        }
      }
    }
    for (int32_t t = 0; t < p; ++t) {
      const int32_t row = rows[k + t];
      for (int32_t r = 0; r < nrhs; ++r) x[static_cast<int64_t>(r) * ldx + row] -= work[t * nrhs + r];
    }
  }
}

template <int NRHS>
void upper_pass(const SymbolicFactor& f, const double* values, double* x, int32_t nrhs_rt,
                int32_t ldx, double* work) {
  const int32_t nrhs = NRHS > 0 ? NRHS : nrhs_rt;
  for (int32_t s = f.num_supernodes - 1; s >= 0; --s) {
    const int32_t k = f.cols(s), m = f.rows(s), p = m - k, first = f.first_col[s];
    const double* l = values + f.value_ptr[s];
    const int32_t* rows = f.row_ind.data() + f.row_ptr[s];
    for (int32_t t = 0; t < p; ++t) {
      const int32_t row = rows[k + t];
      for (int32_t r = 0; r < nrhs; ++r) work[t * nrhs + r] = x[static_cast<int64_t>(r) * ldx + row];
    }
    for (int32_t c = k - 1; c >= 0; --c) {
      const double* lc = l + static_cast<int64_t>(c) * m;
      for (int32_t r0 = 0; r0 < nrhs; r0 += (NRHS > 0 ? NRHS : 16)) {
        const int32_t nr = NRHS > 0 ? NRHS : (nrhs - r0 < 16 ? nrhs - r0 : 16);
        double acc[NRHS > 0 ? NRHS : 16];
        for (int32_t r = 0; r < nr; ++r) acc[r] = 0.0;
        const double* below = lc + k;
        for (int32_t t = 0; t < p; ++t) {
          const double* w = work + static_cast<int64_t>(t) * nrhs + r0;
          for (int32_t r = 0; r < nr; ++r) acc[r] += below[t] * w[r];
        }
        for (int32_t r = 0; r < nr; ++r) {
          double* xr = x + static_cast<int64_t>(r0 + r) * ldx + first;
          double v = xr[c] - acc[r];
          for (int32_t i = c + 1; i < k; ++i) v -= lc[i] * xr[i];
          xr[c] = v / lc[c];
        }
      }
    }
  }
}

}  // namespace

void solve_lower_supernodal(const SymbolicFactor& f, const double* values, double* x,
                            int32_t nrhs, int32_t ldx, double* work) {
  switch (nrhs) {
    case 1: lower_pass<1>(f, values, x, nrhs, ldx, work); break;
    case 2: lower_pass<2>(f, values, x, nrhs, ldx, work); break;
    case 3: lower_pass<3>(f, values, x, nrhs, ldx, work); break;
    case 4: lower_pass<4>(f, values, x, nrhs, ldx, work); break;
    default: lower_pass<0>(f, values, x, nrhs, ldx, work); break;
  }
}

void solve_upper_supernodal(const SymbolicFactor& f, const double* values, double* x,
                            int32_t nrhs, int32_t ldx, double* work) {
  switch (nrhs) {
    case 1: upper_pass<1>(f, values, x, nrhs, ldx, work); break;
    case 2: upper_pass<2>(f, values, x, nrhs, ldx, work); break;
    case 3: upper_pass<3>(f, values, x, nrhs, ldx, work); break;
    case 4: upper_pass<4>(f, values, x, nrhs, ldx, work); break;
    default: upper_pass<0>(f, values, x, nrhs, ldx, work); break;
  }
}

}  // namespace gab
