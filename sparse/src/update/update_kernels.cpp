// Row-rotation kernels of the updater, written once over simd::Vec<W> and
// compiled per SIMD level. Rows are independent, so W rows are rotated at a
// time while x stays in a register across the whole run of rotations: the
// block is read and written exactly once. No FMA, and the same operation
// order at every width, so all levels give bit-identical factors.
#include "update/update_kernels.h"

#include "kernels/simd_vec.h"

namespace gab {
namespace update_detail {

namespace {

using simd::Vec;

// Full unrolling of the loops over the batch's vectors lets the compiler
// keep the per-vector arrays in registers instead of on the stack.
#if defined(__clang__)
#define GAB_UNROLL _Pragma("unroll")
#elif defined(__GNUC__)
#define GAB_UNROLL _Pragma("GCC unroll 8")
#else
#define GAB_UNROLL
#endif

template <int W>
GAB_INLINE void rotate_rows_body(int32_t p, int32_t ncols, const double* c, const double* s,
                                 double* l, int32_t ld, double* x) {
  using V = Vec<W>;
  typedef typename V::type T;
  int32_t t = 0;
  // Four row chunks at a time: each chunk's x is one chain of dependent
  // rotations through the run, and four chains keep the pipeline full.
  for (; t + 4 * W <= p; t += 4 * W) {
    T x0 = V::load(x + t), x1 = V::load(x + t + W), x2 = V::load(x + t + 2 * W),
      x3 = V::load(x + t + 3 * W);
    for (int32_t q = 0; q < ncols; ++q) {
      double* lq = l + static_cast<int64_t>(q) * ld + t;
      const T l0 = V::load(lq), l1 = V::load(lq + W), l2 = V::load(lq + 2 * W),
              l3 = V::load(lq + 3 * W);
      const T cq = V::splat(c[q]), sq = V::splat(s[q]);
      V::store(lq, cq * l0 + sq * x0);
      V::store(lq + W, cq * l1 + sq * x1);
      V::store(lq + 2 * W, cq * l2 + sq * x2);
      V::store(lq + 3 * W, cq * l3 + sq * x3);
      x0 = cq * x0 - sq * l0;
      x1 = cq * x1 - sq * l1;
      x2 = cq * x2 - sq * l2;
      x3 = cq * x3 - sq * l3;
    }
    V::store(x + t, x0);
    V::store(x + t + W, x1);
    V::store(x + t + 2 * W, x2);
    V::store(x + t + 3 * W, x3);
  }
  for (; t + W <= p; t += W) {
    T xv = V::load(x + t);
    for (int32_t q = 0; q < ncols; ++q) {
      double* lq = l + static_cast<int64_t>(q) * ld + t;
      const T lv = V::load(lq);
      const T cq = V::splat(c[q]), sq = V::splat(s[q]);
      V::store(lq, cq * lv + sq * xv);
      xv = cq * xv - sq * lv;
    }
    V::store(x + t, xv);
  }
  for (; t < p; ++t) {
    double xv = x[t];
    for (int32_t q = 0; q < ncols; ++q) {
      double* lq = l + static_cast<int64_t>(q) * ld + t;
      const double lv = *lq;
      *lq = c[q] * lv + s[q] * xv;
      xv = c[q] * xv - s[q] * lv;
    }
    x[t] = xv;
  }
}

template <int W>
GAB_INLINE void rotate_rows_reverse_body(int32_t p, int32_t ncols, const double* c,
                                         const double* s, double* l, int32_t ld, double* x) {
  using V = Vec<W>;
  int32_t t = 0;
  for (; t + W <= p; t += W) {
    typename V::type xv = V::load(x + t);
    for (int32_t q = ncols - 1; q >= 0; --q) {
      double* lq = l + static_cast<int64_t>(q) * ld + t;
      const typename V::type lv = V::load(lq);
      const typename V::type cq = V::splat(c[q]), sq = V::splat(s[q]);
      V::store(lq, cq * lv - sq * xv);
      xv = cq * xv + sq * lv;
    }
    V::store(x + t, xv);
  }
  for (; t < p; ++t) {
    double xv = x[t];
    for (int32_t q = ncols - 1; q >= 0; --q) {
      double* lq = l + static_cast<int64_t>(q) * ld + t;
      const double lv = *lq;
      *lq = c[q] * lv - s[q] * xv;
      xv = c[q] * xv + s[q] * lv;
    }
    x[t] = xv;
  }
}

// Each column's entry passes through NV dependent rotations, so one row
// chunk alone is bound by their latency; two chunks are interleaved so the
// two chains overlap (2 * NV vectors of x stay in registers).
template <int W, int NV>
GAB_INLINE void rotate_rows_batch_fixed(int32_t p, int32_t ncols, const double* c, const double* s,
                                        double* l, int32_t ld, double* x, int32_t ldx) {
  using V = Vec<W>;
  typedef typename V::type T;
  int32_t t = 0;
  for (; t + 2 * W <= p; t += 2 * W) {
    T xa[NV], xb[NV];
    GAB_UNROLL
    for (int v = 0; v < NV; ++v) {
      xa[v] = V::load(x + static_cast<int64_t>(v) * ldx + t);
      xb[v] = V::load(x + static_cast<int64_t>(v) * ldx + t + W);
    }
    for (int32_t q = 0; q < ncols; ++q) {
      double* lq = l + static_cast<int64_t>(q) * ld + t;
      T la = V::load(lq), lb = V::load(lq + W);
      GAB_UNROLL
    for (int v = 0; v < NV; ++v) {
        const T cq = V::splat(c[q * NV + v]), sq = V::splat(s[q * NV + v]);
        const T ra = cq * la + sq * xa[v];
        const T rb = cq * lb + sq * xb[v];
        xa[v] = cq * xa[v] - sq * la;
        xb[v] = cq * xb[v] - sq * lb;
        la = ra;
        lb = rb;
      }
      V::store(lq, la);
      V::store(lq + W, lb);
    }
    GAB_UNROLL
    for (int v = 0; v < NV; ++v) {
      V::store(x + static_cast<int64_t>(v) * ldx + t, xa[v]);
      V::store(x + static_cast<int64_t>(v) * ldx + t + W, xb[v]);
    }
  }
  for (; t < p; ++t) {
    double xv[NV];
    GAB_UNROLL
    for (int v = 0; v < NV; ++v) xv[v] = x[static_cast<int64_t>(v) * ldx + t];
    for (int32_t q = 0; q < ncols; ++q) {
      double* lq = l + static_cast<int64_t>(q) * ld + t;
      double lv = *lq;
      GAB_UNROLL
    for (int v = 0; v < NV; ++v) {
        const double cq = c[q * NV + v], sq = s[q * NV + v];
        const double rotated = cq * lv + sq * xv[v];
        xv[v] = cq * xv[v] - sq * lv;
        lv = rotated;
      }
      *lq = lv;
    }
    GAB_UNROLL
    for (int v = 0; v < NV; ++v) x[static_cast<int64_t>(v) * ldx + t] = xv[v];
  }
}

template <int W>
GAB_INLINE void rotate_rows_batch_body(int32_t p, int32_t ncols, int32_t nvec, const double* c,
                                       const double* s, double* l, int32_t ld, double* x,
                                       int32_t ldx) {
  switch (nvec) {
    case 1: rotate_rows_batch_fixed<W, 1>(p, ncols, c, s, l, ld, x, ldx); break;
    case 2: rotate_rows_batch_fixed<W, 2>(p, ncols, c, s, l, ld, x, ldx); break;
    case 3: rotate_rows_batch_fixed<W, 3>(p, ncols, c, s, l, ld, x, ldx); break;
    case 4: rotate_rows_batch_fixed<W, 4>(p, ncols, c, s, l, ld, x, ldx); break;
    case 5: rotate_rows_batch_fixed<W, 5>(p, ncols, c, s, l, ld, x, ldx); break;
    case 6: rotate_rows_batch_fixed<W, 6>(p, ncols, c, s, l, ld, x, ldx); break;
    case 7: rotate_rows_batch_fixed<W, 7>(p, ncols, c, s, l, ld, x, ldx); break;
    default: rotate_rows_batch_fixed<W, 8>(p, ncols, c, s, l, ld, x, ldx); break;
  }
}

#define GAB_UPDATE_KERNELS(SUFFIX, WIDTH, ATTR)                                                \
  ATTR void rotate_rows_##SUFFIX(int32_t p, int32_t ncols, const double* c, const double* s,  \
                                 double* l, int32_t ld, double* x) {                           \
    rotate_rows_body<WIDTH>(p, ncols, c, s, l, ld, x);                                         \
  }                                                                                            \
  ATTR void rotate_rows_reverse_##SUFFIX(int32_t p, int32_t ncols, const double* c,           \
                                         const double* s, double* l, int32_t ld, double* x) {  \
    rotate_rows_reverse_body<WIDTH>(p, ncols, c, s, l, ld, x);                                 \
  }                                                                                            \
  ATTR void rotate_rows_batch_##SUFFIX(int32_t p, int32_t ncols, int32_t nvec, const double* c,\
                                       const double* s, double* l, int32_t ld, double* x,      \
                                       int32_t ldx) {                                          \
    rotate_rows_batch_body<WIDTH>(p, ncols, nvec, c, s, l, ld, x, ldx);                        \
  }

GAB_UPDATE_KERNELS(scalar, 1, )
#if defined(__x86_64__) && defined(__GNUC__)
GAB_UPDATE_KERNELS(avx2, 4, __attribute__((target("avx2"))))
GAB_UPDATE_KERNELS(avx512, 8, __attribute__((target("avx512f,avx512vl"))))
#endif

const UpdateKernels kScalar = {SimdLevel::kScalar, rotate_rows_scalar, rotate_rows_reverse_scalar,
                             rotate_rows_batch_scalar};
#if defined(__x86_64__) && defined(__GNUC__)
const UpdateKernels kAvx2 = {SimdLevel::kAvx2, rotate_rows_avx2, rotate_rows_reverse_avx2,
                           rotate_rows_batch_avx2};
const UpdateKernels kAvx512 = {SimdLevel::kAvx512, rotate_rows_avx512, rotate_rows_reverse_avx512,
                             rotate_rows_batch_avx512};
#endif

}  // namespace

const UpdateKernels& update_kernels(SimdLevel level) {
  switch (dense_kernels(level).level) {  // clamped to the CPU's level
#if defined(__x86_64__) && defined(__GNUC__)
    case SimdLevel::kAvx512: return kAvx512;
    case SimdLevel::kAvx2: return kAvx2;
#endif
    default: return kScalar;
  }
}

}  // namespace update_detail
}  // namespace gab
