// Approximate minimum degree ordering (Amestoy, Davis & Duff, SIAM J. Matrix
// Anal. Appl. 17(4), 1996; Davis, "Direct Methods for Sparse Linear Systems",
// sec. 7.1): quotient graph, approximate external degrees, element
// absorption, mass elimination of supervariables, aggressive absorption and
// dense-row postponement.
#pragma once

#include <cstdint>
#include <vector>

#include "gab/sparse/csc.h"
#include "gab/sparse/status.h"

namespace gab {

struct AmdOptions {
  // A row with more than max(16, dense * sqrt(n)) off-diagonal entries is
  // "dense": removed from the graph and ordered last.
  double dense = 10.0;
  // Absorb elements whose variables are all covered by the new pivot element.
  bool aggressive = true;
};

struct AmdInfo {
  int32_t n = 0;
  int32_t dense_rows = 0;        // rows postponed as dense
  int64_t nnz_L_estimate = 0;    // nnz(L) incl. diagonal predicted by the ordering
  double flops_estimate = 0.0;   // Cholesky flops predicted by the ordering
  int32_t compressions = 0;      // garbage collections of the workspace
};

// Orders a symmetric matrix given by its lower triangle (only the pattern is
// read; the diagonal is optional and ignored). On success perm[k] is the
// original index of the k-th pivot. O(nnz) memory (about 1.2 nnz + 8 n
// int32 words of workspace); time is near O(nnz) on mesh-like graphs.
Status amd_order(const CscMatrix& lower, std::vector<int32_t>* perm,
                 const AmdOptions& options = AmdOptions(), AmdInfo* info = nullptr);

}  // namespace gab
