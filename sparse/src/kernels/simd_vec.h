// Portable fixed-width vectors for the engine's streaming kernels
// (internal). Kernels are written once over Vec<W> and compiled per SIMD
// level with a per-function target attribute: W = 1 is plain double, W = 4
// needs AVX2, W = 8 AVX-512. Only GCC/Clang vector extensions are used, so
// the same source builds everywhere; the x86 instantiations are guarded.
#pragma once

#include <cstring>

namespace gab {
namespace simd {

#if defined(__GNUC__)
#define GAB_INLINE inline __attribute__((always_inline))
#else
#define GAB_INLINE inline
#endif

// The vector types below never cross a call boundary (every user is
// always_inline into a function compiled for the matching instruction set),
// so GCC's note that their ABI depends on -mavx does not apply.
#if defined(__clang__)
#pragma clang diagnostic ignored "-Wpsabi"
#elif defined(__GNUC__)
#pragma GCC diagnostic ignored "-Wpsabi"
#endif

// Vector types by width. GCC drops vector_size on a template-dependent
// typedef, so each width names its type explicitly.
typedef double v4d __attribute__((vector_size(32)));
typedef double v8d __attribute__((vector_size(64)));

template <typename T, int W>
struct VecOps {
  typedef T type;
  static GAB_INLINE type load(const double* p) {
    type v;
    std::memcpy(&v, p, sizeof(v));
    return v;
  }
  static GAB_INLINE void store(double* p, type v) { std::memcpy(p, &v, sizeof(v)); }
  static GAB_INLINE type splat(double s) {
    type v;
    for (int i = 0; i < W; ++i) v[i] = s;
    return v;
  }
  static GAB_INLINE double sum(type v) {
    double s = 0.0;
    for (int i = 0; i < W; ++i) s += v[i];
    return s;
  }
};

template <int W>
struct Vec;
template <>
struct Vec<4> : VecOps<v4d, 4> {};
template <>
struct Vec<8> : VecOps<v8d, 8> {};
// Width 1: plain double.
template <>
struct Vec<1> {
  typedef double type;
  static GAB_INLINE type load(const double* p) { return *p; }
  static GAB_INLINE void store(double* p, type v) { *p = v; }
  static GAB_INLINE type splat(double s) { return s; }
  static GAB_INLINE double sum(type v) { return v; }
};

}  // namespace simd
}  // namespace gab
