// The two products of a block's orthogonalization against the Lanczos
// basis (internal): P = V^T X and X -= V P, for a tall basis V (n x cols)
// and a block X of a few columns (eight per sweep). Each streams V once, four or three
// columns at a time (contiguous streams the prefetcher follows), with the
// block's columns held in registers or L2: a pass costs one read of V.
// (The engine's solve kernels stream V once per four block columns; the
// dense GEMM's unpacked tile walks 24-row strips across every column of V,
// thousands of strided streams.) Scalar, AVX2 and AVX-512, chosen
// by the dense kernels' level (GAB_SIMD caps it).
#pragma once

#include <cstdint>

#include "gab/sparse/dense_kernels.h"

namespace gab {
namespace eigen_detail {

struct BasisKernels {
  SimdLevel level;
  // P (cols x w, leading dimension ldp) = V^T X; V n x cols (ld n), X n x w
  // (ld n).
  void (*project)(int32_t n, int32_t cols, int32_t w, const double* v, const double* x, double* p,
                  int32_t ldp);
  // X -= V P, the same shapes.
  void (*subtract)(int32_t n, int32_t cols, int32_t w, const double* v, const double* p, int32_t ldp,
                   double* x);
};

// Kernels of the given level (clamped to what the CPU supports).
const BasisKernels& basis_kernels(SimdLevel level);

}  // namespace eigen_detail
}  // namespace gab
