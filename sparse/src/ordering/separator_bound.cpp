// The separator bound on an update's cost (nested_dissection.h,
// separator_update_bounds): per node, the sum of the sizes of its proper
// ancestors A and of their column bounds P, computed from the roots down
// (the tree stores children before parents), then one lookup per index.
#include <string>

#include "gab/sparse/nested_dissection.h"

namespace gab {
namespace {

Status check_tree(const SeparatorTree& tree, const std::vector<int32_t>& perm) {
  const int32_t n = static_cast<int32_t>(perm.size());
  const int32_t count = static_cast<int32_t>(tree.nodes.size());
  if (static_cast<int32_t>(tree.column_node.size()) != n) {
    return Status::Error(StatusCode::kInvalidArgument, "separator_update_bounds: column_node does not have n entries");
  }
  for (int32_t s = 0; s < count; ++s) {
    const SeparatorTree::Node& node = tree.nodes[s];
    if (node.size < 0 || node.first < 0 || node.first > n - node.size || (node.parent >= 0 && node.parent <= s) ||
        node.parent >= count) {
      return Status::Error(StatusCode::kInvalidArgument, "separator_update_bounds: bad node " + std::to_string(s));
    }
  }
  std::vector<char> seen(static_cast<size_t>(n), 0);
  for (int32_t k = 0; k < n; ++k) {
    const int32_t s = tree.column_node[k];
    if (s < 0 || s >= count || k < tree.nodes[s].first || k >= tree.nodes[s].first + tree.nodes[s].size ||
        perm[k] < 0 || perm[k] >= n || seen[perm[k]]) {
      return Status::Error(StatusCode::kInvalidArgument,
                           "separator_update_bounds: tree and permutation disagree at pivot " + std::to_string(k));
    }
    seen[perm[k]] = 1;
  }
  return Status::Ok();
}

// |s| (|s| + 1) / 2 + |s| A: the column bounds of a node's m = |s| last columns.
int64_t last_columns_bound(int64_t m, int64_t above) { return m * (m + 1) / 2 + m * above; }

}  // namespace

Status separator_update_bounds(const SeparatorTree& tree, const std::vector<int32_t>& perm,
                               std::vector<int64_t>* bound) {
  GAB_RETURN_IF_ERROR(check_tree(tree, perm));
  const size_t count = tree.nodes.size();
  std::vector<int64_t> above(count, 0);      // A(s)
  std::vector<int64_t> ancestors(count, 0);  // sum of the ancestors' whole-node bounds
  for (size_t s = count; s-- > 0;) {
    const int32_t p = tree.nodes[s].parent;
    if (p < 0) continue;
    above[s] = above[p] + tree.nodes[p].size;
    ancestors[s] = ancestors[p] + last_columns_bound(tree.nodes[p].size, above[p]);
  }
  const int32_t n = static_cast<int32_t>(perm.size());
  bound->assign(static_cast<size_t>(n), 0);
  for (int32_t k = 0; k < n; ++k) {
    const int32_t s = tree.column_node[k];
    const int64_t m = tree.nodes[s].first + tree.nodes[s].size - k;
    (*bound)[perm[k]] = last_columns_bound(m, above[s]) + ancestors[s];
  }
  return Status::Ok();
}

}  // namespace gab
