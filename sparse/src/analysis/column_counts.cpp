// Gilbert-Ng-Peyton column counts by row-subtree skeletons.
//
// Row i of L is the "row subtree" of the etree rooted at i whose leaves are
// among the columns j < i with A(i, j) != 0. colcount(j) is the number of row
// subtrees containing j. Give every node a weight delta such that the sum of
// the weights in the subtree of j counts those row subtrees: +1 at each leaf
// of a row subtree, -1 at the least common ancestor of consecutive leaves (in
// postorder), and -1 at parent(i) where row subtree i ends. A column j is a
// leaf of row subtree i iff no earlier-visited descendant of j was one, i.e.
// first(j) > maxfirst(i), where first(j) is the postorder number of j's first
// descendant.
#include "gab/sparse/column_counts.h"

#include "gab/sparse/disjoint_set.h"

namespace gab {

std::vector<int32_t> column_counts(const CscMatrix& lower, const EliminationTree& tree) {
  return column_counts_of_graph(symmetric_graph(lower), nullptr, nullptr, tree);
}

std::vector<int32_t> column_counts_of_graph(const CscMatrix& graph, const int32_t* perm,
                                            const int32_t* inverse_perm,
                                            const EliminationTree& tree) {
  const int32_t n = graph.ncols;
  const std::vector<int32_t>& parent = tree.parent;
  const std::vector<int32_t>& post = tree.postorder;
  std::vector<int32_t> delta(n, 0), first(n, -1), maxfirst(n, -1), prevleaf(n, -1),
      ancestor(n);
  for (int32_t j = 0; j < n; ++j) ancestor[j] = j;
  // first[j]: postorder number of j's first descendant; etree leaves start
  // with weight 1 (their row subtree i = j is the single leaf j).
  for (int32_t k = 0; k < n; ++k) {
    int32_t j = post[k];
    delta[j] = (first[j] == -1) ? 1 : 0;
    for (; j != -1 && first[j] == -1; j = parent[j]) first[j] = k;
  }
  for (int32_t k = 0; k < n; ++k) {
    const int32_t j = post[k];
    if (parent[j] != -1) --delta[parent[j]];  // row subtree j ends at j
    // Rows i > j with A(i, j) != 0 (the test below skips i <= j).
    const int32_t col = perm != nullptr ? perm[j] : j;
    for (int32_t p = graph.colptr[col]; p < graph.colptr[col + 1]; ++p) {
      const int32_t i = inverse_perm != nullptr ? inverse_perm[graph.rowind[p]] : graph.rowind[p];
      if (i <= j || first[j] <= maxfirst[i]) continue;  // j is not a new leaf of row i
      maxfirst[i] = first[j];
      const int32_t jprev = prevleaf[i];
      prevleaf[i] = j;
      ++delta[j];
      if (jprev != -1) --delta[find_set_root(&ancestor, jprev)];  // lca(jprev, j)
    }
    if (parent[j] != -1) ancestor[j] = parent[j];
  }
  // Sum the weights over each subtree (children precede parents in post).
  for (int32_t k = 0; k < n; ++k) {
    const int32_t j = post[k];
    if (parent[j] != -1) delta[parent[j]] += delta[j];
  }
  return delta;
}

}  // namespace gab
