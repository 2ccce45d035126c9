// Relaxed amalgamation against its rule (supernodes.h), on hand-made trees
// whose merges are worked out by hand in the comments. Each supernode's
// "rows" is the column count at its first column; merging child s (a
// columns, r_s rows) into the group g holding its parent (b columns, r_g
// rows) gives k = a + b columns, m = a + r_g rows, and z = a (a + r_g - r_s)
// new explicit zeros (plus those both already had), out of
// k m - k (k - 1) / 2 stored entries.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "gab/sparse/supernodes.h"
#include "gab/sparse/symbolic.h"
#include "sparse/test_matrices.h"

namespace gab {
namespace {

using Partition = std::vector<int32_t>;

RelaxOptions relax(int32_t c0, int32_t c1, int32_t c2, double z0, double z1, double z2) {
  RelaxOptions o;
  o.cols[0] = c0;
  o.cols[1] = c1;
  o.cols[2] = c2;
  o.zeros[0] = z0;
  o.zeros[1] = z1;
  o.zeros[2] = z2;
  return o;
}

// No merge is ever allowed by its zeros (a fraction is never below 0): only
// the size rule cols[0] merges.
RelaxOptions size_only(int32_t c0) { return relax(c0, c0, c0, 0.0, 0.0, 0.0); }

TEST(RelaxSupernodesTest, AChainMergesTopDownUpToTheSizeLimit) {
  // Tridiagonal 4 x 4: counts 2, 2, 2, 1; fundamental supernodes {0} {1}
  // {2, 3}. Visiting from the top: {1} joins {2, 3} (k = 3), then {0} joins
  // {1, 2, 3} (k = 4).
  const std::vector<int32_t> parent = {1, 2, 3, -1};
  const std::vector<int32_t> counts = {2, 2, 2, 1};
  const Partition fundamental = {0, 1, 2, 4};
  EXPECT_EQ(relax_supernodes(fundamental, parent, counts, RelaxOptions()), (Partition{0, 4}));
  EXPECT_EQ(relax_supernodes(fundamental, parent, counts, size_only(4)), (Partition{0, 4}));
  // Size 3: {1, 2, 3} forms, {0} would make 4.
  EXPECT_EQ(relax_supernodes(fundamental, parent, counts, size_only(3)), (Partition{0, 1, 4}));
  // Size 2: {1} + {2, 3} is too big, but {0} + {1} is not: a child merges
  // into a parent that stayed alone.
  EXPECT_EQ(relax_supernodes(fundamental, parent, counts, size_only(2)), (Partition{0, 2, 4}));
  // Size 1: nothing.
  EXPECT_EQ(relax_supernodes(fundamental, parent, counts, size_only(1)), fundamental);
}

TEST(RelaxSupernodesTest, OnlyAChildWhoseColumnsEndWhereItsParentsGroupBeginsMerges) {
  // Column 0 and the chain 1 -> 2 -> 3 are both children of the root 4:
  // supernodes {0} {1, 2, 3} {4} (counts 2; 4, 3, 2; 1). {0}'s parent
  // column 4 is in {4}, which begins after {1, 2, 3}, not right after {0}.
  const std::vector<int32_t> parent = {4, 2, 3, 4, -1};
  const std::vector<int32_t> counts = {2, 4, 3, 2, 1};
  const Partition fundamental = {0, 1, 4, 5};
  // Size 2 would allow {0} + {4} (k = 2), but they are not contiguous;
  // {1, 2, 3} + {4} has k = 4.
  EXPECT_EQ(relax_supernodes(fundamental, parent, counts, size_only(2)), fundamental);
  // Size 4: {1, 2, 3, 4} forms and begins right after {0}; {0} + it has k = 5.
  EXPECT_EQ(relax_supernodes(fundamental, parent, counts, size_only(4)), (Partition{0, 1, 5}));
  // Size 5: then {0} joins too.
  EXPECT_EQ(relax_supernodes(fundamental, parent, counts, size_only(5)), (Partition{0, 5}));
}

TEST(RelaxSupernodesTest, EachSizeTierAllowsFewerZerosThanItsBound) {
  // Child {0, 1} with 3 rows (a = 2, r_s = 3) under the dense root {2, 3}
  // (b = 2, r_g = 2): k = 4, m = 4, z = 2 (2 + 2 - 3) = 2 of 16 - 6 = 10
  // stored entries, a fraction of exactly 0.2. The bounds are strict.
  const std::vector<int32_t> parent = {1, 2, 3, -1};
  const std::vector<int32_t> counts = {3, 2, 2, 1};
  const Partition apart = {0, 2, 4}, merged = {0, 4};
  auto run = [&](const RelaxOptions& o) { return relax_supernodes(apart, parent, counts, o); };
  // Any fraction merges at size <= cols[0].
  EXPECT_EQ(run(relax(4, 4, 4, 0.0, 0.0, 0.0)), merged);
  // Size <= cols[1]: fraction below zeros[0].
  EXPECT_EQ(run(relax(3, 4, 4, 0.25, 0.0, 0.0)), merged);
  EXPECT_EQ(run(relax(3, 4, 4, 0.2, 0.0, 0.0)), apart);
  EXPECT_EQ(run(relax(3, 3, 3, 0.25, 0.0, 0.0)), apart) << "k = 4 is past cols[1]";
  // Size <= cols[2]: fraction below zeros[1].
  EXPECT_EQ(run(relax(3, 3, 4, 0.9, 0.25, 0.0)), merged);
  EXPECT_EQ(run(relax(3, 3, 4, 0.9, 0.2, 0.0)), apart);
  EXPECT_EQ(run(relax(3, 3, 3, 0.9, 0.25, 0.0)), apart) << "k = 4 is past cols[2]";
  // Any size: fraction below zeros[2].
  EXPECT_EQ(run(relax(1, 1, 1, 0.9, 0.9, 0.25)), merged);
  EXPECT_EQ(run(relax(1, 1, 1, 0.9, 0.9, 0.2)), apart);
  // Without explicit zeros (the child has all 4 rows) any size merges for
  // any positive zeros[2].
  const std::vector<int32_t> full_counts = {4, 3, 2, 1};
  EXPECT_EQ(relax_supernodes(apart, parent, full_counts, relax(1, 1, 1, 0.0, 0.0, 0.01)), merged);
}

TEST(RelaxSupernodesTest, AGroupCarriesTheZerosOfWhatItAbsorbed) {
  // Chain {0} {1} {2, 3}, counts 2, 2, 2, 1 (tridiagonal, with {2, 3}
  // dense). {1} + {2, 3}: k = 3, m = 3, z = 1 (1 + 2 - 2) = 1 of 6 (1/6).
  // Then {0} + {1, 2, 3}: k = 4, m = 4, z = 1 + 1 (1 + 3 - 2) = 3 of 10
  // (0.3); without the carried 1 it would be 0.2.
  const std::vector<int32_t> parent = {1, 2, 3, -1};
  const Partition fundamental = {0, 1, 2, 4};
  const RelaxOptions quarter = relax(1, 4, 4, 0.25, 0.0, 0.0);
  EXPECT_EQ(relax_supernodes(fundamental, parent, {2, 2, 2, 1}, quarter), (Partition{0, 1, 4}));
  // With column 0 holding row 2 as well (count 3), z = 1 + 1 = 2 of 10.
  EXPECT_EQ(relax_supernodes(fundamental, parent, {3, 2, 2, 1}, quarter), (Partition{0, 4}));
}

TEST(RelaxSupernodesTest, AnalysisMergesFundamentalSupernodesIntoFewerLargerOnes) {
  const CscMatrix a = testing_util::grid_laplacian(9, 7);
  AnalyzeOptions options;
  options.ordering = Ordering::kNatural;
  SymbolicFactor relaxed, fundamental;
  ASSERT_TRUE(analyze(a, options, &relaxed).ok());
  options.relax.enabled = false;
  ASSERT_TRUE(analyze(a, options, &fundamental).ok());
  EXPECT_LT(relaxed.num_supernodes, fundamental.num_supernodes);
  EXPECT_GT(relaxed.stored_L, fundamental.stored_L);  // explicit zeros were let in
  // A coarsening: every relaxed boundary is a fundamental one.
  for (int32_t c : relaxed.first_col) {
    EXPECT_TRUE(std::binary_search(fundamental.first_col.begin(), fundamental.first_col.end(), c));
  }
}

TEST(SplitWideSupernodesTest, CutsIntoNearEqualPanelsUpToTheCap) {
  const std::vector<int32_t> first_col = {0, 2, 12, 13};  // widths 2, 10, 1
  std::vector<uint8_t> continued;
  EXPECT_EQ(split_wide_supernodes(first_col, 4, 8, &continued), (std::vector<int32_t>{0, 2, 6, 9, 12, 13}));
  EXPECT_EQ(continued, (std::vector<uint8_t>{0, 1, 1, 0, 0}));
  EXPECT_EQ(split_wide_supernodes(first_col, 4, 2, &continued), (std::vector<int32_t>{0, 2, 7, 12, 13}));
  EXPECT_EQ(continued, (std::vector<uint8_t>{0, 1, 0, 0}));
  EXPECT_EQ(split_wide_supernodes(first_col, 0, 8, &continued), first_col);
  EXPECT_EQ(continued, (std::vector<uint8_t>{0, 0, 0}));
  EXPECT_EQ(split_wide_supernodes(first_col, 10, 8, nullptr), first_col);
  EXPECT_EQ(split_wide_supernodes({0}, 4, 8, &continued), (std::vector<int32_t>{0}));
  EXPECT_TRUE(continued.empty());
}

}  // namespace
}  // namespace gab
