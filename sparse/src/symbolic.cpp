// The symbolic analysis pipeline (see symbolic.h):
//   order -> postorder -> permute -> etree -> column counts -> supernodes
//   -> row structures -> assembly map and multifrontal stack size.
#include "gab/sparse/symbolic.h"

#include <algorithm>
#include <string>

#include "gab/sparse/amd.h"
#include "gab/sparse/column_counts.h"
#include "gab/sparse/dense_kernels.h"
#include "gab/sparse/supernodes.h"

namespace gab {

namespace {

Status check_input(const CscMatrix& lower) {
  if (lower.nrows != lower.ncols) {
    return Status::Error(StatusCode::kInvalidArgument,
                         "matrix is " + std::to_string(lower.nrows) + " x " +
                             std::to_string(lower.ncols) + ", not square");
  }
  GAB_RETURN_IF_ERROR(check_csc(lower));
  for (int32_t j = 0; j < lower.ncols; ++j) {
    if (lower.colptr[j] < lower.colptr[j + 1] && lower.rowind[lower.colptr[j]] < j) {
      return Status::Error(StatusCode::kInvalidArgument,
                           "entry (" + std::to_string(lower.rowind[lower.colptr[j]]) + ", " +
                               std::to_string(j) +
                               ") is above the diagonal: pass the lower triangle");
    }
  }
  return Status::Ok();
}

Status fill_reducing_order(const CscMatrix& lower, const AnalyzeOptions& options,
                           std::vector<int32_t>* perm) {
  const int32_t n = lower.ncols;
  switch (options.ordering) {
    case Ordering::kAmd:
      return amd_order(lower, perm);
    case Ordering::kNatural:
      perm->resize(n);
      for (int32_t i = 0; i < n; ++i) (*perm)[i] = i;
      return Status::Ok();
    case Ordering::kGiven:
      if (!is_permutation(options.given_perm, n)) {
        return Status::Error(StatusCode::kInvalidArgument,
                             "given ordering is not a permutation of 0.." + std::to_string(n - 1));
      }
      *perm = options.given_perm;
      return Status::Ok();
  }
  return Status::Error(StatusCode::kInvalidArgument, "unknown ordering");
}

// Rows of every supernode: its own columns, then the union of the rows
// below it from A's columns and from its children's structures, sorted.
// `graph` is A's symmetric pattern in the original numbering.
void supernode_rows(const CscMatrix& graph, SymbolicFactor* f) {
  const int32_t ns = f->num_supernodes;
  std::vector<int32_t> mark(f->n, -1);
  std::vector<std::vector<int32_t>> children(ns);
  for (int32_t s = 0; s < ns; ++s) {
    if (f->supernode_parent[s] != -1) children[f->supernode_parent[s]].push_back(s);
  }
  f->row_ptr.assign(ns + 1, 0);
  f->row_ind.clear();
  std::vector<int32_t> below;
  for (int32_t s = 0; s < ns; ++s) {
    const int32_t first = f->first_col[s], last = f->first_col[s + 1] - 1;
    below.clear();
    for (int32_t j = first; j <= last; ++j) {
      const int32_t col = f->perm[j];
      for (int32_t p = graph.colptr[col]; p < graph.colptr[col + 1]; ++p) {
        const int32_t i = f->inverse_perm[graph.rowind[p]];
        if (i > last && mark[i] != s) {
          mark[i] = s;
          below.push_back(i);
        }
      }
    }
    for (int32_t child : children[s]) {
      for (int64_t p = f->row_ptr[child]; p < f->row_ptr[child + 1]; ++p) {
        const int32_t i = f->row_ind[p];
        if (i > last && mark[i] != s) {
          mark[i] = s;
          below.push_back(i);
        }
      }
    }
    std::sort(below.begin(), below.end());
    for (int32_t j = first; j <= last; ++j) f->row_ind.push_back(j);
    f->row_ind.insert(f->row_ind.end(), below.begin(), below.end());
    f->row_ptr[s + 1] = static_cast<int64_t>(f->row_ind.size());
  }
}

}  // namespace

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

Status analyze_structure(const CscMatrix& lower, const AnalyzeOptions& options, SymbolicFactor* out) {
  GAB_RETURN_IF_ERROR(check_input(lower));
  SymbolicFactor f;
  f.n = lower.ncols;
  f.nnz_A = lower.nnz();
  std::vector<int32_t> order;
  GAB_RETURN_IF_ERROR(fill_reducing_order(lower, options, &order));

  // Everything below reads the pattern through the permutation; no
  // permuted copy of A is formed. Renumber by a postorder of the etree so
  // that subtrees, and therefore supernodes, are contiguous ranges of
  // columns; relabelling the tree by its own postorder keeps it a tree.
  const CscMatrix graph = symmetric_graph(lower);
  const std::vector<int32_t> order_inverse = invert_permutation(order);
  const EliminationTree first_tree =
      elimination_tree_of_graph(graph, order.data(), order_inverse.data());
  const std::vector<int32_t>& post = first_tree.postorder;
  const std::vector<int32_t> post_inverse = invert_permutation(post);
  f.perm.resize(f.n);
  f.etree.parent.resize(f.n);
  f.etree.postorder.resize(f.n);
  for (int32_t k = 0; k < f.n; ++k) {
    f.perm[k] = order[post[k]];
    const int32_t parent = first_tree.parent[post[k]];
    f.etree.parent[k] = parent == -1 ? -1 : post_inverse[parent];
    f.etree.postorder[k] = k;
  }
  f.inverse_perm = invert_permutation(f.perm);
  f.column_counts =
      column_counts_of_graph(graph, f.perm.data(), f.inverse_perm.data(), f.etree);
  for (int32_t k = 0; k < f.n; ++k) {
    f.nnz_L += f.column_counts[k];
    f.flops += static_cast<double>(f.column_counts[k]) * f.column_counts[k];
  }

  f.first_col = fundamental_supernodes(f.etree.parent, f.column_counts);
  if (options.relax) {
    RelaxOptions relax;
    for (int i = 0; i < 3; ++i) {
      relax.cols[i] = options.relax_cols[i];
      relax.zeros[i] = options.relax_zeros[i];
    }
    f.first_col = relax_supernodes(f.first_col, f.etree.parent, f.column_counts, relax);
  }
  f.num_supernodes = static_cast<int32_t>(f.first_col.size()) - 1;
  const int32_t ns = f.num_supernodes;
  f.supernode_of.resize(f.n);
  for (int32_t s = 0; s < ns; ++s) {
    for (int32_t j = f.first_col[s]; j < f.first_col[s + 1]; ++j) f.supernode_of[j] = s;
  }
  f.supernode_parent.assign(ns, -1);
  for (int32_t s = 0; s < ns; ++s) {
    const int32_t p = f.etree.parent[f.first_col[s + 1] - 1];
    f.supernode_parent[s] = p == -1 ? -1 : f.supernode_of[p];
  }
  supernode_rows(graph, &f);

  f.value_ptr.assign(ns + 1, 0);
  for (int32_t s = 0; s < ns; ++s) {
    const int64_t m = f.rows(s), k = f.cols(s);
    f.value_ptr[s + 1] = f.value_ptr[s] + m * k;
    f.stored_L += k * m - k * (k - 1) / 2;
    f.max_front_rows = std::max(f.max_front_rows, static_cast<int32_t>(m));
  }
  // Multifrontal update stacks: an update matrix waits until its parent is
  // assembled. Updates of even-depth supernodes grow from one end of the
  // buffer, odd-depth ones from the other, so a parent's update is written
  // while its children's are read and nothing is ever moved (see
  // supernodal_factor.cpp). Simulate both ends to size the buffer.
  std::vector<int32_t> depth(ns, 0);
  for (int32_t s = ns - 1; s >= 0; --s) {
    if (f.supernode_parent[s] != -1) depth[s] = depth[f.supernode_parent[s]] + 1;
  }
  int64_t top[2] = {0, 0};
  std::vector<int64_t> pending(ns, 0);  // update doubles of s's children
  for (int32_t s = 0; s < ns; ++s) {
    const int64_t size = packed_lower_size(f.rows(s) - f.cols(s));  // packed lower triangles
    const int side = depth[s] & 1;
    top[side] += size;
    f.stack_peak = std::max(f.stack_peak, top[0] + top[1]);
    top[1 - side] -= pending[s];
    if (f.supernode_parent[s] != -1) pending[f.supernode_parent[s]] += size;
  }
  *out = std::move(f);
  return Status::Ok();
}

Status analyze(const CscMatrix& lower, const AnalyzeOptions& options, SymbolicFactor* out) {
  GAB_RETURN_IF_ERROR(analyze_structure(lower, options, out));
  map_assembly(lower, out);
  return Status::Ok();
}

}  // namespace gab
