// Elimination tree, column counts, supernodes and row structures against
// brute-force symbolic elimination.
#include <gtest/gtest.h>

#include "gab/sparse/amd.h"
#include "gab/sparse/column_counts.h"
#include "gab/sparse/etree.h"
#include "gab/sparse/supernodes.h"
#include "gab/sparse/symbolic.h"
#include "sparse/test_matrices.h"

namespace gab {
namespace {

using testing_util::brute_force_structure;
using testing_util::random_spd;

std::vector<CscMatrix> symbolic_cases() {
  std::vector<CscMatrix> cases;
  for (uint32_t seed = 0; seed < 40; ++seed) {
    const int32_t n = 1 + static_cast<int32_t>(seed * 7 % 90);
    cases.push_back(random_spd(n, 0.5 + (seed % 5), seed, seed % 3 == 0 ? 1 : 0, 1 + seed % 4));
  }
  cases.push_back(testing_util::grid_laplacian(9, 7));
  return cases;
}

TEST(EliminationTreeTest, ParentIsFirstOffDiagonalOfBruteForceFactor) {
  for (const CscMatrix& a : symbolic_cases()) {
    const int32_t n = a.ncols;
    const std::vector<char> s = brute_force_structure(a);
    const EliminationTree tree = elimination_tree(a);
    for (int32_t j = 0; j < n; ++j) {
      int32_t expect = -1;
      for (int32_t i = j + 1; i < n && expect == -1; ++i) {
        if (s[static_cast<size_t>(i) * n + j]) expect = i;
      }
      ASSERT_EQ(tree.parent[j], expect) << "n=" << n << " column " << j;
    }
  }
}

TEST(EliminationTreeTest, PostorderVisitsChildrenFirstAndSubtreesContiguously) {
  for (const CscMatrix& a : symbolic_cases()) {
    const EliminationTree tree = elimination_tree(a);
    const int32_t n = tree.size();
    ASSERT_TRUE(is_permutation(tree.postorder, n));
    const std::vector<int32_t> pos = invert_permutation(tree.postorder);
    std::vector<int32_t> size(n, 1);
    for (int32_t k = 0; k < n; ++k) {
      const int32_t j = tree.postorder[k];
      if (tree.parent[j] != -1) {
        EXPECT_LT(pos[j], pos[tree.parent[j]]);
        size[tree.parent[j]] += size[j];
      }
    }
    // Subtree of j occupies postorder positions pos[j]-size[j]+1 .. pos[j]:
    // every node there must have j as an ancestor.
    for (int32_t j = 0; j < n; ++j) {
      for (int32_t q = pos[j] - size[j] + 1; q <= pos[j]; ++q) {
        int32_t v = tree.postorder[q];
        while (v != -1 && v != j) v = tree.parent[v];
        EXPECT_EQ(v, j);
      }
    }
  }
}

TEST(EliminationTreeTest, PathAndHeightOfAChain) {
  EliminationTree tree;
  tree.parent = {1, 2, 3, -1, 3};
  tree.postorder = tree_postorder(tree.parent);
  EXPECT_EQ(tree.postorder, (std::vector<int32_t>{0, 1, 2, 4, 3}));
  EXPECT_EQ(tree.path_to_root(0), (std::vector<int32_t>{0, 1, 2, 3}));
  EXPECT_EQ(tree.path_to_root(4), (std::vector<int32_t>{4, 3}));
  EXPECT_EQ(tree.height(), 4);
}

TEST(ColumnCountsTest, MatchBruteForceStructure) {
  for (const CscMatrix& a : symbolic_cases()) {
    const int32_t n = a.ncols;
    const std::vector<char> s = brute_force_structure(a);
    const std::vector<int32_t> counts = column_counts(a, elimination_tree(a));
    for (int32_t j = 0; j < n; ++j) {
      int32_t expect = 0;
      for (int32_t i = j; i < n; ++i) expect += s[static_cast<size_t>(i) * n + j];
      ASSERT_EQ(counts[j], expect) << "n=" << n << " column " << j;
    }
  }
}

TEST(SupernodesTest, FundamentalJoinsAColumnOnlyWhereTheCountDropsByOne) {
  // Tridiagonal: etree is a chain, counts 2,2,...,2,1: no fundamental
  // merges except the last pair (count(j) = count(j+1) + 1 only there).
  const std::vector<int32_t> parent = {1, 2, 3, -1};
  EXPECT_EQ(fundamental_supernodes(parent, {2, 2, 2, 1}), (std::vector<int32_t>{0, 1, 2, 4}));
  // Dense 4x4: one supernode.
  EXPECT_EQ(fundamental_supernodes(parent, {4, 3, 2, 1}), (std::vector<int32_t>{0, 4}));
}

TEST(SupernodesTest, AnalysisRowStructuresCoverTheTrueFactor) {
  for (bool relax : {false, true}) {
    for (const CscMatrix& a : symbolic_cases()) {
      AnalyzeOptions options;
      options.ordering = Ordering::kNatural;
      options.relax.enabled = relax;
      SymbolicFactor f;
      ASSERT_TRUE(analyze(a, options, &f).ok());
      const CscMatrix c = permute_symmetric_lower(a, f.perm);
      const std::vector<char> s = brute_force_structure(c);
      const int32_t n = f.n;
      int64_t true_nnz = 0;
      for (int32_t j = 0; j < n; ++j) {
        const int32_t sn = f.supernode_of[j];
        std::vector<char> in(n, 0);
        for (int64_t p = f.row_ptr[sn]; p < f.row_ptr[sn + 1]; ++p) in[f.row_ind[p]] = 1;
        for (int32_t i = j; i < n; ++i) {
          if (s[static_cast<size_t>(i) * n + j]) {
            ++true_nnz;
            ASSERT_TRUE(in[i]) << "row " << i << " of column " << j << " missing";
          }
        }
      }
      EXPECT_EQ(f.nnz_L, true_nnz);
      if (!relax) {
        EXPECT_EQ(f.stored_L, f.nnz_L);  // fundamental supernodes add no zeros
      }
      EXPECT_GE(f.stored_L, f.nnz_L);
      for (int32_t sn = 0; sn < f.num_supernodes; ++sn) {
        // Own columns first, then strictly increasing rows below.
        for (int32_t t = 0; t < f.cols(sn); ++t) EXPECT_EQ(f.row_ind[f.row_ptr[sn] + t], f.first_col[sn] + t);
        for (int64_t p = f.row_ptr[sn] + 1; p < f.row_ptr[sn + 1]; ++p) EXPECT_LT(f.row_ind[p - 1], f.row_ind[p]);
      }
    }
  }
}

TEST(SymbolicTest, RejectsUpperTriangleAndNonSquare) {
  CscMatrix a;
  ASSERT_TRUE(csc_from_triplets(2, 2, {{0, 0, 1.0}, {0, 1, 1.0}, {1, 1, 1.0}}, &a).ok());
  SymbolicFactor f;
  Status s = analyze(a, AnalyzeOptions(), &f);
  EXPECT_EQ(s.code(), StatusCode::kInvalidArgument);
  EXPECT_EQ(s.message(), "entry (0, 1) is above the diagonal: pass the lower triangle");
  ASSERT_TRUE(csc_from_triplets(3, 2, {{0, 0, 1.0}}, &a).ok());
  EXPECT_EQ(analyze(a, AnalyzeOptions(), &f).message(), "matrix is 3 x 2, not square");
}

TEST(SymbolicTest, GivenOrderingMustBeAPermutation) {
  const CscMatrix a = random_spd(5, 1.0, 1);
  AnalyzeOptions options;
  options.ordering = Ordering::kGiven;
  options.given_perm = {0, 1, 2, 3, 3};
  SymbolicFactor f;
  EXPECT_EQ(analyze(a, options, &f).message(), "given ordering is not a permutation of 0..4");
}

TEST(SymbolicTest, AmdOptionsReachTheOrdering) {
  // Two rows coupled to every column: AMD postpones them as dense unless
  // told that no row is dense, and the two orders differ.
  const CscMatrix a = random_spd(200, 3.0, 5, /*dense_rows=*/2);
  AmdOptions no_dense;
  no_dense.dense = -1.0;
  std::vector<int32_t> amd_default, amd_no_dense;
  ASSERT_TRUE(amd_order(a, &amd_default).ok());
  ASSERT_TRUE(amd_order(a, &amd_no_dense, no_dense).ok());
  ASSERT_NE(amd_default, amd_no_dense);
  // The analysis with options.amd orders as the given AMD order would.
  for (const auto& amd : {std::make_pair(AmdOptions(), amd_default), std::make_pair(no_dense, amd_no_dense)}) {
    AnalyzeOptions options;
    options.amd = amd.first;
    SymbolicFactor by_amd, by_given;
    ASSERT_TRUE(analyze(a, options, &by_amd).ok());
    options.ordering = Ordering::kGiven;
    options.given_perm = amd.second;
    ASSERT_TRUE(analyze(a, options, &by_given).ok());
    EXPECT_EQ(by_amd.perm, by_given.perm);
  }
}

}  // namespace
}  // namespace gab
