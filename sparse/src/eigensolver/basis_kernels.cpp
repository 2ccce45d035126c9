// Written once over a vector of W doubles and compiled per SIMD level (the
// solve kernels' scheme, kernels/simd_vec.h). The reductions of project()
// sum in a width-dependent order, so levels differ in rounding only.
#include "eigensolver/basis_kernels.h"

#include "kernels/simd_vec.h"

namespace gab {
namespace eigen_detail {

namespace {

using simd::Vec;

// a * b + c as written: the build keeps products and sums apart
// (-ffp-contract=off), as the solve kernels do; these loops are bound by
// reading V, not by the arithmetic.
template <class T>
GAB_INLINE T madd(T a, T b, T c) {
  return a * b + c;
}

// P[c..c+Q, 0..R] = V[:, c..c+Q]^T X[:, 0..R]: Q x R accumulators, V's Q
// columns read once.
template <int W, int Q, int R>
GAB_INLINE void project_columns(int32_t n, const double* v, const double* x, double* p, int32_t ldp) {
  using V = Vec<W>;
  typename V::type acc[Q][R];
  for (int q = 0; q < Q; ++q)
    for (int r = 0; r < R; ++r) acc[q][r] = V::splat(0.0);
  int32_t t = 0;
  for (; t + W <= n; t += W) {
    typename V::type vq[Q];
    for (int q = 0; q < Q; ++q) vq[q] = V::load(v + static_cast<int64_t>(q) * n + t);
    for (int r = 0; r < R; ++r) {
      const typename V::type xr = V::load(x + static_cast<int64_t>(r) * n + t);
      for (int q = 0; q < Q; ++q) acc[q][r] = madd(vq[q], xr, acc[q][r]);
    }
  }
  for (int q = 0; q < Q; ++q) {
    for (int r = 0; r < R; ++r) {
      double s = V::sum(acc[q][r]);
      for (int32_t u = t; u < n; ++u) s += v[static_cast<int64_t>(q) * n + u] * x[static_cast<int64_t>(r) * n + u];
      p[q + static_cast<int64_t>(r) * ldp] = s;
    }
  }
}

template <int W, int Q, int R>
GAB_INLINE void project_fixed(int32_t n, int32_t cols, const double* v, const double* x, double* p, int32_t ldp) {
  int32_t c = 0;
  for (; c + Q <= cols; c += Q) project_columns<W, Q, R>(n, v + static_cast<int64_t>(c) * n, x, p + c, ldp);
  for (; c < cols; ++c) project_columns<W, 1, R>(n, v + static_cast<int64_t>(c) * n, x, p + c, ldp);
}

// X[:, 0..R] -= V[:, c..c+4] P[c..c+4, :]: four columns of V per sweep, so
// X is read and written a quarter as often as V.
template <int W, int R>
GAB_INLINE void subtract_fixed(int32_t n, int32_t cols, const double* v, const double* p, int32_t ldp, double* x) {
  using V = Vec<W>;
  int32_t c = 0;
  for (; c + 4 <= cols; c += 4) {
    const double* v0 = v + static_cast<int64_t>(c) * n;
    const double* v1 = v0 + n;
    const double* v2 = v1 + n;
    const double* v3 = v2 + n;
    typename V::type h[4][R];
    for (int q = 0; q < 4; ++q)
      for (int r = 0; r < R; ++r) h[q][r] = V::splat(-p[c + q + static_cast<int64_t>(r) * ldp]);
    int32_t t = 0;
    for (; t + W <= n; t += W) {
      const typename V::type a0 = V::load(v0 + t), a1 = V::load(v1 + t), a2 = V::load(v2 + t), a3 = V::load(v3 + t);
      for (int r = 0; r < R; ++r) {
        double* xr = x + static_cast<int64_t>(r) * n + t;
        typename V::type s = V::load(xr);
        s = madd(a0, h[0][r], s);
        s = madd(a1, h[1][r], s);
        s = madd(a2, h[2][r], s);
        s = madd(a3, h[3][r], s);
        V::store(xr, s);
      }
    }
    for (; t < n; ++t) {
      for (int r = 0; r < R; ++r) {
        double& xr = x[static_cast<int64_t>(r) * n + t];
        for (int q = 0; q < 4; ++q) xr -= v[static_cast<int64_t>(c + q) * n + t] * p[c + q + static_cast<int64_t>(r) * ldp];
      }
    }
  }
  for (; c < cols; ++c) {
    const double* vc = v + static_cast<int64_t>(c) * n;
    for (int r = 0; r < R; ++r) {
      const double h = p[c + static_cast<int64_t>(r) * ldp];
      double* xr = x + static_cast<int64_t>(r) * n;
      for (int32_t t = 0; t < n; ++t) xr[t] -= vc[t] * h;
    }
  }
}

// Run-time w onto the compiled column counts, eight at a time.
template <int W, int Q>
GAB_INLINE void project_body(int32_t n, int32_t cols, int32_t w, const double* v, const double* x, double* p,
                             int32_t ldp) {
  for (int32_t r0 = 0; r0 < w; r0 += 8) {
    const int32_t rw = w - r0 < 8 ? w - r0 : 8;
    const double* xr = x + static_cast<int64_t>(r0) * n;
    double* pr = p + static_cast<int64_t>(r0) * ldp;
#define GAB_CALL(R) project_fixed<W, Q, R>(n, cols, v, xr, pr, ldp)
    switch (rw) {
      case 1: GAB_CALL(1); break;
      case 2: GAB_CALL(2); break;
      case 3: GAB_CALL(3); break;
      case 4: GAB_CALL(4); break;
      case 5: GAB_CALL(5); break;
      case 6: GAB_CALL(6); break;
      case 7: GAB_CALL(7); break;
      default: GAB_CALL(8); break;
    }
#undef GAB_CALL
  }
}

template <int W>
GAB_INLINE void subtract_body(int32_t n, int32_t cols, int32_t w, const double* v, const double* p, int32_t ldp,
                              double* x) {
  for (int32_t r0 = 0; r0 < w; r0 += 8) {
    const int32_t rw = w - r0 < 8 ? w - r0 : 8;
    double* xr = x + static_cast<int64_t>(r0) * n;
    const double* pr = p + static_cast<int64_t>(r0) * ldp;
#define GAB_CALL(R) subtract_fixed<W, R>(n, cols, v, pr, ldp, xr)
    switch (rw) {
      case 1: GAB_CALL(1); break;
      case 2: GAB_CALL(2); break;
      case 3: GAB_CALL(3); break;
      case 4: GAB_CALL(4); break;
      case 5: GAB_CALL(5); break;
      case 6: GAB_CALL(6); break;
      case 7: GAB_CALL(7); break;
      default: GAB_CALL(8); break;
    }
#undef GAB_CALL
  }
}

// Q: V columns per projection sweep, so that Q x 8 accumulators and the
// loads fit the level's registers (32 zmm; 16 ymm).
#define GAB_BASIS_KERNELS(SUFFIX, WIDTH, Q, ATTR)                                                                \
  ATTR void project_##SUFFIX(int32_t n, int32_t cols, int32_t w, const double* v, const double* x, double* p,   \
                             int32_t ldp) {                                                                     \
    project_body<WIDTH, Q>(n, cols, w, v, x, p, ldp);                                                           \
  }                                                                                                             \
  ATTR void subtract_##SUFFIX(int32_t n, int32_t cols, int32_t w, const double* v, const double* p, int32_t ldp, \
                              double* x) {                                                                      \
    subtract_body<WIDTH>(n, cols, w, v, p, ldp, x);                                                             \
  }

GAB_BASIS_KERNELS(scalar, 1, 1, )
#if defined(__x86_64__) && defined(__GNUC__)
GAB_BASIS_KERNELS(avx2, 4, 1, __attribute__((target("avx2"))))
GAB_BASIS_KERNELS(avx512, 8, 3, __attribute__((target("avx512f,avx512vl"))))
#endif

const BasisKernels kScalar = {SimdLevel::kScalar, project_scalar, subtract_scalar};
#if defined(__x86_64__) && defined(__GNUC__)
const BasisKernels kAvx2 = {SimdLevel::kAvx2, project_avx2, subtract_avx2};
const BasisKernels kAvx512 = {SimdLevel::kAvx512, project_avx512, subtract_avx512};
#endif

}  // namespace

const BasisKernels& basis_kernels(SimdLevel level) {
  switch (dense_kernels(level).level) {
#if defined(__x86_64__) && defined(__GNUC__)
    case SimdLevel::kAvx512: return kAvx512;
    case SimdLevel::kAvx2: return kAvx2;
#endif
    default: return kScalar;
  }
}

}  // namespace eigen_detail
}  // namespace gab
