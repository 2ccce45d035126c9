// The Givens updater against fresh factorizations: after adding (removing)
// w^2 e_j e_j^T the factor must equal the factor of the modified matrix.
#include "gab/sparse/update.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "gab/sparse/cholesky.h"
#include "sparse/test_matrices.h"

namespace gab {
namespace {

using testing_util::random_spd;

using testing_util::supported_levels;

// Adds w to the diagonal entry (j, j) of a lower-triangle CSC (which has it).
void add_to_diagonal(CscMatrix* a, int32_t j, double w) {
  for (int32_t p = a->colptr[j]; p < a->colptr[j + 1]; ++p) {
    if (a->rowind[p] == j) a->values[p] += w;
  }
}

// Max difference between two factors' stored lower trapezoids, relative.
double factor_difference(const Cholesky& a, const Cholesky& b) {
  const SymbolicFactor& f = a.symbolic();
  double diff = 0.0, scale = 0.0;
  for (int32_t s = 0; s < f.num_supernodes; ++s) {
    const int32_t m = f.rows(s);
    for (int32_t c = 0; c < f.cols(s); ++c) {
      for (int32_t t = c; t < m; ++t) {
        const int64_t q = f.value_ptr[s] + static_cast<int64_t>(c) * m + t;
        diff = std::max(diff, std::abs(a.values()[q] - b.values()[q]));
        scale = std::max(scale, std::abs(b.values()[q]));
      }
    }
  }
  return diff / scale;
}

// Difference between chol's factor and a fresh factorization of `a` with
// the same ordering (the factor chol should now hold).
double difference_from_fresh(const Cholesky& chol, const CscMatrix& a) {
  Cholesky fresh;
  AnalyzeOptions same;
  same.ordering = Ordering::kGiven;
  same.given_perm = chol.symbolic().perm;
  EXPECT_TRUE(fresh.analyze(a, same).ok());
  EXPECT_TRUE(fresh.factorize(a).ok());
  return factor_difference(chol, fresh);
}

TEST(UpdateTest, AddAnchorMatchesFreshFactorization) {
  for (SimdLevel level : supported_levels()) {
    for (uint32_t seed = 1; seed <= 12; ++seed) {
      const int32_t n = 20 + static_cast<int32_t>(seed * 37 % 400);
      CscMatrix a = random_spd(n, 1.0 + seed % 4, seed, seed % 3 == 0 ? 1 : 0, 1 + seed % 3);
      Cholesky updated;
      updated.set_kernels(dense_kernels(level));
      ASSERT_TRUE(updated.analyze(a).ok());
      ASSERT_TRUE(updated.factorize(a).ok());
      for (int u = 0; u < 15; ++u) {
        const int32_t j = static_cast<int32_t>((u * 2654435761u + seed) % n);
        const double w = 0.5 + u;
        UpdateStats st;
        ASSERT_TRUE(updated.add_anchor(j, w, &st).ok());
        add_to_diagonal(&a, j, w * w);
        EXPECT_GE(st.path_columns, 1);
        EXPECT_GE(st.touched, st.path_columns);
      }
      EXPECT_LT(difference_from_fresh(updated, a), 1e-12) << simd_level_name(level) << " seed " << seed;
    }
  }
}

// Adding and removing anchors on a factor whose wide supernodes are chains
// of panels: the updater walks the panels as supernodes.
TEST(UpdateTest, UpdatesOnPanelChainsMatchFreshFactorization) {
  AnalyzeOptions options;
  options.panel_cols = 3;
  options.max_panels = 10;
  for (const CscMatrix& original : {testing_util::grid_laplacian(25, 20), random_spd(200, 8.0, 5, 1, 1)}) {
    CscMatrix a = original;
    Cholesky updated;
    ASSERT_TRUE(updated.analyze(a, options).ok());
    ASSERT_FALSE(updated.symbolic().continued.empty());
    ASSERT_TRUE(updated.factorize(a).ok());
    const int32_t n = a.ncols;
    std::vector<int32_t> anchors;
    for (int u = 0; u < 12; ++u) anchors.push_back(static_cast<int32_t>((u * 2654435761u + 7) % n));
    std::sort(anchors.begin(), anchors.end());
    anchors.erase(std::unique(anchors.begin(), anchors.end()), anchors.end());
    ASSERT_TRUE(updated.add_anchors(anchors.data(), static_cast<int32_t>(anchors.size()), 3.0).ok());
    for (int32_t j : anchors) add_to_diagonal(&a, j, 9.0);
    ASSERT_TRUE(updated.add_anchor(anchors[0], 2.0).ok());
    ASSERT_TRUE(updated.remove_anchor(anchors[1], 3.0).ok());
    add_to_diagonal(&a, anchors[0], 4.0);
    add_to_diagonal(&a, anchors[1], -9.0);
    Cholesky fresh;
    AnalyzeOptions same = options;
    same.ordering = Ordering::kGiven;
    same.given_perm = updated.symbolic().perm;
    ASSERT_TRUE(fresh.analyze(a, same).ok());
    ASSERT_TRUE(fresh.factorize(a).ok());
    ASSERT_EQ(fresh.symbolic().value_ptr, updated.symbolic().value_ptr);
    EXPECT_LT(factor_difference(updated, fresh), 1e-12);
  }
}

// The updaters' workspace shares its buffer with the factorization's
// stacks: an update after a refactorization must not see what the stacks
// left there.
TEST(UpdateTest, UpdatesAfterARefactorizationMatchFreshFactorization) {
  CscMatrix a = testing_util::grid_laplacian(30, 25);
  Cholesky chol;
  ASSERT_TRUE(chol.analyze(a).ok());
  ASSERT_TRUE(chol.factorize(a).ok());
  ASSERT_TRUE(chol.add_anchor(7, 2.0).ok());
  for (double& v : a.values) v *= 1.5;  // new values, same pattern
  ASSERT_TRUE(chol.factorize(a).ok());
  const int32_t anchors[] = {3, 400, 701};
  ASSERT_TRUE(chol.add_anchors(anchors, 3, 1.5).ok());
  ASSERT_TRUE(chol.add_anchor(100, 2.5).ok());
  for (int32_t j : anchors) add_to_diagonal(&a, j, 2.25);
  add_to_diagonal(&a, 100, 6.25);
  EXPECT_LT(difference_from_fresh(chol, a), 1e-12);
}

TEST(UpdateTest, PathStatisticsFollowTheEliminationTree) {
  const CscMatrix a = testing_util::grid_laplacian(30, 30);
  Cholesky chol;
  AnalyzeOptions options;
  options.relax.enabled = false;  // fundamental supernodes: stored == true structure
  ASSERT_TRUE(chol.analyze(a, options).ok());
  ASSERT_TRUE(chol.factorize(a).ok());
  const SymbolicFactor& f = chol.symbolic();
  for (int32_t j : {0, 17, 450, 899}) {
    UpdateStats st;
    ASSERT_TRUE(chol.add_anchor(j, 1.0, &st).ok());
    const std::vector<int32_t> path = f.etree.path_to_root(f.inverse_perm[j]);
    EXPECT_EQ(st.path_columns, static_cast<int32_t>(path.size()));
    int64_t touched = 0;
    for (int32_t c : path) touched += f.column_counts[c];
    EXPECT_EQ(st.touched, touched);
  }
}

TEST(UpdateTest, SolveAfterUpdatesSeesTheUpdatedMatrix) {
  CscMatrix a = random_spd(300, 3.0, 9, 1);
  Cholesky chol;
  ASSERT_TRUE(chol.analyze(a).ok());
  ASSERT_TRUE(chol.factorize(a).ok());
  for (int32_t j = 0; j < 300; j += 7) {
    ASSERT_TRUE(chol.add_anchor(j, 3.0).ok());
    add_to_diagonal(&a, j, 9.0);
  }
  std::vector<double> x(300), b(300), ax(300);
  for (int32_t i = 0; i < 300; ++i) b[i] = std::sin(i * 0.3);
  x = b;
  ASSERT_TRUE(chol.solve(x.data(), 1, 300).ok());
  symmetric_lower_matvec(a, x.data(), ax.data());
  double num = 0.0, den = 0.0;
  for (int32_t i = 0; i < 300; ++i) {
    num += (ax[i] - b[i]) * (ax[i] - b[i]);
    den += b[i] * b[i];
  }
  EXPECT_LT(std::sqrt(num / den), 1e-13);
}

TEST(UpdateTest, RemoveUndoesAdd) {
  for (SimdLevel level : supported_levels()) {
    const CscMatrix a = random_spd(250, 2.5, 4, 1, 2);
    Cholesky chol, original;
    chol.set_kernels(dense_kernels(level));
    ASSERT_TRUE(chol.analyze(a).ok());
    ASSERT_TRUE(chol.factorize(a).ok());
    ASSERT_TRUE(original.analyze(a).ok());
    ASSERT_TRUE(original.factorize(a).ok());
    for (int32_t j : {3, 100, 249, 3, 17}) ASSERT_TRUE(chol.add_anchor(j, 2.0).ok());
    for (int32_t j : {17, 3, 249, 100, 3}) ASSERT_TRUE(chol.remove_anchor(j, 2.0).ok());
    EXPECT_LT(factor_difference(chol, original), 1e-11) << simd_level_name(level);
  }
}

TEST(UpdateTest, RemoveThatWouldLosePositiveDefinitenessFailsAndKeepsTheFactor) {
  // diag(1, 2, 3) plus couplings: removing more than the diagonal holds fails.
  CscMatrix a;
  ASSERT_TRUE(csc_from_triplets(3, 3, {{0, 0, 1.0}, {1, 0, 0.1}, {1, 1, 2.0}, {2, 2, 3.0}}, &a).ok());
  Cholesky chol, original;
  ASSERT_TRUE(chol.analyze(a).ok());
  ASSERT_TRUE(chol.factorize(a).ok());
  ASSERT_TRUE(original.analyze(a).ok());
  ASSERT_TRUE(original.factorize(a).ok());
  const Status s = chol.remove_anchor(2, 2.0);  // 3 - 4 < 0
  EXPECT_EQ(s.code(), StatusCode::kNotPositiveDefinite);
  EXPECT_EQ(s.message(), "removing anchor 2 would leave a matrix that is not positive definite");
  EXPECT_EQ(factor_difference(chol, original), 0.0);
  EXPECT_TRUE(chol.remove_anchor(2, 1.0).ok());  // 3 - 1 > 0 still fine
}

TEST(UpdateTest, BadArguments) {
  const CscMatrix a = random_spd(10, 2.0, 1);
  Cholesky chol;
  EXPECT_EQ(chol.add_anchor(0, 1.0).message(), "update before factorize");
  ASSERT_TRUE(chol.analyze(a).ok());
  ASSERT_TRUE(chol.factorize(a).ok());
  EXPECT_EQ(chol.add_anchor(10, 1.0).message(), "anchor 10 is not a row (n = 10)");
  EXPECT_EQ(chol.add_anchor(-1, 1.0).code(), StatusCode::kInvalidArgument);
  EXPECT_EQ(chol.add_anchor(1, 0.0).message(), "anchor weight must be finite and nonzero");
  EXPECT_EQ(chol.add_anchor(1, NAN).code(), StatusCode::kInvalidArgument);
}

TEST(UpdateTest, AllSimdLevelsGiveBitIdenticalFactors) {
  // A random pattern, and a grid whose separator supernodes are long
  // enough for every row-chunk path of the kernels (4 chunks, 1, scalar).
  const std::vector<SimdLevel> levels = supported_levels();
  const CscMatrix matrices[] = {random_spd(400, 4.0, 21, 1), testing_util::grid_laplacian(40, 40)};
  for (const CscMatrix& a : matrices) {
    std::vector<std::vector<double>> results;
    for (SimdLevel level : levels) {
      Cholesky chol;
      chol.set_kernels(dense_kernels(SimdLevel::kScalar));  // same factor to start from
      ASSERT_TRUE(chol.analyze(a).ok());
      ASSERT_TRUE(chol.factorize(a).ok());
      chol.set_kernels(dense_kernels(level));
      for (int32_t j = 0; j < a.ncols; j += 13) ASSERT_TRUE(chol.add_anchor(j, 1.5).ok());
      const int64_t size = chol.symbolic().value_ptr.back();
      results.emplace_back(chol.values(), chol.values() + size);
    }
    // Compare the lower trapezoids (the strict upper triangle of diagonal
    // blocks is unspecified).
    Cholesky probe;
    ASSERT_TRUE(probe.analyze(a).ok());
    const SymbolicFactor& f = probe.symbolic();
    for (size_t l = 1; l < results.size(); ++l) {
      for (int32_t s = 0; s < f.num_supernodes; ++s) {
        const int32_t m = f.rows(s);
        for (int32_t c = 0; c < f.cols(s); ++c)
          for (int32_t t = c; t < m; ++t) {
            const int64_t q = f.value_ptr[s] + static_cast<int64_t>(c) * m + t;
            ASSERT_EQ(results[l][q], results[0][q]) << simd_level_name(levels[l]);
          }
      }
    }
  }
}

}  // namespace
}  // namespace gab

namespace gab {
namespace {

TEST(UpdateBatchTest, BatchEqualsSingleUpdates) {
  for (SimdLevel level : supported_levels()) {
    for (int32_t batch : {2, 3, 8, 13, 40}) {
      CscMatrix a = random_spd(350, 3.0, 31 + batch, 1, 2);
      Cholesky chol;
      chol.set_kernels(dense_kernels(level));
      ASSERT_TRUE(chol.analyze(a).ok());
      ASSERT_TRUE(chol.factorize(a).ok());
      std::vector<int32_t> js;
      for (int32_t i = 0; i < batch; ++i) js.push_back((i * 97 + batch) % 350);
      js.push_back(js[0]);  // a repeated anchor is a legal rank-2 contribution
      UpdateStats st;
      ASSERT_TRUE(chol.add_anchors(js.data(), static_cast<int32_t>(js.size()), 2.0, &st).ok());
      for (int32_t j : js) add_to_diagonal(&a, j, 4.0);
      // Mixed with singles and removals afterwards: the workspace invariants hold.
      ASSERT_TRUE(chol.add_anchor(5, 1.0).ok());
      add_to_diagonal(&a, 5, 1.0);
      ASSERT_TRUE(chol.remove_anchor(5, 1.0).ok());
      add_to_diagonal(&a, 5, -1.0);
      ASSERT_TRUE(chol.add_anchors(js.data(), 3, 1.0).ok());
      for (int32_t i = 0; i < 3; ++i) add_to_diagonal(&a, js[i], 1.0);
      EXPECT_LT(difference_from_fresh(chol, a), 1e-12) << simd_level_name(level) << " batch " << batch;
    }
  }
}

TEST(UpdateBatchTest, BatchTouchesTheUnionOnce) {
  const CscMatrix a = testing_util::grid_laplacian(40, 40);
  Cholesky chol;
  ASSERT_TRUE(chol.analyze(a).ok());
  ASSERT_TRUE(chol.factorize(a).ok());
  const int32_t js[4] = {0, 1, 2, 3};
  UpdateStats batch, single, sum;
  ASSERT_TRUE(chol.add_anchors(js, 4, 1.0, &batch).ok());
  for (int32_t j : js) {
    ASSERT_TRUE(chol.add_anchor(j, 1.0, &single).ok());
    sum.touched += single.touched;
  }
  EXPECT_LT(batch.touched, sum.touched);  // shared path segments counted once
  EXPECT_GE(batch.touched * 4, sum.touched);
}

}  // namespace
}  // namespace gab
