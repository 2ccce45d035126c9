// Portable level of the dense kernels: plain C++ that any compiler
// vectorizes as far as the baseline ISA allows. It is the reference twin of
// the SIMD levels and the production path on CPUs without AVX2.
#include <algorithm>
#include <cstddef>

#include "kernels/dense_kernels_internal.h"

namespace gab {
namespace dense_detail {
namespace {

struct ScalarTile {
  // 4 x 4 accumulators fit the 16 registers of SSE2 / NEON as 2-wide vectors.
  static constexpr int32_t kMr = 4;
  static constexpr int32_t kNr = 4;
  static constexpr int32_t kKc = 256;
  static constexpr int32_t kMc = 128;
  static constexpr int32_t kNc = 1024;
  static constexpr int32_t kSmall = 8;

  // Packing pays for itself only when a packed operand is reused: with few
  // column strips or few row tiles there is no reuse, and while A (m x k)
  // fits in L2 the unpacked tiles re-read it from there at full speed.
  static bool direct(int32_t m, int32_t n, int32_t k) {
    return n <= 2 * kNr || m <= kMr || static_cast<int64_t>(m) * k <= 64 * 1024;
  }

  static void tile(int32_t k, const double* a, ptrdiff_t as, const double* b, ptrdiff_t bs,
                   double* c, ptrdiff_t ldc, int32_t rows, int32_t cols, int32_t diag) {
    double acc[kNr][kMr] = {};
    if (rows == kMr && cols == kNr) {
      // Full tile: constant trip counts let the compiler keep acc in
      // registers.
      for (int32_t p = 0; p < k; ++p) {
        for (int32_t j = 0; j < kNr; ++j) {
          for (int32_t i = 0; i < kMr; ++i) acc[j][i] += a[i] * b[j];
        }
        a += as;
        b += bs;
      }
    } else {
      for (int32_t p = 0; p < k; ++p) {
        for (int32_t j = 0; j < cols; ++j) {
          for (int32_t i = 0; i < rows; ++i) acc[j][i] += a[i] * b[j];
        }
        a += as;
        b += bs;
      }
    }
    for (int32_t j = 0; j < cols; ++j) {
      double* cj = c + j * ldc;
      // Entry (i, j) belongs to the lower triangle iff i + diag >= j.
      for (int32_t i = std::max<int32_t>(0, j - diag); i < rows; ++i) cj[i] -= acc[j][i];
    }
  }

  static void pack(const double* a, ptrdiff_t lda, int32_t rows, int32_t k, double* dst) {
    pack_panels(a, lda, rows, k, kMr, dst);
  }

  static int32_t potrf_small(int32_t n, double* a, int32_t lda) {
    return potrf_unblocked(n, a, lda);
  }
  static void trsm_small(int32_t m, int32_t n, const double* l, int32_t ldl, double* b,
                         int32_t ldb) {
    trsm_unblocked(m, n, l, ldl, b, ldb);
  }
};

constexpr DenseKernels kScalar = Blocked<ScalarTile>::table(SimdLevel::kScalar);

}  // namespace

const DenseKernels* scalar_table() { return &kScalar; }

}  // namespace dense_detail
}  // namespace gab
