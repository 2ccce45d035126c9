// Test oracles: a dense and a simplicial Cholesky, simple enough to be
// obviously right, that the fast supernodal path is checked against.
// Not tuned; do not use them for real work.
#pragma once

#include <cstdint>
#include <vector>

#include "gab/sparse/csc.h"
#include "gab/status.h"

namespace gab {

// Dense n x n column-major lower-triangular L with L L^T = A, A given as
// the lower triangle of a symmetric CSC matrix. O(n^3).
Status dense_cholesky(const CscMatrix& lower, std::vector<double>* l);

// Simplicial left-looking Cholesky (no ordering): L as a CSC matrix with
// exactly the structural nonzeros of the factor (diagonal first in each
// column). O(flops) with a dense work column.
Status simplicial_cholesky(const CscMatrix& lower, CscMatrix* l);

}  // namespace gab
