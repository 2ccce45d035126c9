// Dense kernels of the supernodal factorization and solves, column-major.
//
// Each kernel has a portable scalar version and, where the compiler can build
// them, AVX2 and AVX-512 versions; dense_kernels() picks the best one the CPU
// supports at run time (one binary runs everywhere). The environment variable
// GAB_SIMD=scalar|avx2|avx512 caps the choice (tests use it; so can users
// chasing a bug). Levels differ only in rounding (the SIMD ones use FMA).
//
// Memory: no kernel allocates inside its numeric loops. GEMM/SYRK calls large
// enough to pack their operands (A of 256-512 KB or more) use one per-thread
// buffer of fixed size (4.4 MB at AVX-512, 3.5 MB at AVX2, 2.4 MB scalar),
// allocated by the first such call of each thread and freed at thread exit;
// if it cannot be had they run unpacked, correct but slower. All other work
// is in registers or on the stack (POTRF/TRSM reach the packed path through
// their GEMM/SYRK).
//
// Shapes: every dimension may be 0 (no-op); leading dimensions are >= the row
// count and >= 1. Matrices are column-major; int32 sizes, products of a
// dimension and a leading dimension are formed in ptrdiff_t.
#pragma once

#include <cstdint>

namespace gab {

// Packed lower triangle of an n x n matrix: the columns in panels of
// kPackedLowerPanel, panel J (columns J*P .. min(n, (J+1)*P) - 1) stored
// column-major from row J*P down, leading dimension n - J*P. Half the room
// of the square for large n (the waste is P/2 entries per column) while
// every column stays contiguous and every panel a plain column-major block.
// The multifrontal update matrices are stored this way.
constexpr int32_t kPackedLowerPanel = 16;
// Doubles before panel J, that is before column J * kPackedLowerPanel.
constexpr int64_t packed_lower_panel_offset(int64_t n, int64_t panel) {
  return kPackedLowerPanel * (panel * n - kPackedLowerPanel * (panel * (panel - 1) / 2));
}
// Doubles the packed lower triangle of an n x n matrix takes: the full
// panels, then the narrower last one.
constexpr int64_t packed_lower_size(int64_t n) {
  const int64_t rest = n % kPackedLowerPanel;
  return packed_lower_panel_offset(n, n / kPackedLowerPanel) + rest * rest;
}
// Leading dimension of column j's panel.
constexpr int32_t packed_lower_ld(int32_t n, int32_t j) { return n - j / kPackedLowerPanel * kPackedLowerPanel; }
// Column j of the packed lower triangle at c: entry (i, j), i >= j, is at
// packed_lower_column(c, n, j)[i].
inline double* packed_lower_column(double* c, int32_t n, int32_t j) {
  const int64_t panel = j / kPackedLowerPanel, first = panel * kPackedLowerPanel;
  return c + packed_lower_panel_offset(n, panel) + (j - first) * (n - first) - first;
}
inline const double* packed_lower_column(const double* c, int32_t n, int32_t j) {
  return packed_lower_column(const_cast<double*>(c), n, j);
}

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
  // not finite (NaN, inf); columns before j then hold their factor (all
  // rows), the others are partly updated. n^3/3 flops.
  int32_t (*potrf)(int32_t n, double* a, int32_t lda);
  // B := B L^{-T}: b is m x n (ldb), l is n x n lower triangular (ldl; its
  // strict upper triangle is not read). No check for a zero diagonal.
  // m n^2 flops.
  void (*trsm_right_lower_trans)(int32_t m, int32_t n, const double* l, int32_t ldl, double* b,
                                 int32_t ldb);
  // Lower triangle of C (n x n, ldc) -= A A^T, a is n x k (lda); the strict
  // upper triangle of C is never written. n (n+1) k flops.
  void (*syrk_lower_sub)(int32_t n, int32_t k, const double* a, int32_t lda, double* c,
                         int32_t ldc);
  // C (m x n, ldc) -= A B^T, a is m x k (lda), b is n x k (ldb). 2 m n k
  // flops.
  void (*gemm_nt_sub)(int32_t m, int32_t n, int32_t k, const double* a, int32_t lda,
                      const double* b, int32_t ldb, double* c, int32_t ldc);
  // syrk_lower_sub with C packed (packed_lower_column above): the same
  // operations in the same order, so the same bits as on a square C.
  void (*syrk_lower_sub_packed)(int32_t n, int32_t k, const double* a, int32_t lda, double* c);
};

// Kernels of the given level; a level the CPU lacks falls back to the best
// supported one below it (check .level).
const DenseKernels& dense_kernels(SimdLevel level);
// Kernels of the best supported level, honouring GAB_SIMD. The variable is
// read once, on the first call; later changes to it have no effect.
const DenseKernels& dense_kernels();

// The level dense_kernels() picks when GAB_SIMD holds `cap`: the lower of the
// named level and cpu_simd_level(). nullptr, "" or an unrecognized name mean
// no cap. Exposed so the variable's handling can be tested in-process.
SimdLevel simd_level_for_cap(const char* cap);

}  // namespace gab
