// Solve kernels, written once over a vector type of W doubles (GCC/Clang
// vector extensions) and compiled three times: W = 1 portable, W = 4 with
// AVX2, W = 8 with AVX-512 (per-function target attributes, chosen at run
// time). Products and sums are kept separate (no FMA) and every elementwise
// update follows the scalar order, so the axpy-form kernels give identical
// results at every width; only the dot-form reductions (transposed solves)
// sum in a width-dependent order.
#include "kernels/solve_kernels.h"

#include "kernels/simd_vec.h"

namespace gab {
namespace solve_detail {

namespace {

using simd::Vec;

// The solves stream L from memory several columns at a time; hinting the
// lines a little ahead keeps the four streams in flight (the hardware
// prefetcher alone leaves the loop waiting on loads).
constexpr int32_t kPrefetchAhead = 64;  // doubles (eight cache lines) ahead

GAB_INLINE void prefetch_columns(const double* b0, const double* b1, const double* b2,
                                 const double* b3, int32_t t) {
#if defined(__GNUC__)
  __builtin_prefetch(b0 + t + kPrefetchAhead);
  __builtin_prefetch(b1 + t + kPrefetchAhead);
  __builtin_prefetch(b2 + t + kPrefetchAhead);
  __builtin_prefetch(b3 + t + kPrefetchAhead);
#else
  (void)b0, (void)b1, (void)b2, (void)b3, (void)t;
#endif
}

// Right-hand sides handled together in the streaming kernels.
constexpr int kMaxR = 4;

// OUT (p x R, ldo) -= B X for R right-hand sides, B p x k (ldb), X k x R
// (ldx); four columns of B per sweep over the rows so OUT is read and
// written a quarter as often.
template <int W, int R>
GAB_INLINE void gemm_nn_sub_fixed(int32_t p, int32_t k, const double* b, int32_t ldb,
                                  const double* x, int32_t ldx, double* out, int32_t ldo) {
  using V = Vec<W>;
  int32_t c = 0;
  for (; c + 4 <= k; c += 4) {
    const double* b0 = b + static_cast<int64_t>(c) * ldb;
    const double* b1 = b0 + ldb;
    const double* b2 = b1 + ldb;
    const double* b3 = b2 + ldb;
    double xs[4][R];
    for (int r = 0; r < R; ++r) {
      for (int q = 0; q < 4; ++q) xs[q][r] = x[static_cast<int64_t>(r) * ldx + c + q];
    }
    int32_t t = 0;
    for (; t + W <= p; t += W) {
      prefetch_columns(b0, b1, b2, b3, t);
      const typename V::type l0 = V::load(b0 + t), l1 = V::load(b1 + t), l2 = V::load(b2 + t),
                             l3 = V::load(b3 + t);
      for (int r = 0; r < R; ++r) {
        double* o = out + static_cast<int64_t>(r) * ldo + t;
        V::store(o, V::load(o) - (l0 * V::splat(xs[0][r]) + l1 * V::splat(xs[1][r]) +
                                  l2 * V::splat(xs[2][r]) + l3 * V::splat(xs[3][r])));
      }
    }
    for (; t < p; ++t) {
      for (int r = 0; r < R; ++r) {
        out[static_cast<int64_t>(r) * ldo + t] -=
            b0[t] * xs[0][r] + b1[t] * xs[1][r] + b2[t] * xs[2][r] + b3[t] * xs[3][r];
      }
    }
  }
  for (; c < k; ++c) {
    const double* bc = b + static_cast<int64_t>(c) * ldb;
    for (int r = 0; r < R; ++r) {
      const double xc = x[static_cast<int64_t>(r) * ldx + c];
      double* o = out + static_cast<int64_t>(r) * ldo;
      int32_t t = 0;
      for (; t + W <= p; t += W) V::store(o + t, V::load(o + t) - V::load(bc + t) * V::splat(xc));
      for (; t < p; ++t) o[t] -= bc[t] * xc;
    }
  }
}

// X (k x R, ldx) -= B^T Y for R right-hand sides, B p x k (ldb), Y p x R
// (ldy): dot products of four columns of B with every Y column per sweep.
template <int W, int R>
GAB_INLINE void gemm_tn_sub_fixed(int32_t p, int32_t k, const double* b, int32_t ldb,
                                  const double* y, int32_t ldy, double* x, int32_t ldx) {
  using V = Vec<W>;
  int32_t c = 0;
  for (; c + 4 <= k; c += 4) {
    const double* b0 = b + static_cast<int64_t>(c) * ldb;
    const double* b1 = b0 + ldb;
    const double* b2 = b1 + ldb;
    const double* b3 = b2 + ldb;
    typename V::type acc[4][R];
    for (int q = 0; q < 4; ++q)
      for (int r = 0; r < R; ++r) acc[q][r] = V::splat(0.0);
    int32_t t = 0;
    for (; t + W <= p; t += W) {
      prefetch_columns(b0, b1, b2, b3, t);
      const typename V::type l0 = V::load(b0 + t), l1 = V::load(b1 + t), l2 = V::load(b2 + t),
                             l3 = V::load(b3 + t);
      for (int r = 0; r < R; ++r) {
        const typename V::type yr = V::load(y + static_cast<int64_t>(r) * ldy + t);
        acc[0][r] += l0 * yr;
        acc[1][r] += l1 * yr;
        acc[2][r] += l2 * yr;
        acc[3][r] += l3 * yr;
      }
    }
    for (int r = 0; r < R; ++r) {
      double sum[4] = {V::sum(acc[0][r]), V::sum(acc[1][r]), V::sum(acc[2][r]), V::sum(acc[3][r])};
      for (int32_t u = t; u < p; ++u) {
        const double yu = y[static_cast<int64_t>(r) * ldy + u];
        sum[0] += b0[u] * yu;
        sum[1] += b1[u] * yu;
        sum[2] += b2[u] * yu;
        sum[3] += b3[u] * yu;
      }
      for (int q = 0; q < 4; ++q) x[static_cast<int64_t>(r) * ldx + c + q] -= sum[q];
    }
  }
  for (; c < k; ++c) {
    const double* bc = b + static_cast<int64_t>(c) * ldb;
    for (int r = 0; r < R; ++r) {
      const double* yr = y + static_cast<int64_t>(r) * ldy;
      typename V::type acc = V::splat(0.0);
      int32_t t = 0;
      for (; t + W <= p; t += W) acc += V::load(bc + t) * V::load(yr + t);
      double sum = V::sum(acc);
      for (; t < p; ++t) sum += bc[t] * yr[t];
      x[static_cast<int64_t>(r) * ldx + c] -= sum;
    }
  }
}

// Triangular solves in blocks of four columns: a scalar 4 x 4 triangle,
// then the rest of the block column through the streaming kernels above.
template <int W, int R>
GAB_INLINE void trsm_lower_fixed(int32_t k, const double* l, int32_t ldl, double* x, int32_t ldx) {
  for (int32_t c0 = 0; c0 < k; c0 += 4) {
    const int32_t cb = k - c0 < 4 ? k - c0 : 4;
    // Right-hand sides innermost: their division chains are independent
    // and overlap in the pipeline.
    for (int32_t c = c0; c < c0 + cb; ++c) {
      const double* lc = l + static_cast<int64_t>(c) * ldl;
      for (int r = 0; r < R; ++r) {
        double* xr = x + static_cast<int64_t>(r) * ldx;
        xr[c] /= lc[c];
        for (int32_t i = c + 1; i < c0 + cb; ++i) xr[i] -= lc[i] * xr[c];
      }
    }
    const int32_t rest = k - c0 - cb;
    if (rest > 0) {
      gemm_nn_sub_fixed<W, R>(rest, cb, l + static_cast<int64_t>(c0) * ldl + c0 + cb, ldl, x + c0,
                              ldx, x + c0 + cb, ldx);
    }
  }
}

template <int W, int R>
GAB_INLINE void trsm_lower_trans_fixed(int32_t k, const double* l, int32_t ldl, double* x,
                                       int32_t ldx) {
  for (int32_t c0 = (k - 1) / 4 * 4; c0 >= 0; c0 -= 4) {
    const int32_t cb = k - c0 < 4 ? k - c0 : 4;
    const int32_t rest = k - c0 - cb;
    if (rest > 0) {
      gemm_tn_sub_fixed<W, R>(rest, cb, l + static_cast<int64_t>(c0) * ldl + c0 + cb, ldl,
                              x + c0 + cb, ldx, x + c0, ldx);
    }
    for (int32_t c = c0 + cb - 1; c >= c0; --c) {
      const double* lc = l + static_cast<int64_t>(c) * ldl;
      for (int r = 0; r < R; ++r) {
        double* xr = x + static_cast<int64_t>(r) * ldx;
        double v = xr[c];
        for (int32_t i = c + 1; i < c0 + cb; ++i) v -= lc[i] * xr[i];
        xr[c] = v / lc[c];
      }
    }
  }
}

// Run-time right-hand-side counts: unrolled up to kMaxR, larger counts in
// chunks of kMaxR.
#define GAB_FOR_RHS_CHUNKS(CALL)                                 \
  for (int32_t r0 = 0; r0 < nrhs; r0 += kMaxR) {                 \
    switch (nrhs - r0 >= kMaxR ? kMaxR : nrhs - r0) {            \
      case 1: CALL(1); break;                                    \
      case 2: CALL(2); break;                                    \
      case 3: CALL(3); break;                                    \
      default: CALL(4); break;                                   \
    }                                                            \
  }

template <int W>
GAB_INLINE void trsm_lower_body(int32_t k, int32_t nrhs, const double* l, int32_t ldl, double* x,
                                int32_t ldx) {
#define GAB_CALL(R) trsm_lower_fixed<W, R>(k, l, ldl, x + static_cast<int64_t>(r0) * ldx, ldx)
  GAB_FOR_RHS_CHUNKS(GAB_CALL)
#undef GAB_CALL
}

template <int W>
GAB_INLINE void trsm_lower_trans_body(int32_t k, int32_t nrhs, const double* l, int32_t ldl,
                                      double* x, int32_t ldx) {
#define GAB_CALL(R) trsm_lower_trans_fixed<W, R>(k, l, ldl, x + static_cast<int64_t>(r0) * ldx, ldx)
  GAB_FOR_RHS_CHUNKS(GAB_CALL)
#undef GAB_CALL
}

// W = -B X (zero, then subtract-accumulate); the caller adds W to the rows
// below.
template <int W>
GAB_INLINE void gemm_nn_body(int32_t p, int32_t k, int32_t nrhs, const double* b, int32_t ldb,
                             const double* x, int32_t ldx, double* w) {
  for (int64_t t = 0; t < static_cast<int64_t>(p) * nrhs; ++t) w[t] = 0.0;
#define GAB_CALL(R)                                                                      \
  gemm_nn_sub_fixed<W, R>(p, k, b, ldb, x + static_cast<int64_t>(r0) * ldx, ldx,        \
                          w + static_cast<int64_t>(r0) * p, p)
  GAB_FOR_RHS_CHUNKS(GAB_CALL)
#undef GAB_CALL
}

template <int W>
GAB_INLINE void gemm_tn_body(int32_t p, int32_t k, int32_t nrhs, const double* b, int32_t ldb,
                             const double* w, double* x, int32_t ldx) {
#define GAB_CALL(R)                                                                   \
  gemm_tn_sub_fixed<W, R>(p, k, b, ldb, w + static_cast<int64_t>(r0) * p, p,         \
                          x + static_cast<int64_t>(r0) * ldx, ldx)
  GAB_FOR_RHS_CHUNKS(GAB_CALL)
#undef GAB_CALL
}

// One set of entry points per level; the attribute makes the inlined
// bodies compile for that instruction set.
#define GAB_SOLVE_KERNELS(SUFFIX, WIDTH, ATTR)                                                  \
  ATTR void trsm_lower_##SUFFIX(int32_t k, int32_t nrhs, const double* l, int32_t ldl,         \
                                double* x, int32_t ldx) {                                       \
    trsm_lower_body<WIDTH>(k, nrhs, l, ldl, x, ldx);                                            \
  }                                                                                             \
  ATTR void trsm_lower_trans_##SUFFIX(int32_t k, int32_t nrhs, const double* l, int32_t ldl,   \
                                      double* x, int32_t ldx) {                                 \
    trsm_lower_trans_body<WIDTH>(k, nrhs, l, ldl, x, ldx);                                      \
  }                                                                                             \
  ATTR void gemm_nn_neg_##SUFFIX(int32_t p, int32_t k, int32_t nrhs, const double* b, int32_t ldb, \
                             const double* x, int32_t ldx, double* w) {                         \
    gemm_nn_body<WIDTH>(p, k, nrhs, b, ldb, x, ldx, w);                                         \
  }                                                                                             \
  ATTR void gemm_tn_sub_##SUFFIX(int32_t p, int32_t k, int32_t nrhs, const double* b,          \
                                 int32_t ldb, const double* w, double* x, int32_t ldx) {        \
    gemm_tn_body<WIDTH>(p, k, nrhs, b, ldb, w, x, ldx);                                         \
  }

GAB_SOLVE_KERNELS(scalar, 1, )
#if defined(__x86_64__) && defined(__GNUC__)
GAB_SOLVE_KERNELS(avx2, 4, __attribute__((target("avx2"))))
GAB_SOLVE_KERNELS(avx512, 8, __attribute__((target("avx512f,avx512vl"))))
#endif

const SolveKernels kScalar = {SimdLevel::kScalar, trsm_lower_scalar, trsm_lower_trans_scalar,
                              gemm_nn_neg_scalar, gemm_tn_sub_scalar};
#if defined(__x86_64__) && defined(__GNUC__)
const SolveKernels kAvx2 = {SimdLevel::kAvx2, trsm_lower_avx2, trsm_lower_trans_avx2, gemm_nn_neg_avx2,
                            gemm_tn_sub_avx2};
const SolveKernels kAvx512 = {SimdLevel::kAvx512, trsm_lower_avx512, trsm_lower_trans_avx512,
                              gemm_nn_neg_avx512, gemm_tn_sub_avx512};
#endif

}  // namespace

const SolveKernels& solve_kernels(SimdLevel level) {
  // dense_kernels() clamps the level to what the CPU supports.
  switch (dense_kernels(level).level) {
#if defined(__x86_64__) && defined(__GNUC__)
    case SimdLevel::kAvx512: return kAvx512;
    case SimdLevel::kAvx2: return kAvx2;
#endif
    default: return kScalar;
  }
}

}  // namespace solve_detail
}  // namespace gab
