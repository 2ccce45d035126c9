// The numeric assembly map of the symbolic analysis (SymbolicFactor::a_ptr,
// a_order, a_dest): the last step of analyze, kept apart so that Cholesky
// can fault in the factor's storage before it runs (symbolic.h).
#include "gab/sparse/symbolic.h"

#include <algorithm>
#include <vector>

namespace gab {

// For every entry of A (original numbering) its supernode and offset in the
// supernode's block, grouped per supernode so the numeric phase scatters A
// into one front at a time. Nothing of A's size is allocated beyond the map
// itself: this runs while Cholesky faults in the factor, at the analysis's
// peak (two per-entry scratch arrays were 0.2 GB of a 2.4M-vertex decode's).
void map_assembly(const CscMatrix& lower, SymbolicFactor* f) {
  const int32_t ns = f->num_supernodes;
  const int64_t nnz = lower.nnz();
  // An entry lands in the column of its earlier pivot, in that column's supernode.
  auto supernode_of_entry = [f](int32_t row, int32_t col) {
    return f->supernode_of[std::min(f->inverse_perm[row], f->inverse_perm[col])];
  };
  f->a_ptr.assign(ns + 1, 0);
  for (int32_t j = 0; j < lower.ncols; ++j) {
    for (int32_t p = lower.colptr[j]; p < lower.colptr[j + 1]; ++p) {
      ++f->a_ptr[supernode_of_entry(lower.rowind[p], j) + 1];
    }
  }
  for (int32_t s = 0; s < ns; ++s) f->a_ptr[s + 1] += f->a_ptr[s];
  f->a_order.assign(nnz, 0);
  f->a_dest.assign(nnz, 0);
  // a_dest holds each entry's column until its offset replaces it below.
  std::vector<int64_t> cursor(f->a_ptr.begin(), f->a_ptr.end() - 1);
  for (int32_t j = 0; j < lower.ncols; ++j) {
    for (int32_t p = lower.colptr[j]; p < lower.colptr[j + 1]; ++p) {
      const int64_t q = cursor[supernode_of_entry(lower.rowind[p], j)]++;
      f->a_order[q] = p;
      f->a_dest[q] = j;
    }
  }
  // local[i]: position of row i in the current supernode's rows.
  std::vector<int32_t> local(f->n, -1);
  for (int32_t s = 0; s < ns; ++s) {
    const int32_t m = f->rows(s);
    for (int32_t t = 0; t < m; ++t) local[f->row_ind[f->row_ptr[s] + t]] = t;
    for (int64_t q = f->a_ptr[s]; q < f->a_ptr[s + 1]; ++q) {
      const int32_t a = f->inverse_perm[lower.rowind[f->a_order[q]]], b = f->inverse_perm[f->a_dest[q]];
      const int32_t row = std::max(a, b), col = std::min(a, b);
      // Below 2^31: analyze_structure refuses larger blocks.
      f->a_dest[q] = (col - f->first_col[s]) * m + local[row];
    }
  }
}

}  // namespace gab
