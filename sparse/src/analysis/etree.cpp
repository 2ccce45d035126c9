// Elimination tree and postorder (Liu, "The role of elimination trees in
// sparse factorization", SIMAX 1990; Davis, "Direct Methods", sec. 4.1, 4.3).
#include "gab/sparse/etree.h"

#include <algorithm>

namespace gab {

EliminationTree elimination_tree(const CscMatrix& lower) {
  return elimination_tree_of_graph(symmetric_graph(lower), nullptr, nullptr);
}

EliminationTree elimination_tree_of_graph(const CscMatrix& graph, const int32_t* perm,
                                          const int32_t* inverse_perm) {
  const int32_t n = graph.ncols;
  EliminationTree tree;
  tree.parent.assign(n, -1);
  // ancestor[] is the path-compressed "virtual forest": following it from j
  // reaches the current root of j's subtree quickly.
  std::vector<int32_t> ancestor(n, -1);
  // Liu's algorithm visits the rows k in order and, for each, the columns
  // i < k with A(k, i) != 0 (both triangles of the graph are at hand).
  for (int32_t k = 0; k < n; ++k) {
    const int32_t col = perm != nullptr ? perm[k] : k;
    for (int32_t p = graph.colptr[col]; p < graph.colptr[col + 1]; ++p) {
      int32_t i = inverse_perm != nullptr ? inverse_perm[graph.rowind[p]] : graph.rowind[p];
      // Climb from i to the root of its subtree, pointing each visited node
      // at k (path compression); that root's parent is k.
      while (i != -1 && i < k) {
        const int32_t next = ancestor[i];
        ancestor[i] = k;
        if (next == -1) tree.parent[i] = k;
        i = next;
      }
    }
  }
  tree.postorder = tree_postorder(tree.parent);
  return tree;
}

std::vector<int32_t> tree_postorder(const std::vector<int32_t>& parent) {
  const int32_t n = static_cast<int32_t>(parent.size());
  // Children as linked lists; inserting in decreasing order makes each list
  // increasing, so the postorder of a postordered tree is the identity.
  std::vector<int32_t> head(n, -1), next(n, -1), stack;
  for (int32_t j = n - 1; j >= 0; --j) {
    if (parent[j] == -1) continue;
    next[j] = head[parent[j]];
    head[parent[j]] = j;
  }
  std::vector<int32_t> post;
  post.reserve(n);
  stack.reserve(n);
  for (int32_t root = 0; root < n; ++root) {
    if (parent[root] != -1) continue;
    stack.push_back(root);
    while (!stack.empty()) {
      const int32_t top = stack.back();
      const int32_t child = head[top];
      if (child == -1) {
        stack.pop_back();
        post.push_back(top);
      } else {
        head[top] = next[child];  // consume the child, descend into it
        stack.push_back(child);
      }
    }
  }
  return post;
}

int32_t EliminationTree::height() const {
  const int32_t n = size();
  // Depth from the leaves: in a postorder every child precedes its parent.
  std::vector<int32_t> depth(n, 1);
  int32_t best = 0;
  for (int32_t k = 0; k < n; ++k) {
    const int32_t j = postorder[k];
    best = std::max(best, depth[j]);
    if (parent[j] != -1) depth[parent[j]] = std::max(depth[parent[j]], depth[j] + 1);
  }
  return best;
}

std::vector<int32_t> EliminationTree::path_to_root(int32_t j) const {
  std::vector<int32_t> path;
  for (; j != -1; j = parent[j]) path.push_back(j);
  return path;
}

}  // namespace gab
