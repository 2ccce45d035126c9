// Compressed sparse column matrices: the engine's one matrix format.
//
// Conventions (whole engine): 0-based int32 indices, double values, row
// indices sorted within each column. A symmetric matrix is stored as its
// lower triangle (row >= col) unless a function says otherwise. Index limit:
// n and nnz must fit in int32 (about 2.1e9); builders check and return
// StatusCode::kOverflow instead of wrapping.
#pragma once

#include <cstdint>
#include <vector>

#include "gab/status.h"

namespace gab {

struct CscMatrix {
  int32_t nrows = 0;
  int32_t ncols = 0;
  std::vector<int32_t> colptr;  // ncols + 1 entries
  std::vector<int32_t> rowind;  // nnz entries, sorted within each column
  std::vector<double> values;   // nnz entries, or empty for a pattern-only matrix

  int64_t nnz() const { return colptr.empty() ? 0 : colptr[ncols]; }
  bool has_values() const { return !values.empty() || nnz() == 0; }
};

struct Triplet {
  int32_t row;
  int32_t col;
  double value;
};

// Builds a CSC matrix from triplets; duplicates are summed, rows sorted.
// O(nnz + nrows + ncols). Fails on out-of-range indices.
Status csc_from_triplets(int32_t nrows, int32_t ncols, const std::vector<Triplet>& triplets,
                         CscMatrix* out);

// Returns A^T (values transposed too when present). O(nnz + nrows + ncols).
CscMatrix transpose(const CscMatrix& a);

// Checks the structural invariants: sizes, colptr monotone, rows in range,
// strictly increasing within each column. O(nnz).
Status check_csc(const CscMatrix& a);

// Lower triangle (row >= col) of a square matrix; entries above are dropped. O(nnz).
CscMatrix lower_triangle(const CscMatrix& a);

// Full symmetric pattern (both triangles, no diagonal, no values) of a
// symmetric matrix given by its lower triangle. O(nnz). This is the graph
// orderings work on.
CscMatrix symmetric_graph(const CscMatrix& lower);

// C = P A P^T for a symmetric A given by its lower triangle, returned as the
// lower triangle. perm[k] is the original index of the k-th row/column of C
// (the pivot order). O(nnz + n).
CscMatrix permute_symmetric_lower(const CscMatrix& lower, const std::vector<int32_t>& perm);

// y = A x for a symmetric A given by its lower triangle. O(nnz).
void symmetric_lower_matvec(const CscMatrix& lower, const double* x, double* y);

// Inverse of a permutation: inv[perm[k]] = k. O(n).
std::vector<int32_t> invert_permutation(const std::vector<int32_t>& perm);

// True when perm is a permutation of 0..n-1. O(n).
bool is_permutation(const std::vector<int32_t>& perm, int32_t n);

}  // namespace gab
