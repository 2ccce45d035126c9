#include "gab/sparse/csc.h"

#include <gtest/gtest.h>

#include "sparse/test_matrices.h"

namespace gab {
namespace {

TEST(CscTest, TripletsSumDuplicatesAndSortRows) {
  CscMatrix a;
  ASSERT_TRUE(csc_from_triplets(3, 2, {{2, 0, 1.0}, {0, 0, 2.0}, {2, 0, 3.0}, {1, 1, 5.0}}, &a).ok());
  EXPECT_EQ(a.colptr, (std::vector<int32_t>{0, 2, 3}));
  EXPECT_EQ(a.rowind, (std::vector<int32_t>{0, 2, 1}));
  EXPECT_EQ(a.values, (std::vector<double>{2.0, 4.0, 5.0}));
  EXPECT_TRUE(check_csc(a).ok());
}

TEST(CscTest, TripletOutOfRangeIsAnError) {
  CscMatrix a;
  const Status s = csc_from_triplets(2, 2, {{0, 0, 1.0}, {2, 1, 1.0}}, &a);
  EXPECT_EQ(s.code(), StatusCode::kInvalidArgument);
  EXPECT_EQ(s.message(), "entry 1 at (2, 1) is outside a 2 x 2 matrix");
}

TEST(CscTest, CheckCscRejectsUnsortedRows) {
  CscMatrix a;
  a.nrows = a.ncols = 2;
  a.colptr = {0, 2, 2};
  a.rowind = {1, 0};
  a.values = {1, 1};
  EXPECT_EQ(check_csc(a).message(), "column 0 has an out-of-range or unsorted row index");
}

TEST(CscTest, TransposeTwiceIsIdentity) {
  const CscMatrix a = testing_util::random_spd(50, 3.0, 7);
  const CscMatrix t = transpose(a);
  EXPECT_TRUE(check_csc(t).ok());
  const CscMatrix tt = transpose(t);
  EXPECT_EQ(tt.colptr, a.colptr);
  EXPECT_EQ(tt.rowind, a.rowind);
  EXPECT_EQ(tt.values, a.values);
}

TEST(CscTest, SymmetricGraphHasBothTrianglesNoDiagonal) {
  const CscMatrix a = testing_util::random_spd(40, 2.0, 3);
  const CscMatrix g = symmetric_graph(a);
  EXPECT_TRUE(check_csc(g).ok());
  EXPECT_EQ(g.nnz(), 2 * (a.nnz() - 40));
  for (int32_t j = 0; j < 40; ++j) {
    for (int32_t p = g.colptr[j]; p < g.colptr[j + 1]; ++p) EXPECT_NE(g.rowind[p], j);
  }
}

TEST(CscTest, PermutedMatvecMatchesDense) {
  const int32_t n = 60;
  const CscMatrix a = testing_util::random_spd(n, 4.0, 11, 1);
  std::vector<int32_t> perm(n);
  for (int32_t i = 0; i < n; ++i) perm[i] = (i * 37 + 5) % n;
  ASSERT_TRUE(is_permutation(perm, n));
  const CscMatrix c = permute_symmetric_lower(a, perm);
  EXPECT_TRUE(check_csc(c).ok());
  const std::vector<double> dense = testing_util::to_dense_symmetric(a);
  std::vector<double> x(n), y(n), ydense(n, 0.0), xp(n), yp(n);
  for (int32_t i = 0; i < n; ++i) x[i] = std::sin(i + 1.0);
  symmetric_lower_matvec(a, x.data(), y.data());
  for (int32_t j = 0; j < n; ++j)
    for (int32_t i = 0; i < n; ++i) ydense[i] += dense[i + j * n] * x[j];
  for (int32_t i = 0; i < n; ++i) EXPECT_NEAR(y[i], ydense[i], 1e-12);
  // (P A P^T)(P x) = P (A x)
  for (int32_t k = 0; k < n; ++k) xp[k] = x[perm[k]];
  symmetric_lower_matvec(c, xp.data(), yp.data());
  for (int32_t k = 0; k < n; ++k) EXPECT_NEAR(yp[k], y[perm[k]], 1e-12);
}

TEST(CscTest, IsPermutationRejectsRepeatsAndRange) {
  EXPECT_TRUE(is_permutation({2, 0, 1}, 3));
  EXPECT_FALSE(is_permutation({0, 0, 1}, 3));
  EXPECT_FALSE(is_permutation({0, 1, 3}, 3));
  EXPECT_FALSE(is_permutation({0, 1}, 3));
}

}  // namespace
}  // namespace gab
