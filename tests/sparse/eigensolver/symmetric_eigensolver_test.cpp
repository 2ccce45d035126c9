// The eigensolver against closed forms (path, cycle and grid Laplacians), a
// dense Jacobi eigensolver written here as the oracle, and its own
// contract: orthonormal vectors, residuals, restarts, bad arguments.
#include "gab/sparse/symmetric_eigensolver.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "sparse/test_matrices.h"

namespace gab {
namespace {

const double kPi = 3.14159265358979323846;

// Uniform Laplacian D - A (lower triangle) of a graph given by its edges.
CscMatrix laplacian(int32_t n, const std::vector<std::pair<int32_t, int32_t>>& edges) {
  std::vector<Triplet> t;
  std::vector<double> degree(n, 0.0);
  for (auto [i, j] : edges) {
    t.push_back({std::max(i, j), std::min(i, j), -1.0});
    degree[i] += 1.0;
    degree[j] += 1.0;
  }
  for (int32_t i = 0; i < n; ++i) t.push_back({i, i, degree[i]});
  CscMatrix a;
  EXPECT_TRUE(csc_from_triplets(n, n, t, &a).ok());
  return a;
}

std::vector<std::pair<int32_t, int32_t>> path_edges(int32_t n, int32_t offset = 0) {
  std::vector<std::pair<int32_t, int32_t>> e;
  for (int32_t i = 0; i + 1 < n; ++i) e.push_back({offset + i, offset + i + 1});
  return e;
}

std::vector<std::pair<int32_t, int32_t>> grid_edges(int32_t nx, int32_t ny) {
  std::vector<std::pair<int32_t, int32_t>> e;
  for (int32_t y = 0; y < ny; ++y) {
    for (int32_t x = 0; x < nx; ++x) {
      if (x + 1 < nx) e.push_back({y * nx + x, y * nx + x + 1});
      if (y + 1 < ny) e.push_back({y * nx + x, (y + 1) * nx + x});
    }
  }
  return e;
}

// max |V^T V - I| over the returned vectors.
double orthonormality_error(const SymmetricEigenResult& r, int32_t n) {
  const int32_t k = static_cast<int32_t>(r.values.size());
  double worst = 0.0;
  for (int32_t a = 0; a < k; ++a) {
    for (int32_t b = 0; b <= a; ++b) {
      double dot = 0.0;
      for (int32_t i = 0; i < n; ++i) dot += r.vectors[static_cast<size_t>(a) * n + i] * r.vectors[static_cast<size_t>(b) * n + i];
      worst = std::max(worst, std::abs(dot - (a == b ? 1.0 : 0.0)));
    }
  }
  return worst;
}

// ||A v - lambda v||_2 / ||A||_1 recomputed here, worst over the pairs.
double worst_residual(const CscMatrix& given, const SymmetricEigenResult& r, int32_t n) {
  const CscMatrix a = lower_triangle(given);
  std::vector<double> av(n);
  double worst = 0.0;
  for (size_t c = 0; c < r.values.size(); ++c) {
    const double* v = r.vectors.data() + c * n;
    symmetric_lower_matvec(a, v, av.data());
    double s = 0.0;
    for (int32_t i = 0; i < n; ++i) s += (av[i] - r.values[c] * v[i]) * (av[i] - r.values[c] * v[i]);
    worst = std::max(worst, std::sqrt(s) / r.norm);
  }
  return worst;
}

// Eigenvalues of a dense symmetric matrix by cyclic Jacobi rotations
// (Golub & Van Loan, sec. 8.5): slow, obviously right. Ascending.
std::vector<double> jacobi_eigenvalues(std::vector<double> a, int32_t n) {
  auto at = [&](int32_t i, int32_t j) -> double& { return a[static_cast<size_t>(j) * n + i]; };
  for (int sweep = 0; sweep < 100; ++sweep) {
    double off = 0.0;
    for (int32_t j = 0; j < n; ++j)
      for (int32_t i = 0; i < n; ++i)
        if (i != j) off += at(i, j) * at(i, j);
    if (off < 1e-30) break;
    for (int32_t p = 0; p < n; ++p) {
      for (int32_t q = p + 1; q < n; ++q) {
        if (at(p, q) == 0.0) continue;
        const double tau = (at(q, q) - at(p, p)) / (2.0 * at(p, q));
        const double t = (tau >= 0 ? 1.0 : -1.0) / (std::abs(tau) + std::sqrt(1.0 + tau * tau));
        const double c = 1.0 / std::sqrt(1.0 + t * t), s = t * c;
        for (int32_t k = 0; k < n; ++k) {  // A := A J (columns p, q)
          const double akp = at(k, p), akq = at(k, q);
          at(k, p) = c * akp - s * akq;
          at(k, q) = s * akp + c * akq;
        }
        for (int32_t k = 0; k < n; ++k) {  // A := J^T A (rows p, q)
          const double apk = at(p, k), aqk = at(q, k);
          at(p, k) = c * apk - s * aqk;
          at(q, k) = s * apk + c * aqk;
        }
      }
    }
  }
  std::vector<double> d(n);
  for (int32_t i = 0; i < n; ++i) d[i] = at(i, i);
  std::sort(d.begin(), d.end());
  return d;
}

std::vector<double> dense_of(const CscMatrix& lower) {
  const int32_t n = lower.nrows;
  std::vector<double> a(static_cast<size_t>(n) * n, 0.0);
  for (int32_t j = 0; j < n; ++j) {
    for (int32_t p = lower.colptr[j]; p < lower.colptr[j + 1]; ++p) {
      a[static_cast<size_t>(j) * n + lower.rowind[p]] = lower.values[p];
      a[static_cast<size_t>(lower.rowind[p]) * n + j] = lower.values[p];
    }
  }
  return a;
}

// Solves and checks the contract: the values against `expected`, residuals,
// orthonormal vectors.
SymmetricEigenResult solve_and_check(const CscMatrix& a, const SymmetricEigenOptions& o,
                                     const std::vector<double>& expected) {
  SymmetricEigenResult r;
  const Status s = smallest_eigenpairs(a, o, &r);
  EXPECT_TRUE(s.ok()) << s.message();
  if (!s.ok()) return r;
  const int32_t n = a.nrows;
  EXPECT_EQ(static_cast<int32_t>(r.values.size()), o.count);
  for (int32_t j = 0; j < o.count; ++j) EXPECT_NEAR(r.values[j], expected[j], 1e-9 * r.norm) << "eigenvalue " << j;
  for (double res : r.residuals) EXPECT_LE(res, o.tolerance);
  EXPECT_LE(worst_residual(a, r, n), o.tolerance);
  EXPECT_LE(orthonormality_error(r, n), 1e-9);
  return r;
}

TEST(SymmetricEigensolver, PathLaplacianMatchesClosedForm) {
  const int32_t n = 400;
  std::vector<double> expected;
  for (int32_t j = 0; j < n; ++j) expected.push_back(2.0 - 2.0 * std::cos(kPi * j / n));
  SymmetricEigenOptions o;
  o.count = 25;
  solve_and_check(laplacian(n, path_edges(n)), o, expected);
}

TEST(SymmetricEigensolver, CycleLaplacianDoubleEigenvalues) {
  const int32_t n = 150;
  auto edges = path_edges(n);
  edges.push_back({n - 1, 0});
  std::vector<double> expected;
  for (int32_t j = 0; j < n; ++j) expected.push_back(2.0 - 2.0 * std::cos(2.0 * kPi * j / n));
  std::sort(expected.begin(), expected.end());
  SymmetricEigenOptions o;
  o.count = 21;  // 0 and ten double eigenvalues
  solve_and_check(laplacian(n, edges), o, expected);
}

TEST(SymmetricEigensolver, GridLaplacianIsSumsOfPathEigenvalues) {
  const int32_t nx = 24, ny = 17;
  std::vector<double> expected;
  for (int32_t a = 0; a < nx; ++a)
    for (int32_t b = 0; b < ny; ++b)
      expected.push_back(4.0 - 2.0 * std::cos(kPi * a / nx) - 2.0 * std::cos(kPi * b / ny));
  std::sort(expected.begin(), expected.end());
  SymmetricEigenOptions o;
  o.count = 40;
  o.block_size = 4;
  solve_and_check(laplacian(nx * ny, grid_edges(nx, ny)), o, expected);
}

TEST(SymmetricEigensolver, DisconnectedGraphHasOneZeroPerComponent) {
  // Paths of 50, 80 and 30 vertices: zero three times, then the smallest of
  // 2 - 2 cos(pi j / len) over the three.
  auto edges = path_edges(50);
  for (auto e : path_edges(80, 50)) edges.push_back(e);
  for (auto e : path_edges(30, 130)) edges.push_back(e);
  std::vector<double> expected;
  for (int32_t len : {50, 80, 30})
    for (int32_t j = 0; j < len; ++j) expected.push_back(2.0 - 2.0 * std::cos(kPi * j / len));
  std::sort(expected.begin(), expected.end());
  SymmetricEigenOptions o;
  o.count = 12;
  const SymmetricEigenResult r = solve_and_check(laplacian(160, edges), o, expected);
  ASSERT_EQ(r.values.size(), 12u);
  EXPECT_LT(std::abs(r.values[2]), 1e-10);
  EXPECT_GT(r.values[3], 1e-3);
}

TEST(SymmetricEigensolver, MoreComponentsThanTheBlockSize) {
  // 20 triangles (eigenvalues 0, 3, 3 each) and 12 isolated vertices: 32
  // zeros, more than a block of 8 can hold, then threes.
  std::vector<std::pair<int32_t, int32_t>> edges;
  for (int32_t t = 0; t < 20; ++t) {
    edges.push_back({3 * t, 3 * t + 1});
    edges.push_back({3 * t + 1, 3 * t + 2});
    edges.push_back({3 * t, 3 * t + 2});
  }
  std::vector<double> expected(32, 0.0);
  expected.resize(72, 3.0);
  SymmetricEigenOptions o;
  o.count = 36;
  const SymmetricEigenResult r = solve_and_check(laplacian(72, edges), o, expected);
  EXPECT_GT(r.probes, 0);
}

TEST(SymmetricEigensolver, RandomSpdMatchesJacobiOracle) {
  const CscMatrix a = testing_util::random_spd(90, 3.0, 7);
  const std::vector<double> expected = jacobi_eigenvalues(dense_of(a), 90);
  SymmetricEigenOptions o;
  o.count = 30;
  o.block_size = 3;
  solve_and_check(a, o, expected);
}

TEST(SymmetricEigensolver, CountEqualToSizeGivesTheWholeSpectrum) {
  const CscMatrix a = testing_util::random_spd(37, 2.0, 11);
  const std::vector<double> expected = jacobi_eigenvalues(dense_of(a), 37);
  SymmetricEigenOptions o;
  o.count = 37;
  solve_and_check(a, o, expected);
}

TEST(SymmetricEigensolver, SmallBasisRestartsAndStillConverges) {
  const int32_t n = 300;
  std::vector<double> expected;
  for (int32_t j = 0; j < n; ++j) expected.push_back(2.0 - 2.0 * std::cos(kPi * j / n));
  SymmetricEigenOptions o;
  o.count = 30;
  o.block_size = 4;
  o.max_basis = 60;
  o.max_restarts = 100;
  const SymmetricEigenResult r = solve_and_check(laplacian(n, path_edges(n)), o, expected);
  EXPECT_GT(r.restarts, 0);
  EXPECT_EQ(r.basis_columns, 60);
}

TEST(SymmetricEigensolver, BlockSizesAgree) {
  const int32_t nx = 15, ny = 15;
  const CscMatrix a = laplacian(nx * ny, grid_edges(nx, ny));
  std::vector<double> expected;
  for (int32_t p = 0; p < nx; ++p)
    for (int32_t q = 0; q < ny; ++q)
      expected.push_back(4.0 - 2.0 * std::cos(kPi * p / nx) - 2.0 * std::cos(kPi * q / ny));
  std::sort(expected.begin(), expected.end());
  for (int32_t b : {1, 2, 8, 16}) {
    SymmetricEigenOptions o;
    o.count = 20;
    o.block_size = b;
    SCOPED_TRACE(b);
    solve_and_check(a, o, expected);
  }
}

TEST(SymmetricEigensolver, BadArgumentsSayWhatIsWrong) {
  const CscMatrix a = laplacian(10, path_edges(10));
  SymmetricEigenResult r;
  SymmetricEigenOptions o;
  CscMatrix rect;
  ASSERT_TRUE(csc_from_triplets(4, 3, {{0, 0, 1.0}}, &rect).ok());
  Status s = smallest_eigenpairs(rect, o, &r);
  EXPECT_EQ(s.code(), StatusCode::kInvalidArgument);
  EXPECT_EQ(s.message(), "smallest_eigenpairs: the matrix is 4 x 3, not square");
  o.count = 11;
  s = smallest_eigenpairs(a, o, &r);
  EXPECT_EQ(s.message(), "smallest_eigenpairs: count 11 is outside 1..10");
  o.count = 0;
  EXPECT_EQ(smallest_eigenpairs(a, o, &r).message(), "smallest_eigenpairs: count 0 is outside 1..10");
  o.count = 3;
  o.shift = 0.5;
  EXPECT_EQ(smallest_eigenpairs(a, o, &r).message(), "smallest_eigenpairs: shift must be negative (or 0: chosen)");
  o.shift = 0.0;
  o.block_size = 65;
  EXPECT_EQ(smallest_eigenpairs(a, o, &r).message(), "smallest_eigenpairs: block_size 65 is outside 1..64");
  o.block_size = 8;
  o.tolerance = -1.0;
  EXPECT_EQ(smallest_eigenpairs(a, o, &r).message(), "smallest_eigenpairs: tolerance must be positive and finite");
  o.tolerance = 1e-10;
  o.max_basis = 4;
  o.block_size = 2;
  s = smallest_eigenpairs(a, o, &r);
  EXPECT_EQ(s.code(), StatusCode::kInvalidArgument);
  EXPECT_EQ(s.message(), "smallest_eigenpairs: max_basis 4 is below count + block_size (5)");
}

TEST(SymmetricEigensolver, EntriesAboveTheDiagonalAreIgnored) {
  // The whole symmetric matrix gives what its lower triangle gives.
  const int32_t n = 120;
  const CscMatrix lower = laplacian(n, path_edges(n));
  std::vector<Triplet> t;
  for (int32_t j = 0; j < n; ++j) {
    for (int32_t p = lower.colptr[j]; p < lower.colptr[j + 1]; ++p) {
      t.push_back({lower.rowind[p], j, lower.values[p]});
      if (lower.rowind[p] != j) t.push_back({j, lower.rowind[p], lower.values[p]});
    }
  }
  CscMatrix full;
  ASSERT_TRUE(csc_from_triplets(n, n, t, &full).ok());
  std::vector<double> expected;
  for (int32_t j = 0; j < n; ++j) expected.push_back(2.0 - 2.0 * std::cos(kPi * j / n));
  SymmetricEigenOptions o;
  o.count = 10;
  const SymmetricEigenResult r = solve_and_check(full, o, expected);
  EXPECT_DOUBLE_EQ(r.norm, 4.0);
}

TEST(SymmetricEigensolver, NonFiniteValueIsNamed) {
  CscMatrix a = laplacian(10, path_edges(10));
  a.values[a.colptr[3] + 1] = std::nan("");
  SymmetricEigenResult r;
  const Status s = smallest_eigenpairs(a, SymmetricEigenOptions(), &r);
  EXPECT_EQ(s.code(), StatusCode::kInvalidArgument);
  EXPECT_EQ(s.message(), "smallest_eigenpairs: entry (4, 3) is not finite");
}

TEST(SymmetricEigensolver, IndefiniteMatrixIsRefused) {
  CscMatrix a = laplacian(20, path_edges(20));
  for (int32_t j = 0; j < 20; ++j) a.values[a.colptr[j]] -= 1.5;  // eigenvalues down to -1.5
  SymmetricEigenResult r;
  const Status s = smallest_eigenpairs(a, SymmetricEigenOptions(), &r);
  EXPECT_EQ(s.code(), StatusCode::kNotPositiveDefinite);
  EXPECT_NE(s.message().find("A is not positive semi-definite"), std::string::npos) << s.message();
}

TEST(SymmetricEigensolver, IterationLimitSaysHowManyConverged) {
  const int32_t n = 400;
  SymmetricEigenOptions o;
  o.count = 30;
  o.block_size = 2;
  o.max_basis = 34;
  o.max_restarts = 0;
  SymmetricEigenResult r;
  const Status s = smallest_eigenpairs(laplacian(n, path_edges(n)), o, &r);
  EXPECT_EQ(s.code(), StatusCode::kResourceExhausted);
  EXPECT_NE(s.message().find(" of 30 eigenpairs converged within 0 restarts (basis of 34 columns)"), std::string::npos)
      << s.message();
}

}  // namespace
}  // namespace gab
