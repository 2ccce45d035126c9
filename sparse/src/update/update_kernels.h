// SIMD kernels of the factor updater (internal): a run of Givens rotations
// applied to the rows of a dense column block, one pass over the block.
#pragma once

#include <cstdint>

#include "gab/sparse/dense_kernels.h"

namespace gab {
namespace update_detail {

struct UpdateKernels {
  SimdLevel level;
  // For every row t < p, in order q = 0..ncols-1:
  //   (L[t, q], x[t]) <- (c[q] L[t, q] + s[q] x[t], c[q] x[t] - s[q] L[t, q]).
  // L is p x ncols column-major (ld), x has p entries.
  void (*rotate_rows)(int32_t p, int32_t ncols, const double* c, const double* s, double* l,
                      int32_t ld, double* x);
  // Downdate form, q = ncols-1 down to 0:
  //   (L[t, q], x[t]) <- (c[q] L[t, q] - s[q] x[t], c[q] x[t] + s[q] L[t, q]).
  void (*rotate_rows_reverse)(int32_t p, int32_t ncols, const double* c, const double* s,
                              double* l, int32_t ld, double* x);
  // Batch form: nvec (<= kMaxBatch) vectors x_v = x + v * ldx; for every row,
  // for q = 0..ncols-1, for v = 0..nvec-1, the rotation (c[q*nvec+v],
  // s[q*nvec+v]) of (L[t, q], x_v[t]).
  void (*rotate_rows_batch)(int32_t p, int32_t ncols, int32_t nvec, const double* c,
                            const double* s, double* l, int32_t ld, double* x, int32_t ldx);
};

constexpr int32_t kMaxBatch = 8;

const UpdateKernels& update_kernels(SimdLevel level);

}  // namespace update_detail
}  // namespace gab
