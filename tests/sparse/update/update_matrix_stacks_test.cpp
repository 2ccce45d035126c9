// The two-stack layout of the multifrontal update matrices against a brute
// force: replay the groups, keep the set of live update matrices, and check
// that the layout's peak is the largest live total, that every live update
// lies inside its group's buffer, and that no two live updates overlap.
#include "gab/sparse/update_matrix_stacks.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "gab/sparse/dense_kernels.h"

namespace gab {
namespace {

// Only what the layout reads: the supernode tree and each supernode's
// columns and rows (rows - cols is the order of its update matrix).
SymbolicFactor supernode_tree(const std::vector<int32_t>& parent, const std::vector<int32_t>& cols,
                              const std::vector<int32_t>& below) {
  SymbolicFactor f;
  f.num_supernodes = static_cast<int32_t>(parent.size());
  f.supernode_parent = parent;
  f.first_col.assign(1, 0);
  f.row_ptr.assign(1, 0);
  for (int32_t s = 0; s < f.num_supernodes; ++s) {
    f.first_col.push_back(f.first_col.back() + cols[s]);
    f.row_ptr.push_back(f.row_ptr.back() + cols[s] + below[s]);
  }
  f.n = f.first_col.back();
  return f;
}

int64_t update_size(const SymbolicFactor& f, int32_t s) {
  return packed_lower_size(f.rows(s) - f.cols(s));
}

// Replays the groups with an explicit set of live updates. Returns each
// group's peak of live doubles; checks the layout's placement as it goes.
std::vector<int64_t> replay(const SymbolicFactor& f, const std::vector<int32_t>& order,
                            const std::vector<int32_t>& group_ptr,
                            const std::vector<int64_t>& stack_ptr,
                            const std::vector<int64_t>& offset) {
  const int32_t groups = static_cast<int32_t>(group_ptr.size()) - 1;
  std::vector<int32_t> group_of(f.num_supernodes);
  for (int32_t g = 0; g < groups; ++g) {
    for (int32_t i = group_ptr[g]; i < group_ptr[g + 1]; ++i) group_of[order[i]] = g;
  }
  std::vector<int64_t> peaks;
  for (int32_t g = 0; g < groups; ++g) {
    std::vector<int32_t> live;
    int64_t peak = 0;
    for (int32_t i = group_ptr[g]; i < group_ptr[g + 1]; ++i) {
      const int32_t s = order[i];
      live.push_back(s);  // s writes its update while its children's are live
      int64_t total = 0;
      for (int32_t a : live) {
        total += update_size(f, a);
        EXPECT_GE(offset[a], stack_ptr[g]) << "supernode " << a;
        EXPECT_LE(offset[a] + update_size(f, a), stack_ptr[g + 1]) << "supernode " << a;
        for (int32_t b : live) {
          const bool apart = a == b || offset[a] + update_size(f, a) <= offset[b] ||
                             offset[b] + update_size(f, b) <= offset[a];
          EXPECT_TRUE(apart) << "updates of " << a << " and " << b << " overlap";
        }
      }
      peak = std::max(peak, total);
      // Then s has assembled its children of this group: they are gone.
      live.erase(std::remove_if(live.begin(), live.end(),
                                [&](int32_t c) { return f.supernode_parent[c] == s && group_of[c] == g; }),
                 live.end());
    }
    peaks.push_back(peak);
  }
  return peaks;
}

void expect_layout_matches_replay(const SymbolicFactor& f, const std::vector<int32_t>& order,
                                  const std::vector<int32_t>& group_ptr) {
  std::vector<int64_t> stack_ptr, offset;
  lay_out_update_stacks(f, order, group_ptr, &stack_ptr, &offset);
  ASSERT_EQ(stack_ptr.size(), group_ptr.size());
  EXPECT_EQ(stack_ptr[0], 0);
  const std::vector<int64_t> peaks = replay(f, order, group_ptr, stack_ptr, offset);
  for (size_t g = 0; g < peaks.size(); ++g) {
    EXPECT_EQ(stack_ptr[g + 1] - stack_ptr[g], peaks[g]) << "group " << g;
  }
}

TEST(UpdateMatrixStacksTest, TreeDepthsCountEdgesToTheRoot) {
  EXPECT_EQ(tree_depths({2, 2, 5, 4, 5, -1, -1}), (std::vector<int32_t>{2, 2, 1, 2, 1, 0, 0}));
  EXPECT_TRUE(tree_depths({}).empty());
}

TEST(UpdateMatrixStacksTest, PeakOfAHandMadeTree) {
  //        5
  //      /   \       update orders (rows - cols): 2, 3, 2, 1, 2, 0, so
  //     2     4      sizes 4, 9, 4, 1, 4, 0 (packed_lower_size: p^2 below
  //    / \    |      one 16-column panel). The peak is when 2 writes its
  //   0   1   3      update while 0's and 1's are live: 4 + 9 + 4 = 17.
  const SymbolicFactor f = supernode_tree({2, 2, 5, 4, 5, -1}, {1, 2, 1, 3, 1, 2}, {2, 3, 2, 1, 2, 0});
  EXPECT_EQ(update_stack_size(f), 17);
  expect_layout_matches_replay(f, {0, 1, 2, 3, 4, 5}, {0, 6});
}

TEST(UpdateMatrixStacksTest, GroupsKeepChildrenOfOtherGroupsLive) {
  // Two subtree groups {0, 1, 2} and {3, 4} and the top part {5}, as a
  // schedule splits the tree above: 2's and 4's updates stay in their
  // groups' buffers (17, then 1 + 4); 5 pops none of them from its own
  // (empty) stacks.
  const SymbolicFactor f = supernode_tree({2, 2, 5, 4, 5, -1}, {1, 2, 1, 3, 1, 2}, {2, 3, 2, 1, 2, 0});
  const std::vector<int32_t> order = {0, 1, 2, 3, 4, 5}, group_ptr = {0, 3, 5, 6};
  std::vector<int64_t> stack_ptr, offset;
  lay_out_update_stacks(f, order, group_ptr, &stack_ptr, &offset);
  EXPECT_EQ(stack_ptr, (std::vector<int64_t>{0, 17, 22, 22}));
  expect_layout_matches_replay(f, order, group_ptr);
}

TEST(UpdateMatrixStacksTest, RandomForestsMatchTheReplay) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 50; ++trial) {
    const int32_t ns = 1 + static_cast<int32_t>(rng() % 40);
    std::vector<int32_t> parent(ns), cols(ns), below(ns);
    // Postordered: each node's subtree is the contiguous range just below
    // it. Build it by attaching s to the root of a range ending at s - 1.
    std::vector<int32_t> roots;  // current forest roots, increasing
    for (int32_t s = 0; s < ns; ++s) {
      const int32_t take = roots.empty() ? 0 : static_cast<int32_t>(rng() % (roots.size() + 1));
      for (int32_t i = 0; i < take; ++i) {
        parent[roots.back()] = s;
        roots.pop_back();
      }
      roots.push_back(s);
      cols[s] = 1 + static_cast<int32_t>(rng() % 4);
      below[s] = static_cast<int32_t>(rng() % 9);
    }
    for (int32_t r : roots) parent[r] = -1;
    const SymbolicFactor f = supernode_tree(parent, cols, below);
    std::vector<int32_t> order(ns);
    for (int32_t s = 0; s < ns; ++s) order[s] = s;
    expect_layout_matches_replay(f, order, {0, ns});
    std::vector<int64_t> stack_ptr;
    lay_out_update_stacks(f, order, {0, ns}, &stack_ptr, nullptr);
    EXPECT_EQ(update_stack_size(f), stack_ptr[1]);
  }
}

}  // namespace
}  // namespace gab
