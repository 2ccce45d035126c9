// The eigensolver's parts on their own: the tridiagonal QL, the band
// reduction, band inverse iteration and the basis kernels at every SIMD
// level this machine has (against the scalar ones).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "eigensolver/band_inverse_iteration.h"
#include "eigensolver/band_tridiagonal.h"
#include "eigensolver/basis_kernels.h"
#include "eigensolver/tridiagonal_ql.h"
#include "gab/sparse/splitmix64.h"
#include "sparse/test_matrices.h"

namespace gab {
namespace eigen_detail {
namespace {

const double kPi = 3.14159265358979323846;

TEST(TridiagonalQl, PathLaplacianEigenvalues) {
  const int32_t m = 300;
  std::vector<double> d(m, 2.0), e(m, -1.0);
  d[0] = d[m - 1] = 1.0;
  ASSERT_TRUE(tridiagonal_eigenvalues(m, d.data(), e.data()));
  for (int32_t j = 0; j < m; ++j) EXPECT_NEAR(d[j], 2.0 - 2.0 * std::cos(kPi * j / m), 1e-13) << j;
}

TEST(TridiagonalQl, SplitsWhereACouplingIsZero) {
  // Two blocks [1 1; 1 1] (eigenvalues 0, 2) and [3] decoupled.
  std::vector<double> d = {1.0, 1.0, 3.0}, e = {1.0, 0.0, 0.0};
  ASSERT_TRUE(tridiagonal_eigenvalues(3, d.data(), e.data()));
  EXPECT_NEAR(d[0], 0.0, 1e-15);
  EXPECT_NEAR(d[1], 2.0, 1e-15);
  EXPECT_NEAR(d[2], 3.0, 1e-15);
}

// A random symmetric band matrix and its dense copy.
SymmetricBand random_band(int32_t m, int32_t b, uint64_t seed) {
  SymmetricBand band;
  band.m = m;
  band.b = b;
  band.data.assign(static_cast<size_t>(b + 1) * m, 0.0);
  SplitMix64 rng(seed);
  for (int32_t j = 0; j < m; ++j)
    for (int32_t t = 0; t <= b && j + t < m; ++t) band.at(j + t, j) = rng.uniform() - 0.5;
  return band;
}

// Eigenvalues through the band reduction and QL, ascending.
std::vector<double> band_eigenvalues(const SymmetricBand& band) {
  std::vector<double> d(band.m), e(band.m), work;
  band_to_tridiagonal(band, &work, d.data(), e.data());
  EXPECT_TRUE(tridiagonal_eigenvalues(band.m, d.data(), e.data()));
  return d;
}

TEST(BandTridiagonal, KeepsTraceAndFrobeniusNorm) {
  // An orthogonal similarity keeps sum(lambda) = trace and
  // sum(lambda^2) = ||T||_F^2.
  for (int32_t b : {1, 2, 5, 9}) {
    const SymmetricBand band = random_band(120, b, 3 + b);
    double trace = 0.0, frob = 0.0;
    for (int32_t j = 0; j < band.m; ++j) {
      trace += band.at(j, j);
      for (int32_t t = 0; t <= b && j + t < band.m; ++t) frob += (t ? 2.0 : 1.0) * band.at(j + t, j) * band.at(j + t, j);
    }
    const std::vector<double> lambda = band_eigenvalues(band);
    double sum = 0.0, sum2 = 0.0;
    for (double l : lambda) sum += l, sum2 += l * l;
    EXPECT_NEAR(sum, trace, 1e-11) << b;
    EXPECT_NEAR(sum2, frob, 1e-11) << b;
  }
}

TEST(BandInverseIteration, VectorsAreOrthonormalEigenvectors) {
  const int32_t m = 150, b = 6;
  SymmetricBand band = random_band(m, b, 5);
  // A double eigenvalue: a block that is a copy of another, decoupled.
  SymmetricBand twin;
  twin.m = 2 * m;
  twin.b = b;
  twin.data.assign(static_cast<size_t>(b + 1) * twin.m, 0.0);
  for (int32_t j = 0; j < m; ++j)
    for (int32_t t = 0; t <= b && j + t < m; ++t) twin.at(j + t, j) = twin.at(m + j + t, m + j) = band.at(j + t, j);
  std::vector<double> lambda = band_eigenvalues(twin);
  std::reverse(lambda.begin(), lambda.end());  // descending, the largest first
  const int32_t count = 20;
  std::vector<double> x(static_cast<size_t>(twin.m) * count);
  band_eigenvectors(twin, lambda.data(), count, 1e-8, 1, x.data());
  for (int32_t c = 0; c < count; ++c) {
    const double* xc = x.data() + static_cast<size_t>(c) * twin.m;
    double r = 0.0;
    for (int32_t i = 0; i < twin.m; ++i) {
      double ti = 0.0;
      for (int32_t k = std::max(0, i - b); k <= std::min(twin.m - 1, i + b); ++k) {
        ti += (i >= k ? twin.at(i, k) : twin.at(k, i)) * xc[k];
      }
      r = std::max(r, std::abs(ti - lambda[c] * xc[i]));
    }
    EXPECT_LT(r, 1e-12) << c;
    for (int32_t o = 0; o <= c; ++o) {
      double dot = 0.0;
      for (int32_t i = 0; i < twin.m; ++i) dot += xc[i] * x[static_cast<size_t>(o) * twin.m + i];
      EXPECT_NEAR(dot, o == c ? 1.0 : 0.0, 1e-10) << c << " " << o;
    }
  }
}

TEST(BasisKernels, EveryLevelMatchesScalar) {
  const int32_t n = 203, cols = 37;
  SplitMix64 rng(9);
  std::vector<double> v(static_cast<size_t>(n) * cols), x(static_cast<size_t>(n) * 11);
  for (double& t : v) t = rng.uniform() - 0.5;
  for (double& t : x) t = rng.uniform() - 0.5;
  for (int32_t w : {1, 3, 8, 11}) {
    // The reference: plain loops.
    std::vector<double> p_ref(static_cast<size_t>(cols) * w), x_ref(x.begin(), x.begin() + static_cast<size_t>(n) * w);
    for (int32_t c = 0; c < w; ++c)
      for (int32_t i = 0; i < cols; ++i) {
        double s = 0.0;
        for (int32_t t = 0; t < n; ++t) s += v[static_cast<size_t>(i) * n + t] * x[static_cast<size_t>(c) * n + t];
        p_ref[i + static_cast<size_t>(c) * cols] = s;
      }
    for (int32_t c = 0; c < w; ++c)
      for (int32_t t = 0; t < n; ++t)
        for (int32_t i = 0; i < cols; ++i)
          x_ref[static_cast<size_t>(c) * n + t] -= v[static_cast<size_t>(i) * n + t] * p_ref[i + static_cast<size_t>(c) * cols];
    for (SimdLevel level : testing_util::supported_levels()) {
      const BasisKernels& k = basis_kernels(level);
      ASSERT_EQ(k.level, level);
      std::vector<double> p(static_cast<size_t>(cols) * w), xs(x.begin(), x.begin() + static_cast<size_t>(n) * w);
      k.project(n, cols, w, v.data(), xs.data(), p.data(), cols);
      for (size_t i = 0; i < p.size(); ++i) EXPECT_NEAR(p[i], p_ref[i], 1e-13) << simd_level_name(level) << " w " << w;
      k.subtract(n, cols, w, v.data(), p_ref.data(), cols, xs.data());
      for (size_t i = 0; i < xs.size(); ++i) EXPECT_NEAR(xs[i], x_ref[i], 1e-13) << simd_level_name(level) << " w " << w;
    }
  }
}

}  // namespace
}  // namespace eigen_detail
}  // namespace gab
