// Dense kernels of the supernodal factorization and solves, column-major.
//
// Each kernel has a portable scalar version and, where the compiler can build
// them, AVX2 and AVX-512 versions; dense_kernels() picks the best one the CPU
// supports at run time (one binary runs everywhere). The environment variable
// GAB_SIMD=scalar|avx2|avx512 caps the choice (tests use it; so can users
// chasing a bug). No kernel allocates memory.
#pragma once

#include <cstdint>

namespace gab {

enum class SimdLevel { kScalar = 0, kAvx2 = 1, kAvx512 = 2 };

// Highest level both compiled in and supported by this CPU. Cheap after the
// first call.
SimdLevel cpu_simd_level();
// "scalar", "avx2" or "avx512".
const char* simd_level_name(SimdLevel level);

struct DenseKernels {
  SimdLevel level;
  // In-place Cholesky A = L L^T of the n x n lower triangle of a (leading
  // dimension lda); the strict upper triangle is not touched. Returns -1 on
  // success, otherwise the first column j (0-based) whose pivot is <= 0 or
  // not finite (columns before j hold their factor).
  int32_t (*potrf)(int32_t n, double* a, int32_t lda);
  // B := B L^{-T}: b is m x n (ldb), l is n x n lower triangular (ldl).
  void (*trsm_right_lower_trans)(int32_t m, int32_t n, const double* l, int32_t ldl, double* b,
                                 int32_t ldb);
  // Lower triangle of C (n x n, ldc) -= A A^T, a is n x k (lda).
  void (*syrk_lower_sub)(int32_t n, int32_t k, const double* a, int32_t lda, double* c,
                         int32_t ldc);
  // C (m x n, ldc) -= A B^T, a is m x k (lda), b is n x k (ldb).
  void (*gemm_nt_sub)(int32_t m, int32_t n, int32_t k, const double* a, int32_t lda,
                      const double* b, int32_t ldb, double* c, int32_t ldc);
};

// Kernels of the given level; a level the CPU lacks falls back to the best
// supported one below it (check .level).
const DenseKernels& dense_kernels(SimdLevel level);
// Kernels of the best supported level, honouring GAB_SIMD.
const DenseKernels& dense_kernels();

}  // namespace gab
