// AVX2 + FMA level of the dense kernels. Every function that touches a ymm
// register carries the target attribute, so this file builds with the
// project's baseline flags and is only entered after the run-time check in
// dense_kernels.cpp.
//
// Register tile: 12 x 4 (3 ymm of rows x 4 columns = 12 accumulators), the
// broadcast-FMA micro-kernel of Goto / BLIS sized for the 16 ymm registers:
// 12 accumulators + 3 A vectors + 1 broadcast. Partial tiles use
// vmaskmov loads/stores (fault-free past the end of a column).
#include "kernels/dense_kernels_internal.h"

#if defined(__x86_64__)

#include <immintrin.h>

#define GAB_TARGET_AVX2 __attribute__((target("avx2,fma")))

namespace gab {
namespace dense_detail {
namespace {

constexpr int32_t kMr = 12;
constexpr int32_t kNr = 4;

// All-ones in lanes t with t < count.
GAB_TARGET_AVX2 inline __m256i lanes_below(int32_t count) {
  return _mm256_cmpgt_epi64(_mm256_set1_epi64x(count), _mm256_setr_epi64x(0, 1, 2, 3));
}

// All-ones in lanes t with t >= from.
GAB_TARGET_AVX2 inline __m256i lanes_from(int32_t from) {
  return _mm256_cmpgt_epi64(_mm256_setr_epi64x(0, 1, 2, 3), _mm256_set1_epi64x(from - 1));
}

// acc += A B^T over k steps; the last A vector is loaded under `tail` when
// kMaskedTail (rows not a multiple of 4), else all loads are plain.
template <int MV, int NC, bool kMaskedTail>
GAB_TARGET_AVX2 inline void accumulate(int32_t k, const double* a, ptrdiff_t as, const double* b,
                                       ptrdiff_t bs, __m256i tail, __m256d (&acc)[MV][NC]) {
  for (int32_t p = 0; p < k; ++p) {
    __m256d av[MV];
#pragma GCC unroll 8
    for (int v = 0; v + 1 < MV; ++v) av[v] = _mm256_loadu_pd(a + 4 * v);
    av[MV - 1] = kMaskedTail ? _mm256_maskload_pd(a + 4 * (MV - 1), tail)
                             : _mm256_loadu_pd(a + 4 * (MV - 1));
#pragma GCC unroll 8
    for (int j = 0; j < NC; ++j) {
      const __m256d bj = _mm256_broadcast_sd(b + j);
#pragma GCC unroll 8
      for (int v = 0; v < MV; ++v) acc[v][j] = _mm256_fmadd_pd(av[v], bj, acc[v][j]);
    }
    a += as;
    b += bs;
  }
}

// C[0:rows, 0:NC] -= A B^T, rows in (4*(MV-1), 4*MV]; see Blocked's tile
// contract for diag.
template <int MV, int NC>
GAB_TARGET_AVX2 void tile_fixed(int32_t k, const double* a, ptrdiff_t as, const double* b,
                                ptrdiff_t bs, double* c, ptrdiff_t ldc, int32_t rows,
                                int32_t diag) {
  const int32_t tail_rows = rows - 4 * (MV - 1);
  const __m256i tail = lanes_below(tail_rows);
#pragma GCC unroll 8
  for (int j = 0; j < NC; ++j) {
    _mm_prefetch(reinterpret_cast<const char*>(c + j * ldc), _MM_HINT_T0);
    _mm_prefetch(reinterpret_cast<const char*>(c + j * ldc + rows - 1), _MM_HINT_T0);
  }
  __m256d acc[MV][NC];
#pragma GCC unroll 8
  for (int v = 0; v < MV; ++v) {
#pragma GCC unroll 8
    for (int j = 0; j < NC; ++j) acc[v][j] = _mm256_setzero_pd();
  }
  if (tail_rows == 4) {
    accumulate<MV, NC, false>(k, a, as, b, bs, tail, acc);
  } else {
    accumulate<MV, NC, true>(k, a, as, b, bs, tail, acc);
  }
  const bool masked = tail_rows < 4 || diag < NC - 1;
#pragma GCC unroll 8
  for (int j = 0; j < NC; ++j) {
    double* cj = c + j * ldc;
#pragma GCC unroll 8
    for (int v = 0; v < MV; ++v) {
      if (!masked) {
        _mm256_storeu_pd(cj + 4 * v, _mm256_sub_pd(_mm256_loadu_pd(cj + 4 * v), acc[v][j]));
        continue;
      }
      // Entry (r, j) is written iff r < rows and r + diag >= j.
      __m256i mask = v + 1 < MV ? _mm256_set1_epi64x(-1) : tail;
      if (diag < NC - 1) mask = _mm256_and_si256(mask, lanes_from(j - diag - 4 * v));
      const __m256d old = _mm256_maskload_pd(cj + 4 * v, mask);
      _mm256_maskstore_pd(cj + 4 * v, mask, _mm256_sub_pd(old, acc[v][j]));
    }
  }
}

// pack_panels with kMr = 12 rows: a panel step is three ymm copies, the
// partial last panel loads under masks (which also zero its padding).
GAB_TARGET_AVX2 void pack12(const double* a, ptrdiff_t lda, int32_t rows, int32_t k, double* dst) {
  for (int32_t i = 0; i < rows; i += kMr) {
    const int32_t h = std::min(kMr, rows - i);
    const double* src = a + i;
    if (h == kMr) {
      for (int32_t p = 0; p < k; ++p) {
        _mm256_storeu_pd(dst, _mm256_loadu_pd(src));
        _mm256_storeu_pd(dst + 4, _mm256_loadu_pd(src + 4));
        _mm256_storeu_pd(dst + 8, _mm256_loadu_pd(src + 8));
        dst += kMr;
        src += lda;
      }
      continue;
    }
    const __m256i m0 = lanes_below(h);
    const __m256i m1 = lanes_below(h - 4);
    const __m256i m2 = lanes_below(h - 8);
    for (int32_t p = 0; p < k; ++p) {
      _mm256_storeu_pd(dst, _mm256_maskload_pd(src, m0));
      _mm256_storeu_pd(dst + 4, _mm256_maskload_pd(src + 4, m1));
      _mm256_storeu_pd(dst + 8, _mm256_maskload_pd(src + 8, m2));
      dst += kMr;
      src += lda;
    }
  }
}

using TileFn = void (*)(int32_t, const double*, ptrdiff_t, const double*, ptrdiff_t, double*,
                        ptrdiff_t, int32_t, int32_t);

template <int MV>
struct TileRow {
  static constexpr TileFn fns[kNr] = {&tile_fixed<MV, 1>, &tile_fixed<MV, 2>, &tile_fixed<MV, 3>,
                                      &tile_fixed<MV, 4>};
};

// B := B L^{-T} for N <= 8 columns on 4 rows at a time (fewer under a mask):
// the 4 x N block stays in registers through the substitution.
template <int N>
GAB_TARGET_AVX2 void trsm_fixed(int32_t m, const double* l, ptrdiff_t ldl, double* b,
                                ptrdiff_t ldb) {
  double inv[N];
#pragma GCC unroll 8
  for (int j = 0; j < N; ++j) inv[j] = 1.0 / l[j + j * ldl];
  for (int32_t i = 0; i < m; i += 4) {
    const __m256i mask = lanes_below(std::min<int32_t>(4, m - i));
    double* bi = b + i;
    __m256d x[N];
#pragma GCC unroll 8
    for (int j = 0; j < N; ++j) x[j] = _mm256_maskload_pd(bi + j * ldb, mask);
#pragma GCC unroll 8
    for (int j = 0; j < N; ++j) {
      x[j] = _mm256_mul_pd(x[j], _mm256_set1_pd(inv[j]));
#pragma GCC unroll 8
      for (int c = j + 1; c < N; ++c) {
        x[c] = _mm256_fnmadd_pd(x[j], _mm256_broadcast_sd(l + c + j * ldl), x[c]);
      }
    }
#pragma GCC unroll 8
    for (int j = 0; j < N; ++j) _mm256_maskstore_pd(bi + j * ldb, mask, x[j]);
  }
}

struct Avx2Tile {
  static constexpr int32_t kMr = 12;
  static constexpr int32_t kNr = 4;
  static constexpr int32_t kKc = 256;
  static constexpr int32_t kMc = 192;
  static constexpr int32_t kNc = 1536;
  static constexpr int32_t kSmall = 8;

  // Packing pays for itself only when a packed operand is reused: with few
  // column strips or few row tiles there is no reuse, and while A (m x k)
  // is small the unpacked tiles re-read it from L2 at full speed. The
  // 4-column strips re-read A twice as often as AVX-512's, hence half its
  // limit (measured: unpacked falls behind from about 256 KB of A).
  static bool direct(int32_t m, int32_t n, int32_t k) {
    return n <= 2 * kNr || m <= kMr || static_cast<int64_t>(m) * k <= 32 * 1024;
  }

  static void tile(int32_t k, const double* a, ptrdiff_t as, const double* b, ptrdiff_t bs,
                   double* c, ptrdiff_t ldc, int32_t rows, int32_t cols, int32_t diag) {
    const int32_t cidx = cols - 1;
    if (rows > 8) {
      TileRow<3>::fns[cidx](k, a, as, b, bs, c, ldc, rows, diag);
    } else if (rows > 4) {
      TileRow<2>::fns[cidx](k, a, as, b, bs, c, ldc, rows, diag);
    } else {
      TileRow<1>::fns[cidx](k, a, as, b, bs, c, ldc, rows, diag);
    }
  }

  static void pack(const double* a, ptrdiff_t lda, int32_t rows, int32_t k, double* dst) {
    pack12(a, lda, rows, k, dst);
  }

  // The pivot chain (sqrt, divide) dominates an 8 x 8 factorization, so the
  // scalar base case is as fast as a vector one would be here.
  static int32_t potrf_small(int32_t n, double* a, int32_t lda) {
    return potrf_unblocked(n, a, lda);
  }

  static void trsm_small(int32_t m, int32_t n, const double* l, int32_t ldl, double* b,
                         int32_t ldb) {
    switch (n) {
      case 1:
        trsm_fixed<1>(m, l, ldl, b, ldb);
        break;
      case 2:
        trsm_fixed<2>(m, l, ldl, b, ldb);
        break;
      case 3:
        trsm_fixed<3>(m, l, ldl, b, ldb);
        break;
      case 4:
        trsm_fixed<4>(m, l, ldl, b, ldb);
        break;
      case 5:
        trsm_fixed<5>(m, l, ldl, b, ldb);
        break;
      case 6:
        trsm_fixed<6>(m, l, ldl, b, ldb);
        break;
      case 7:
        trsm_fixed<7>(m, l, ldl, b, ldb);
        break;
      default:
        trsm_fixed<8>(m, l, ldl, b, ldb);
        break;
    }
  }
};

constexpr DenseKernels kAvx2 = Blocked<Avx2Tile>::table(SimdLevel::kAvx2);

}  // namespace

const DenseKernels* avx2_table() { return &kAvx2; }

}  // namespace dense_detail
}  // namespace gab

#else  // !defined(__x86_64__)

namespace gab {
namespace dense_detail {
const DenseKernels* avx2_table() { return nullptr; }
}  // namespace dense_detail
}  // namespace gab

#endif
