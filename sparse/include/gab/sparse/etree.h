// The elimination tree of a symmetric matrix: an explicit, inspectable object.
//
// parent[j] is the row index of the first off-diagonal nonzero of column j of
// the Cholesky factor L (or -1 for a root); the structure of L(:, j) lies on
// the path from j to its root. This is the tree the anchor updater walks.
#pragma once

#include <cstdint>
#include <vector>

#include "gab/sparse/csc.h"

namespace gab {

struct EliminationTree {
  std::vector<int32_t> parent;     // parent[j], -1 for roots
  std::vector<int32_t> postorder;  // postorder[k] = the k-th node in a postorder

  int32_t size() const { return static_cast<int32_t>(parent.size()); }
  // Number of nodes on the longest leaf-to-root path. O(n).
  int32_t height() const;
  // Nodes from j up to its root, j first. O(path length).
  std::vector<int32_t> path_to_root(int32_t j) const;
};

// Elimination tree of the symmetric matrix whose lower triangle is `lower`
// (pattern only). Liu's algorithm with path compression (Davis, "Direct
// Methods", sec. 4.1): O(nnz * alpha(n)) time, O(n + nnz) workspace.
EliminationTree elimination_tree(const CscMatrix& lower);

// Elimination tree of P G P^T, where `graph` holds both triangles of a
// symmetric pattern (see symmetric_graph) and perm[k] is the original index
// of pivot k (nullptr: identity), without forming the permuted matrix.
// O(nnz * alpha(n)) time, O(n) workspace.
EliminationTree elimination_tree_of_graph(const CscMatrix& graph, const int32_t* perm,
                                          const int32_t* inverse_perm);

// A postorder of the forest given by parent[] (children visited in
// increasing index order, so a tree that is already postordered maps to the
// identity). O(n), iterative.
std::vector<int32_t> tree_postorder(const std::vector<int32_t>& parent);

}  // namespace gab
