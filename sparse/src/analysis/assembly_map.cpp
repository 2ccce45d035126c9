// The numeric assembly map of the symbolic analysis (SymbolicFactor::a_ptr,
// a_order, a_dest): the last step of analyze, kept apart so that Cholesky
// can fault in the factor's storage before it runs (symbolic.h).
#include "gab/sparse/symbolic.h"

#include <algorithm>
#include <vector>

namespace gab {

// For every entry of A (original numbering) its supernode and offset in the
// factor's values, grouped per supernode so the numeric phase scatters A
// into one front at a time.
void map_assembly(const CscMatrix& lower, SymbolicFactor* f) {
  const int32_t ns = f->num_supernodes;
  const int64_t nnz = lower.nnz();
  std::vector<int32_t> super_of_entry(nnz);
  std::vector<int32_t> col_of_entry(nnz);
  // local[i]: position of row i in the current supernode's rows; filled per
  // supernode from its row list, so walk A by permuted column.
  std::vector<int32_t> local(f->n, -1);
  f->a_ptr.assign(ns + 1, 0);
  for (int32_t j = 0; j < lower.ncols; ++j) {
    for (int32_t p = lower.colptr[j]; p < lower.colptr[j + 1]; ++p) {
      const int32_t a = f->inverse_perm[lower.rowind[p]], b = f->inverse_perm[j];
      super_of_entry[p] = f->supernode_of[std::min(a, b)];
      col_of_entry[p] = j;
      ++f->a_ptr[super_of_entry[p] + 1];
    }
  }
  for (int32_t s = 0; s < ns; ++s) f->a_ptr[s + 1] += f->a_ptr[s];
  f->a_order.assign(nnz, 0);
  f->a_dest.assign(nnz, 0);
  std::vector<int64_t> cursor(f->a_ptr.begin(), f->a_ptr.end() - 1);
  for (int32_t j = 0; j < lower.ncols; ++j) {
    for (int32_t p = lower.colptr[j]; p < lower.colptr[j + 1]; ++p) {
      f->a_order[cursor[super_of_entry[p]]++] = p;
    }
  }
  for (int32_t s = 0; s < ns; ++s) {
    const int32_t m = f->rows(s);
    for (int32_t t = 0; t < m; ++t) local[f->row_ind[f->row_ptr[s] + t]] = t;
    for (int64_t q = f->a_ptr[s]; q < f->a_ptr[s + 1]; ++q) {
      const int32_t p = f->a_order[q];
      const int32_t a = f->inverse_perm[lower.rowind[p]], b = f->inverse_perm[col_of_entry[p]];
      const int32_t row = std::max(a, b), col = std::min(a, b);
      f->a_dest[q] = f->value_ptr[s] + static_cast<int64_t>(col - f->first_col[s]) * m + local[row];
    }
  }
}

}  // namespace gab
