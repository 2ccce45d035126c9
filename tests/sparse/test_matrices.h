// Generators of test matrices and brute-force references shared by the
// sparse suites.
#pragma once

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "gab/sparse/csc.h"
#include "gab/sparse/dense_kernels.h"

namespace gab {
namespace testing_util {

// The SIMD levels this machine runs (every test compares them all).
inline std::vector<SimdLevel> supported_levels() {
  std::vector<SimdLevel> levels;
  for (SimdLevel l : {SimdLevel::kScalar, SimdLevel::kAvx2, SimdLevel::kAvx512}) {
    if (dense_kernels(l).level == l) levels.push_back(l);
  }
  return levels;
}

// Random symmetric pattern with about `density` off-diagonal entries per
// column, values making it strictly diagonally dominant (hence SPD). Extra
// shapes: `dense_rows` rows coupled to every column, and `blocks` disjoint
// diagonal blocks (disconnected graph).
inline CscMatrix random_spd(int32_t n, double density, uint32_t seed, int32_t dense_rows = 0,
                            int32_t blocks = 1) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> val(-1.0, 1.0);
  std::vector<Triplet> t;
  std::vector<double> rowsum(n, 0.0);
  const int32_t block = n / (blocks > 0 ? blocks : 1) + 1;
  auto add = [&](int32_t i, int32_t j) {
    if (i == j) return;
    if (i < j) std::swap(i, j);
    const double v = val(rng);
    t.push_back({i, j, v});
    rowsum[i] += std::abs(v);
    rowsum[j] += std::abs(v);
  };
  if (n > 1) {
    std::uniform_int_distribution<int32_t> pick(0, n - 1);
    const int64_t count = static_cast<int64_t>(density * n);
    for (int64_t e = 0; e < count; ++e) {
      const int32_t i = pick(rng);
      const int32_t lo = (i / block) * block, hi = std::min(n, lo + block) - 1;
      std::uniform_int_distribution<int32_t> near(lo, hi);
      add(i, near(rng));
    }
    for (int32_t d = 0; d < dense_rows && d < n; ++d) {
      const int32_t r = pick(rng);
      for (int32_t j = 0; j < n; ++j) add(r, j);
    }
  }
  for (int32_t i = 0; i < n; ++i) t.push_back({i, i, rowsum[i] + 1.0 + std::abs(val(rng))});
  CscMatrix a;
  EXPECT_TRUE(csc_from_triplets(n, n, t, &a).ok());
  return a;
}

// 5-point Laplacian of an nx x ny grid plus a small shift (SPD), lower triangle.
inline CscMatrix grid_laplacian(int32_t nx, int32_t ny, double shift = 0.01) {
  std::vector<Triplet> t;
  auto id = [nx](int32_t x, int32_t y) { return y * nx + x; };
  for (int32_t y = 0; y < ny; ++y) {
    for (int32_t x = 0; x < nx; ++x) {
      int32_t deg = 0;
      if (x + 1 < nx) { t.push_back({id(x + 1, y), id(x, y), -1.0}); ++deg; }
      if (y + 1 < ny) { t.push_back({id(x, y + 1), id(x, y), -1.0}); ++deg; }
      deg += (x > 0) + (y > 0);
      t.push_back({id(x, y), id(x, y), deg + shift});
    }
  }
  CscMatrix a;
  EXPECT_TRUE(csc_from_triplets(nx * ny, nx * ny, t, &a).ok());
  return a;
}

// Dense symmetric matrix (n x n, column-major, both triangles) from a lower CSC.
inline std::vector<double> to_dense_symmetric(const CscMatrix& lower) {
  const int32_t n = lower.ncols;
  std::vector<double> d(static_cast<size_t>(n) * n, 0.0);
  for (int32_t j = 0; j < n; ++j) {
    for (int32_t p = lower.colptr[j]; p < lower.colptr[j + 1]; ++p) {
      const int32_t i = lower.rowind[p];
      d[i + static_cast<size_t>(j) * n] += lower.values[p];
      if (i != j) d[j + static_cast<size_t>(i) * n] += lower.values[p];
    }
  }
  return d;
}

// Structure of L by boolean elimination, O(n^3): struct[i * n + j] for i >= j.
inline std::vector<char> brute_force_structure(const CscMatrix& lower) {
  const int32_t n = lower.ncols;
  std::vector<char> s(static_cast<size_t>(n) * n, 0);
  for (int32_t j = 0; j < n; ++j) {
    s[static_cast<size_t>(j) * n + j] = 1;
    for (int32_t p = lower.colptr[j]; p < lower.colptr[j + 1]; ++p) {
      s[static_cast<size_t>(lower.rowind[p]) * n + j] = 1;
    }
  }
  for (int32_t j = 0; j < n; ++j) {
    for (int32_t i = j + 1; i < n; ++i) {
      if (!s[static_cast<size_t>(i) * n + j]) continue;
      for (int32_t r = i; r < n; ++r) {
        if (s[static_cast<size_t>(r) * n + j]) s[static_cast<size_t>(r) * n + i] = 1;
      }
    }
  }
  return s;
}

}  // namespace testing_util
}  // namespace gab
