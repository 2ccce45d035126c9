// AVX-512 level of the dense kernels (needs AVX512F/VL/DQ and FMA). Every
// function that touches a zmm register carries the target attribute, so this
// file builds with the project's baseline flags and is only entered after the
// run-time check in dense_kernels.cpp.
//
// Register tile: 24 x 8 (3 zmm of rows x 8 columns = 24 accumulators), the
// broadcast-FMA micro-kernel of Goto / BLIS: per step of the inner dimension
// 3 vector loads of A, 8 scalar broadcasts of B^T and 24 FMAs. 24
// accumulators cover the FMA latency x throughput product (2 pipes x 4
// cycles = 8 independent chains) three times over and leave 8 registers for
// the A vectors and broadcasts. Partial tiles use masks, never a scratch copy.
#include "kernels/dense_kernels_internal.h"

#if defined(__x86_64__)

#include <immintrin.h>

#define GAB_TARGET_AVX512 __attribute__((target("avx512f,avx512vl,avx512dq,fma")))

namespace gab {
namespace dense_detail {
namespace {

constexpr int32_t kMr = 24;
constexpr int32_t kNr = 8;

// Lanes [0, count) of an 8-lane mask, count in [0, 8].
inline __mmask8 first_lanes(int32_t count) { return static_cast<__mmask8>((1u << count) - 1u); }

// Lanes t with t >= from (from may be outside [0, 8]).
inline __mmask8 lanes_from(int32_t from) {
  if (from <= 0) return 0xFF;
  if (from >= 8) return 0;
  return static_cast<__mmask8>(0xFFu << from);
}

// C[0:rows, 0:NC] -= A B^T over k steps, rows in (8*(MV-1), 8*MV]. A is read
// 8*MV rows at a time with the last vector masked (so an unpacked A is
// never read past `rows`), B^T one broadcast per column.
template <int MV, int NC>
GAB_TARGET_AVX512 void tile_fixed(int32_t k, const double* a, ptrdiff_t as, const double* b,
                                  ptrdiff_t bs, double* c, ptrdiff_t ldc, int32_t rows,
                                  int32_t diag) {
  const __mmask8 tail = first_lanes(rows - 8 * (MV - 1));
// The tile's C columns are written once, at the end; fetching them now
// hides that miss behind the k loop.
#pragma GCC unroll 8
  for (int j = 0; j < NC; ++j) {
    _mm_prefetch(reinterpret_cast<const char*>(c + j * ldc), _MM_HINT_T0);
    _mm_prefetch(reinterpret_cast<const char*>(c + j * ldc + rows - 1), _MM_HINT_T0);
  }
  __m512d acc[MV][NC];
#pragma GCC unroll 8
  for (int v = 0; v < MV; ++v) {
#pragma GCC unroll 8
    for (int j = 0; j < NC; ++j) acc[v][j] = _mm512_setzero_pd();
  }
  for (int32_t p = 0; p < k; ++p) {
    __m512d av[MV];
#pragma GCC unroll 8
    for (int v = 0; v + 1 < MV; ++v) av[v] = _mm512_loadu_pd(a + 8 * v);
    av[MV - 1] = _mm512_maskz_loadu_pd(tail, a + 8 * (MV - 1));
#pragma GCC unroll 8
    for (int j = 0; j < NC; ++j) {
      const __m512d bj = _mm512_set1_pd(b[j]);
#pragma GCC unroll 8
      for (int v = 0; v < MV; ++v) acc[v][j] = _mm512_fmadd_pd(av[v], bj, acc[v][j]);
    }
    a += as;
    b += bs;
  }
  // Entry (r, j) is written iff r < rows and r + diag >= j (lower triangle
  // of a symmetric C); the second test only bites on diagonal tiles.
  const bool on_diagonal = diag < NC - 1;
#pragma GCC unroll 8
  for (int j = 0; j < NC; ++j) {
    double* cj = c + j * ldc;
#pragma GCC unroll 8
    for (int v = 0; v < MV; ++v) {
      __mmask8 mask = v + 1 < MV ? static_cast<__mmask8>(0xFF) : tail;
      if (on_diagonal) mask &= lanes_from(j - diag - 8 * v);
      const __m512d old = _mm512_maskz_loadu_pd(mask, cj + 8 * v);
      _mm512_mask_storeu_pd(cj + 8 * v, mask, _mm512_sub_pd(old, acc[v][j]));
    }
  }
}

// pack_panels with kMr = 24 rows: a panel step is three zmm copies, the
// partial last panel loads under masks (which also zero its padding).
GAB_TARGET_AVX512 void pack24(const double* a, ptrdiff_t lda, int32_t rows, int32_t k,
                              double* dst) {
  for (int32_t i = 0; i < rows; i += kMr) {
    const int32_t h = std::min(kMr, rows - i);
    const __mmask8 m0 = first_lanes(std::min(8, h));
    const __mmask8 m1 = first_lanes(std::min(8, std::max(0, h - 8)));
    const __mmask8 m2 = first_lanes(std::max(0, h - 16));
    const double* src = a + i;
    for (int32_t p = 0; p < k; ++p) {
      _mm512_storeu_pd(dst, _mm512_maskz_loadu_pd(m0, src));
      _mm512_storeu_pd(dst + 8, _mm512_maskz_loadu_pd(m1, src + 8));
      _mm512_storeu_pd(dst + 16, _mm512_maskz_loadu_pd(m2, src + 16));
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
                                      &tile_fixed<MV, 4>, &tile_fixed<MV, 5>, &tile_fixed<MV, 6>,
                                      &tile_fixed<MV, 7>, &tile_fixed<MV, 8>};
};

// potrf of an N x N block held entirely in registers, one zmm per column.
// Lane c of column j is broadcast with a permute, so the only scalar work is
// the pivot test.
//
// A tiny factorization is one long dependency chain through the pivots, so
// the trailing update is written in LDL^T form, a_ic -= a_ij (a_cj / d_j),
// with the Schur-complement column a_.j before scaling: the next pivot then
// waits for a divide, a multiply and an FMA, while the square root and the
// scaling of column j to l_.j = a_.j / sqrt(d_j) run beside the chain
// instead of in it (about half the latency of the textbook order). Same
// arithmetic up to rounding.
template <int N>
GAB_TARGET_AVX512 int32_t potrf_fixed(double* a, ptrdiff_t lda) {
  constexpr __mmask8 kRows = static_cast<__mmask8>((1u << N) - 1u);
  __m512d col[N];
// Only the lower triangle is loaded, and only it is stored back.
#pragma GCC unroll 8
  for (int j = 0; j < N; ++j) {
    col[j] = _mm512_maskz_loadu_pd(kRows & static_cast<__mmask8>(0xFFu << j), a + j * lda);
  }
  const __m512d one = _mm512_set1_pd(1.0);
  int32_t failed = -1;
  int done = 0;
#pragma GCC unroll 8
  for (int j = 0; j < N; ++j) {
    const __m512d djj = _mm512_maskz_permutexvar_pd(0xFF, _mm512_set1_epi64(j), col[j]);
    const double d = _mm512_cvtsd_f64(djj);
    if (!pivot_ok(d)) {
      failed = j;
      break;
    }
    const __m512d inv_d = _mm512_div_pd(one, djj);
#pragma GCC unroll 8
    for (int c = j + 1; c < N; ++c) {
      const __m512d acj = _mm512_maskz_permutexvar_pd(0xFF, _mm512_set1_epi64(c), col[j]);
      col[c] = _mm512_fnmadd_pd(col[j], _mm512_mul_pd(acj, inv_d), col[c]);
    }
    // Row j becomes sqrt(d) exactly; rows below are divided by it.
    const __m512d s = _mm512_maskz_sqrt_pd(0xFF, djj);
    col[j] = _mm512_mask_mov_pd(_mm512_div_pd(col[j], s), static_cast<__mmask8>(1u << j), s);
    done = j + 1;
  }
// On failure only the finished columns are written: the rest keep the
// caller's input.
#pragma GCC unroll 8
  for (int j = 0; j < N; ++j) {
    if (j < done) {
      _mm512_mask_storeu_pd(a + j * lda, kRows & static_cast<__mmask8>(0xFFu << j), col[j]);
    }
  }
  return failed;
}

// B := B L^{-T} for N <= 8 columns, rows [0, rows) with rows <= 8*MV: the
// 8*MV x N block of B lives in registers through the whole substitution.
template <int N, int MV>
GAB_TARGET_AVX512 void trsm_chunk(int32_t rows, const double* inv, const double* l, ptrdiff_t ldl,
                                  double* b, ptrdiff_t ldb) {
  __mmask8 mask[MV];
#pragma GCC unroll 8
  for (int v = 0; v < MV; ++v) {
    mask[v] = first_lanes(std::min<int32_t>(8, std::max<int32_t>(0, rows - 8 * v)));
  }
  __m512d x[MV][N];
#pragma GCC unroll 8
  for (int j = 0; j < N; ++j) {
#pragma GCC unroll 8
    for (int v = 0; v < MV; ++v) x[v][j] = _mm512_maskz_loadu_pd(mask[v], b + j * ldb + 8 * v);
  }
#pragma GCC unroll 8
  for (int j = 0; j < N; ++j) {
    const __m512d r = _mm512_set1_pd(inv[j]);
#pragma GCC unroll 8
    for (int v = 0; v < MV; ++v) x[v][j] = _mm512_mul_pd(x[v][j], r);
#pragma GCC unroll 8
    for (int c = j + 1; c < N; ++c) {
      const __m512d lcj = _mm512_set1_pd(l[c + j * ldl]);
#pragma GCC unroll 8
      for (int v = 0; v < MV; ++v) x[v][c] = _mm512_fnmadd_pd(x[v][j], lcj, x[v][c]);
    }
  }
#pragma GCC unroll 8
  for (int j = 0; j < N; ++j) {
#pragma GCC unroll 8
    for (int v = 0; v < MV; ++v) _mm512_mask_storeu_pd(b + j * ldb + 8 * v, mask[v], x[v][j]);
  }
}

template <int N>
GAB_TARGET_AVX512 void trsm_fixed(int32_t m, const double* l, int32_t ldl, double* b, int32_t ldb) {
  double inv[N];
#pragma GCC unroll 8
  for (int j = 0; j < N; ++j) inv[j] = 1.0 / l[j + j * static_cast<ptrdiff_t>(ldl)];
  int32_t i = 0;
  for (; i + kMr <= m; i += kMr) trsm_chunk<N, 3>(kMr, inv, l, ldl, b + i, ldb);
  const int32_t rest = m - i;
  if (rest > 16) {
    trsm_chunk<N, 3>(rest, inv, l, ldl, b + i, ldb);
  } else if (rest > 8) {
    trsm_chunk<N, 2>(rest, inv, l, ldl, b + i, ldb);
  } else if (rest > 0) {
    trsm_chunk<N, 1>(rest, inv, l, ldl, b + i, ldb);
  }
}

struct Avx512Tile {
  static constexpr int32_t kMr = 24;
  static constexpr int32_t kNr = 8;
  // kc x kNr doubles of packed B^T (20 KB) stay in the 48 KB L1 while a
  // kMc x kc block of packed A (480 KB) streams from the 1 MB L2.
  static constexpr int32_t kKc = 320;
  static constexpr int32_t kMc = 192;
  static constexpr int32_t kNc = 1536;
  static constexpr int32_t kSmall = 8;

  // Packing pays for itself only when a packed operand is reused: with few
  // column strips or few row tiles there is no reuse, and while A (m x k)
  // fits in L2 the unpacked tiles re-read it from there at full speed
  // (measured on Zen 5: unpacked stays ahead up to about 512 KB of A).
  static bool direct(int32_t m, int32_t n, int32_t k) {
    return n <= 2 * kNr || m <= kMr || static_cast<int64_t>(m) * k <= 64 * 1024;
  }

  static void tile(int32_t k, const double* a, ptrdiff_t as, const double* b, ptrdiff_t bs,
                   double* c, ptrdiff_t ldc, int32_t rows, int32_t cols, int32_t diag) {
    const int32_t cidx = cols - 1;
    if (rows > 16) {
      TileRow<3>::fns[cidx](k, a, as, b, bs, c, ldc, rows, diag);
    } else if (rows > 8) {
      TileRow<2>::fns[cidx](k, a, as, b, bs, c, ldc, rows, diag);
    } else {
      TileRow<1>::fns[cidx](k, a, as, b, bs, c, ldc, rows, diag);
    }
  }

  static void pack(const double* a, ptrdiff_t lda, int32_t rows, int32_t k, double* dst) {
    pack24(a, lda, rows, k, dst);
  }

  static int32_t potrf_small(int32_t n, double* a, int32_t lda) {
    // Up to 4 x 4 the scalar loop's shorter chain (no permutes, scalar
    // divides) is faster than the register version.
    if (n <= 4) return potrf_unblocked(n, a, lda);
    switch (n) {
      case 5:
        return potrf_fixed<5>(a, lda);
      case 6:
        return potrf_fixed<6>(a, lda);
      case 7:
        return potrf_fixed<7>(a, lda);
      default:
        return potrf_fixed<8>(a, lda);
    }
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

constexpr DenseKernels kAvx512 = Blocked<Avx512Tile>::table(SimdLevel::kAvx512);

}  // namespace

const DenseKernels* avx512_table() { return &kAvx512; }

}  // namespace dense_detail
}  // namespace gab

#else  // !defined(__x86_64__)

namespace gab {
namespace dense_detail {
const DenseKernels* avx512_table() { return nullptr; }
}  // namespace dense_detail
}  // namespace gab

#endif
