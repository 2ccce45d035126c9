// Approximate minimum degree ordering (Amestoy, Davis & Duff, SIAM J. Matrix
// Anal. Appl. 17(4), 1996; Davis, "Direct Methods for Sparse Linear Systems",
// sec. 7.1): quotient graph, approximate external degrees, element
// absorption, mass elimination of supervariables, aggressive absorption and
// dense-row postponement.
#pragma once

#include <cstdint>
#include <vector>

#include "gab/sparse/csc.h"
#include "gab/status.h"

namespace gab {

struct AmdOptions {
  // A row with more than max(16, dense * sqrt(n)) off-diagonal entries is
  // "dense": removed from the graph and ordered last. Negative: no row is dense.
  double dense = 10.0;
  // Absorb elements whose variables are all covered by the new pivot element.
  bool aggressive = true;
};

struct AmdInfo {
  int32_t n = 0;
  int32_t dense_rows = 0;        // rows postponed as dense
  // nnz(L) incl. diagonal of the returned ordering: exact when dense_rows == 0,
  // otherwise an upper bound (each dense row is counted as full below every pivot).
  int64_t nnz_L_estimate = 0;
  // Cholesky operation count sum_j |L(:,j)|^2 (column counts incl. diagonal), with
  // the same exactness as nnz_L_estimate.
  double flops_estimate = 0.0;
  int32_t compressions = 0;      // garbage collections of the workspace
};

// Orders a symmetric matrix given by its lower triangle (only the pattern is
// read; the diagonal is optional and ignored; rows must be strictly increasing
// within a column and none may lie above the diagonal). On success perm[k] is
// the original index of the k-th pivot. The order is a postorder of AMD's
// assembly tree with each pivot's supervariable block contiguous.
// Deterministic. Limits: n < 2^30 and 2 nnz_offdiag + n < 2^31.
// Memory: about 1.2 nnz(A + A^T) + 13 n int32 words of workspace, allocated
// once up front. Time: near O(nnz(A)) on mesh-like graphs (the ordering of a
// 134k-vertex 2-ring mesh matrix takes ~0.07 s).
Status amd_order(const CscMatrix& lower, std::vector<int32_t>* perm,
                 const AmdOptions& options = AmdOptions(), AmdInfo* info = nullptr);

}  // namespace gab
