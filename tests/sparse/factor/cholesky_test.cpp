// The supernodal factorization and solves against the oracles, on many
// random SPD matrices and every SIMD level this machine has.
#include "gab/sparse/cholesky.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "common/oracles.h"
#include "sparse/test_matrices.h"

namespace gab {
namespace {

using testing_util::random_spd;

using testing_util::supported_levels;

// Max |L_supernodal - L_oracle| over the whole factor, relative to max |L|.
double factor_difference(const Cholesky& chol, const CscMatrix& lower) {
  const SymbolicFactor& f = chol.symbolic();
  const CscMatrix c = permute_symmetric_lower(lower, f.perm);
  CscMatrix oracle;
  EXPECT_TRUE(simplicial_cholesky(c, &oracle).ok());
  const int32_t n = f.n;
  std::vector<double> col(n, 0.0);
  double diff = 0.0, scale = 0.0;
  for (int32_t j = 0; j < n; ++j) {
    for (int32_t p = oracle.colptr[j]; p < oracle.colptr[j + 1]; ++p) col[oracle.rowind[p]] = oracle.values[p];
    const int32_t s = f.supernode_of[j], m = f.rows(s);
    const double* block = chol.values() + f.value_ptr[s] + static_cast<int64_t>(j - f.first_col[s]) * m;
    for (int32_t t = j - f.first_col[s]; t < m; ++t) {
      const int32_t i = f.row_ind[f.row_ptr[s] + t];
      diff = std::max(diff, std::abs(block[t] - col[i]));
      scale = std::max(scale, std::abs(col[i]));
      col[i] = 0.0;
    }
    for (int32_t p = oracle.colptr[j]; p < oracle.colptr[j + 1]; ++p) {
      EXPECT_EQ(col[oracle.rowind[p]], 0.0) << "oracle entry outside the supernodal structure";
      col[oracle.rowind[p]] = 0.0;
    }
  }
  return scale > 0 ? diff / scale : diff;
}

double relative_residual(const CscMatrix& a, const std::vector<double>& x, const std::vector<double>& b,
                         int32_t nrhs) {
  const int32_t n = a.ncols;
  std::vector<double> ax(n);
  double num = 0.0, den = 0.0;
  for (int32_t r = 0; r < nrhs; ++r) {
    symmetric_lower_matvec(a, x.data() + static_cast<size_t>(r) * n, ax.data());
    for (int32_t i = 0; i < n; ++i) {
      const double d = ax[i] - b[i + static_cast<size_t>(r) * n];
      num += d * d;
      den += b[i + static_cast<size_t>(r) * n] * b[i + static_cast<size_t>(r) * n];
    }
  }
  return std::sqrt(num / den);
}

struct Case {
  int32_t n;
  double density;
  int32_t dense_rows;
  int32_t blocks;
};

TEST(CholeskyTest, FactorMatchesSimplicialOracleOnRandomMatrices) {
  std::vector<Case> cases;
  for (int32_t n : {1, 2, 3, 5, 8, 17, 40, 100, 300}) {
    for (double d : {0.5, 2.0, 6.0}) cases.push_back({n, d, 0, 1});
  }
  cases.push_back({200, 3.0, 2, 1});
  cases.push_back({250, 2.0, 0, 5});
  cases.push_back({400, 4.0, 3, 3});
  cases.push_back({2000, 2.5, 1, 2});
  cases.push_back({150, 40.0, 0, 1});  // nearly dense: big supernodes
  for (SimdLevel level : supported_levels()) {
    uint32_t seed = 100;
    for (const Case& c : cases) {
      for (Ordering ord : {Ordering::kAmd, Ordering::kNatural}) {
        const CscMatrix a = random_spd(c.n, c.density, ++seed, c.dense_rows, c.blocks);
        Cholesky chol;
        chol.set_kernels(dense_kernels(level));
        AnalyzeOptions options;
        options.ordering = ord;
        ASSERT_TRUE(chol.analyze(a, options).ok());
        ASSERT_TRUE(chol.factorize(a).ok());
        EXPECT_LT(factor_difference(chol, a), 1e-12)
            << simd_level_name(level) << " n=" << c.n << " density=" << c.density;
      }
    }
  }
}

// Wide supernodes cut into chains of panels (AnalyzeOptions::panel_cols):
// the chain's structure is its supernode's, the factor the oracle's, the
// same bits on every thread count, in fewer stored entries.
TEST(CholeskyTest, PanelChainsMatchTheOracleInLessStorage) {
  std::vector<CscMatrix> matrices = {testing_util::grid_laplacian(40, 30), random_spd(300, 6.0, 11, 2, 1),
                                     random_spd(150, 40.0, 12), random_spd(400, 4.0, 13, 3, 3)};
  for (size_t which = 0; which < matrices.size(); ++which) {
    const CscMatrix& a = matrices[which];
    AnalyzeOptions uncut;
    uncut.panel_cols = 0;
    Cholesky whole;
    ASSERT_TRUE(whole.analyze(a, uncut).ok());
    for (int32_t panel_cols : {3, 16}) {
      std::vector<double> reference;
      for (int32_t threads = 1; threads <= 3; ++threads) {
        AnalyzeOptions options;
        options.panel_cols = panel_cols;
        options.max_panels = 6;
        options.threads = threads;
        Cholesky chol;
        ASSERT_TRUE(chol.analyze(a, options).ok());
        ASSERT_TRUE(chol.factorize(a).ok());
        const SymbolicFactor& f = chol.symbolic();
        EXPECT_EQ(f.perm, whole.symbolic().perm);
        EXPECT_EQ(f.nnz_L, whole.symbolic().nnz_L);
        ASSERT_FALSE(f.continued.empty()) << which;
        EXPECT_LT(f.value_ptr.back(), whole.symbolic().value_ptr.back()) << which;
        for (int32_t s = 0, e = 0; s < f.num_supernodes; s = e + 1) {
          // Chain s..e: at most max_panels of near-equal widths, no wider
          // than panel_cols unless the cap on panels made them so.
          for (e = s; f.continues(e); ++e) {
          }
          int32_t widest = 0, narrowest = INT32_MAX;
          for (int32_t t = s; t <= e; ++t) {
            widest = std::max(widest, f.cols(t));
            narrowest = std::min(narrowest, f.cols(t));
          }
          EXPECT_LE(e - s + 1, options.max_panels);
          EXPECT_LE(widest - narrowest, 1);
          if (e - s + 1 < options.max_panels) {
            EXPECT_LE(widest, panel_cols);
          }
        }
        for (int32_t s = 0; s < f.num_supernodes; ++s) {
          if (!f.continues(s)) continue;
          ASSERT_EQ(f.supernode_parent[s], s + 1);
          // The next panel's rows are this one's from the next panel's column on.
          EXPECT_TRUE(std::equal(f.row_ind.begin() + f.row_ptr[s] + f.cols(s), f.row_ind.begin() + f.row_ptr[s + 1],
                                 f.row_ind.begin() + f.row_ptr[s + 1], f.row_ind.begin() + f.row_ptr[s + 2]));
        }
        EXPECT_LT(factor_difference(chol, a), 1e-12) << which << " panel_cols " << panel_cols;
        std::vector<double> values(chol.values(), chol.values() + f.value_ptr.back());
        for (int32_t s = 0; s < f.num_supernodes; ++s) {  // the unspecified upper triangles
          for (int32_t c = 1; c < f.cols(s); ++c) {
            std::fill_n(values.begin() + f.value_ptr[s] + static_cast<int64_t>(c) * f.rows(s), c, 0.0);
          }
        }
        if (threads == 1) {
          reference = values;
        } else {
          EXPECT_TRUE(values == reference) << which << " threads " << threads;
        }
        const int32_t n = a.ncols;
        std::vector<double> b(2 * static_cast<size_t>(n));
        for (size_t i = 0; i < b.size(); ++i) b[i] = std::sin(0.7 * i) + 2.0;
        std::vector<double> x = b;
        ASSERT_TRUE(chol.solve(x.data(), 2, n).ok());
        EXPECT_LT(relative_residual(a, x, b, 2), 1e-12);
      }
    }
  }
}

TEST(CholeskyTest, SolveSeveralRightHandSidesToResidual1e12) {
  for (SimdLevel level : supported_levels()) {
    for (int32_t nrhs : {1, 2, 3, 4, 7}) {
      const CscMatrix a = random_spd(500, 3.0, 77 + nrhs, 1, 2);
      const int32_t n = a.ncols;
      std::vector<double> b(static_cast<size_t>(n) * nrhs);
      for (size_t i = 0; i < b.size(); ++i) b[i] = std::cos(0.37 * i);
      std::vector<double> x = b;
      Cholesky chol;
      chol.set_kernels(dense_kernels(level));
      ASSERT_TRUE(chol.analyze(a).ok());
      ASSERT_TRUE(chol.factorize(a).ok());
      ASSERT_TRUE(chol.solve(x.data(), nrhs, n).ok());
      EXPECT_LT(relative_residual(a, x, b, nrhs), 1e-12) << simd_level_name(level) << " nrhs=" << nrhs;
    }
  }
}

// A leading dimension beyond n leaves the rows between the columns as they
// were.
TEST(CholeskyTest, SolveWithALeadingDimensionBeyondN) {
  const CscMatrix a = random_spd(300, 4.0, 31, 1, 2);
  const int32_t n = a.ncols, ld = n + 5, nrhs = 3;
  for (int32_t threads : {1, 2}) {
    AnalyzeOptions options;
    options.threads = threads;
    Cholesky chol;
    ASSERT_TRUE(chol.analyze(a, options).ok());
    ASSERT_TRUE(chol.factorize(a).ok());
    std::vector<double> padded(static_cast<size_t>(ld) * nrhs, -7.0), b(static_cast<size_t>(n) * nrhs);
    for (int32_t r = 0; r < nrhs; ++r) {
      for (int32_t i = 0; i < n; ++i) {
        b[i + static_cast<size_t>(r) * n] = std::cos(0.1 * i + r);
        padded[i + static_cast<size_t>(r) * ld] = b[i + static_cast<size_t>(r) * n];
      }
    }
    ASSERT_TRUE(chol.solve(padded.data(), nrhs, ld).ok());
    std::vector<double> x(static_cast<size_t>(n) * nrhs);
    for (int32_t r = 0; r < nrhs; ++r) {
      for (int32_t i = 0; i < n; ++i) x[i + static_cast<size_t>(r) * n] = padded[i + static_cast<size_t>(r) * ld];
      for (int32_t i = n; i < ld; ++i) EXPECT_EQ(padded[i + static_cast<size_t>(r) * ld], -7.0);
    }
    EXPECT_LT(relative_residual(a, x, b, nrhs), 1e-12) << threads;
  }
}

TEST(CholeskyTest, GridLaplacianResidual) {
  const CscMatrix a = testing_util::grid_laplacian(60, 50);
  const int32_t n = a.ncols;
  std::vector<double> b(n * 3);
  for (size_t i = 0; i < b.size(); ++i) b[i] = 1.0 + (i % 7);
  std::vector<double> x = b;
  Cholesky chol;
  ASSERT_TRUE(chol.analyze(a).ok());
  ASSERT_TRUE(chol.factorize(a).ok());
  ASSERT_TRUE(chol.solve(x.data(), 3, n).ok());
  EXPECT_LT(relative_residual(a, x, b, 3), 1e-12);
  EXPECT_LT(chol.symbolic().nnz_L, 20 * a.nnz());  // AMD keeps grid fill modest
}

TEST(CholeskyTest, RefactorizationWithNewValuesReusesAnalysis) {
  CscMatrix a = random_spd(300, 3.0, 5);
  Cholesky chol;
  ASSERT_TRUE(chol.analyze(a).ok());
  ASSERT_TRUE(chol.factorize(a).ok());
  for (size_t p = 0; p < a.values.size(); ++p) a.values[p] *= 1.0 + 0.5 * std::sin(p);
  // Keep diagonal dominance: bump the diagonal.
  for (int32_t j = 0; j < a.ncols; ++j) a.values[a.colptr[j]] += 10.0;
  ASSERT_TRUE(chol.factorize(a).ok());
  EXPECT_LT(factor_difference(chol, a), 1e-12);
}

TEST(CholeskyTest, NotPositiveDefiniteNamesTheColumn) {
  // diag(1, 1, -1, 1): with natural ordering the bad pivot is column 2.
  CscMatrix a;
  ASSERT_TRUE(csc_from_triplets(4, 4, {{0, 0, 1.0}, {1, 1, 1.0}, {2, 2, -1.0}, {3, 3, 1.0}}, &a).ok());
  Cholesky chol;
  AnalyzeOptions options;
  options.ordering = Ordering::kNatural;
  ASSERT_TRUE(chol.analyze(a, options).ok());
  const Status s = chol.factorize(a);
  EXPECT_EQ(s.code(), StatusCode::kNotPositiveDefinite);
  EXPECT_EQ(s.message(), "matrix is not positive definite: pivot 2 (original row/column 2) is not positive");
  EXPECT_FALSE(chol.factorized());
  std::vector<double> b(4, 1.0);
  EXPECT_EQ(chol.solve(b.data(), 1, 4).message(), "solve before factorize");
}

TEST(CholeskyTest, IndefiniteInsideALargeSupernodeIsReported) {
  // Dense 30x30 block that is SPD except a negative shift at the end.
  std::vector<Triplet> t;
  for (int32_t j = 0; j < 30; ++j) {
    for (int32_t i = j; i < 30; ++i) t.push_back({i, j, i == j ? (j == 29 ? -100.0 : 31.0) : 1.0});
  }
  CscMatrix a;
  ASSERT_TRUE(csc_from_triplets(30, 30, t, &a).ok());
  // Whether the block is one supernode or a chain of panels, the failure
  // is at the shifted column, whichever pivot it is.
  for (int32_t panel_cols : {0, 4}) {
    AnalyzeOptions options;
    options.panel_cols = panel_cols;
    Cholesky chol;
    ASSERT_TRUE(chol.analyze(a, options).ok());
    EXPECT_EQ(chol.symbolic().continued.empty(), panel_cols == 0);
    const Status s = chol.factorize(a);
    EXPECT_EQ(s.code(), StatusCode::kNotPositiveDefinite);
    EXPECT_NE(s.message().find("(original row/column 29) is not positive"), std::string::npos) << s.message();
  }
}

TEST(CholeskyTest, FactorLimitRefusesBeforeAnyStorageIsReserved) {
  const CscMatrix a = testing_util::grid_laplacian(60, 50);
  AnalyzeOptions options;
  options.threads = 2;
  Cholesky probe;
  ASSERT_TRUE(probe.analyze(a, options).ok());
  const int64_t stored = probe.symbolic().stored_L;

  options.max_factor_entries = stored - 1;
  Cholesky chol;
  const Status s = chol.analyze(a, options);
  EXPECT_EQ(s.code(), StatusCode::kResourceExhausted);
  EXPECT_EQ(s.message(), "the factor would exceed " + std::to_string(stored - 1) + " entries");
  EXPECT_EQ(chol.values(), nullptr);
  EXPECT_EQ(chol.factorize(a).message(), "factorize before analyze");

  options.max_factor_entries = stored;  // the bound itself is allowed
  ASSERT_TRUE(chol.analyze(a, options).ok());
  ASSERT_TRUE(chol.factorize(a).ok());
}

TEST(CholeskyTest, FactorizeRejectsAnotherPattern) {
  const CscMatrix a = random_spd(50, 2.0, 1);
  const CscMatrix b = random_spd(50, 3.0, 2);
  Cholesky chol;
  ASSERT_TRUE(chol.analyze(a).ok());
  EXPECT_EQ(chol.factorize(b).code(), StatusCode::kInvalidArgument);
}

TEST(CholeskyTest, FactorizeValuesIsFactorizeWithoutThePattern) {
  const CscMatrix a = random_spd(120, 3.0, 21, 1, 2);
  Cholesky by_matrix, by_values;
  EXPECT_EQ(by_values.factorize_values(a.values.data(), a.nnz()).message(), "factorize before analyze");
  ASSERT_TRUE(by_matrix.analyze(a).ok());
  ASSERT_TRUE(by_values.analyze(a).ok());
  ASSERT_TRUE(by_matrix.factorize(a).ok());
  const Status short_count = by_values.factorize_values(a.values.data(), a.nnz() - 1);
  EXPECT_EQ(short_count.code(), StatusCode::kInvalidArgument);
  EXPECT_EQ(short_count.message(), "factorize_values needs the analyzed matrix's " + std::to_string(a.nnz()) +
                                       " values, got " + std::to_string(a.nnz() - 1));
  EXPECT_FALSE(by_values.factorized());
  const std::vector<double> values = a.values;  // the pattern is not needed
  ASSERT_TRUE(by_values.factorize_values(values.data(), static_cast<int64_t>(values.size())).ok());
  const int64_t size = by_matrix.symbolic().value_ptr.back();
  EXPECT_TRUE(std::equal(by_matrix.values(), by_matrix.values() + size, by_values.values()));
}

// A 0 x 0 matrix is a matrix: an empty factor that solves nothing, and has
// no column an update could name.
TEST(CholeskyTest, EmptyMatrixHasAnEmptyFactor) {
  CscMatrix a;
  ASSERT_TRUE(csc_from_triplets(0, 0, {}, &a).ok());
  Cholesky chol;
  ASSERT_TRUE(chol.analyze(a).ok());
  EXPECT_EQ(chol.symbolic().n, 0);
  EXPECT_EQ(chol.symbolic().num_supernodes, 0);
  EXPECT_EQ(chol.symbolic().nnz_L, 0);
  EXPECT_EQ(chol.symbolic().flops, 0.0);
  EXPECT_FALSE(chol.factorized());
  ASSERT_TRUE(chol.factorize(a).ok());
  EXPECT_TRUE(chol.factorized());
  EXPECT_TRUE(chol.solve(nullptr, 3, 0).ok());
  UpdateStats stats;
  const Status update = chol.add_anchor(0, 1.0, &stats);
  EXPECT_EQ(update.code(), StatusCode::kInvalidArgument) << update.message();
  EXPECT_EQ(stats.path_columns, 0);
}

// The default kernels (the best level GAB_SIMD allows) are exactly the
// table of the level Cholesky reports: the same factor, bit for bit.
TEST(CholeskyTest, DefaultKernelsAreTheLevelItReports) {
  const CscMatrix a = random_spd(300, 3.0, 7, 0, 2);
  Cholesky by_default, by_name;
  ASSERT_TRUE(by_default.analyze(a).ok());
  ASSERT_TRUE(by_default.factorize(a).ok());
  SimdLevel reported = SimdLevel::kScalar;
  for (SimdLevel level : {SimdLevel::kScalar, SimdLevel::kAvx2, SimdLevel::kAvx512}) {
    if (std::string(simd_level_name(level)) == by_default.simd_level()) reported = level;
  }
  EXPECT_STREQ(simd_level_name(reported), by_default.simd_level());
  by_name.set_kernels(dense_kernels(reported));
  ASSERT_TRUE(by_name.analyze(a).ok());
  ASSERT_TRUE(by_name.factorize(a).ok());
  const int64_t stored = by_default.symbolic().value_ptr.back();
  ASSERT_EQ(stored, by_name.symbolic().value_ptr.back());
  EXPECT_EQ(std::memcmp(by_default.values(), by_name.values(), static_cast<size_t>(stored) * sizeof(double)), 0);
  by_name.set_kernels(dense_kernels(SimdLevel::kScalar));
  EXPECT_STREQ(by_name.simd_level(), "scalar");
}

TEST(OracleTest, DenseAndSimplicialAgree) {
  for (uint32_t seed = 0; seed < 20; ++seed) {
    const CscMatrix a = random_spd(1 + seed * 3, 2.0, seed, seed % 2);
    const int32_t n = a.ncols;
    std::vector<double> dense;
    CscMatrix l;
    ASSERT_TRUE(dense_cholesky(a, &dense).ok());
    ASSERT_TRUE(simplicial_cholesky(a, &l).ok());
    std::vector<double> from_sparse(static_cast<size_t>(n) * n, 0.0);
    for (int32_t j = 0; j < n; ++j)
      for (int32_t p = l.colptr[j]; p < l.colptr[j + 1]; ++p) from_sparse[l.rowind[p] + static_cast<size_t>(j) * n] = l.values[p];
    for (size_t i = 0; i < dense.size(); ++i) EXPECT_NEAR(dense[i], from_sparse[i], 1e-12);
    // L L^T reproduces A.
    const std::vector<double> full = testing_util::to_dense_symmetric(a);
    for (int32_t i = 0; i < n; ++i) {
      for (int32_t j = 0; j <= i; ++j) {
        double v = 0.0;
        for (int32_t k = 0; k <= j; ++k) v += dense[i + static_cast<size_t>(k) * n] * dense[j + static_cast<size_t>(k) * n];
        EXPECT_NEAR(v, full[i + static_cast<size_t>(j) * n], 1e-10);
      }
    }
  }
}

}  // namespace
}  // namespace gab
