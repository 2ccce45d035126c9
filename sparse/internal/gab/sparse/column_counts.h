// Column counts of the Cholesky factor without forming it (Gilbert, Ng &
// Peyton, "An efficient algorithm to compute row and column counts for sparse
// Cholesky factorization", SIMAX 1994; Davis, "Direct Methods", sec. 4.5).
#pragma once

#include <cstdint>
#include <vector>

#include "gab/sparse/csc.h"
#include "gab/sparse/etree.h"

namespace gab {

// counts[j] = nnz of column j of L, diagonal included, for the symmetric
// matrix whose lower triangle is `lower` and its elimination tree.
// O(nnz * alpha(n)) time, O(n) workspace.
std::vector<int32_t> column_counts(const CscMatrix& lower, const EliminationTree& tree);

// Column counts of P G P^T for a symmetric pattern `graph` holding both
// triangles, perm[k] the original index of pivot k (nullptr: identity), and
// the elimination tree of P G P^T. Same costs, no permuted copy formed.
std::vector<int32_t> column_counts_of_graph(const CscMatrix& graph, const int32_t* perm,
                                            const int32_t* inverse_perm,
                                            const EliminationTree& tree);

}  // namespace gab
