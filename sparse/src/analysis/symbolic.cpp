// The symbolic analysis (symbolic.h), read top to bottom in
// analyze_structure, one named call per step:
//   fill-reducing order -> elimination tree and its postorder -> permutation
//   -> column counts -> fundamental supernodes -> relaxed amalgamation
//   -> supernode tree -> row structures -> block layout -> update stack size
// then analyze adds the assembly map (assembly_map.cpp). No permuted copy of
// A is formed: every step reads A's symmetric pattern through the
// permutation.
#include "gab/sparse/symbolic.h"

#include <algorithm>
#include <string>

#include "analysis/heap_release_internal.h"
#include "gab/sparse/amd.h"
#include "gab/sparse/column_counts.h"
#include "gab/sparse/nested_dissection.h"
#include "gab/sparse/supernode_structure.h"
#include "gab/sparse/supernodes.h"
#include "gab/sparse/update_matrix_stacks.h"

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

// `graph` is symmetric_graph(lower).
Status fill_reducing_order(const CscMatrix& lower, const CscMatrix& graph, const AnalyzeOptions& options,
                           std::vector<int32_t>* order) {
  const int32_t n = lower.ncols;
  switch (resolve_ordering(options.ordering, n)) {
    case Ordering::kAuto:  // resolved above
    case Ordering::kAmd:
      return amd_order(lower, order, options.amd);
    case Ordering::kNestedDissection: {
      // The factorization's threads dissect too: the permutation is the same for any count.
      NestedDissectionOptions nd;
      nd.threads = options.threads;
      const Status status = nested_dissection_order_of_graph(graph, order, nd);
      release_heap_after_ordering(lower.nnz());  // only when the host asked (heap_release.h)
      return status;
    }
    case Ordering::kNatural:
      order->resize(n);
      for (int32_t i = 0; i < n; ++i) (*order)[i] = i;
      return Status::Ok();
    case Ordering::kGiven:
      if (!is_permutation(options.given_perm, n)) {
        return Status::Error(StatusCode::kInvalidArgument,
                             "given ordering is not a permutation of 0.." + std::to_string(n - 1));
      }
      *order = options.given_perm;
      return Status::Ok();
  }
  return Status::Error(StatusCode::kInvalidArgument, "unknown ordering");
}

// The pivot order: `order` followed by a postorder of its elimination tree,
// so that subtrees, and therefore supernodes, are contiguous ranges of
// columns. Writes perm, inverse_perm and the tree relabelled by that
// postorder (still a tree, now with the identity postorder).
void postorder_pivots(const CscMatrix& graph, const std::vector<int32_t>& order,
                      SymbolicFactor* f) {
  const std::vector<int32_t> order_inverse = invert_permutation(order);
  const EliminationTree tree = elimination_tree_of_graph(graph, order.data(), order_inverse.data());
  const std::vector<int32_t>& post = tree.postorder;
  const std::vector<int32_t> post_inverse = invert_permutation(post);
  f->perm.resize(f->n);
  f->etree.parent.resize(f->n);
  f->etree.postorder.resize(f->n);
  for (int32_t k = 0; k < f->n; ++k) {
    f->perm[k] = order[post[k]];
    const int32_t parent = tree.parent[post[k]];
    f->etree.parent[k] = parent == -1 ? -1 : post_inverse[parent];
    f->etree.postorder[k] = k;
  }
  f->inverse_perm = invert_permutation(f->perm);
}

// nnz_L and flops from the column counts.
void total_counts(SymbolicFactor* f) {
  for (int32_t k = 0; k < f->n; ++k) {
    f->nnz_L += f->column_counts[k];
    f->flops += static_cast<double>(f->column_counts[k]) * f->column_counts[k];
  }
}

}  // namespace

Status analyze_structure(const CscMatrix& lower, const AnalyzeOptions& options, SymbolicFactor* out) {
  GAB_RETURN_IF_ERROR(check_input(lower));
  SymbolicFactor f;
  f.n = lower.ncols;
  f.nnz_A = lower.nnz();
  std::vector<int32_t> order;
  const CscMatrix graph = symmetric_graph(lower);
  GAB_RETURN_IF_ERROR(fill_reducing_order(lower, graph, options, &order));
  postorder_pivots(graph, order, &f);
  f.column_counts = column_counts_of_graph(graph, f.perm.data(), f.inverse_perm.data(), f.etree);
  total_counts(&f);
  f.first_col = fundamental_supernodes(f.etree.parent, f.column_counts);
  if (options.relax.enabled) {
    f.first_col = relax_supernodes(f.first_col, f.etree.parent, f.column_counts, options.relax);
  }
  f.first_col = split_wide_supernodes(f.first_col, options.panel_cols, options.max_panels, &f.continued);
  if (std::find(f.continued.begin(), f.continued.end(), 1) == f.continued.end()) f.continued.clear();
  link_supernodes(&f);
  supernode_rows(graph, &f);
  lay_out_blocks(&f);
  // The assembly map's offsets within a block are 32-bit (symbolic.h).
  for (int32_t s = 0; s < f.num_supernodes; ++s) {
    if (f.value_ptr[s + 1] - f.value_ptr[s] > INT32_MAX) {
      return Status::Error(StatusCode::kResourceExhausted,
                           "supernode " + std::to_string(s) + " would hold " +
                               std::to_string(f.value_ptr[s + 1] - f.value_ptr[s]) +
                               " entries, more than 2^31 - 1");
    }
  }
  f.stack_peak = update_stack_size(f);
  *out = std::move(f);
  return Status::Ok();
}

Status analyze(const CscMatrix& lower, const AnalyzeOptions& options, SymbolicFactor* out) {
  GAB_RETURN_IF_ERROR(analyze_structure(lower, options, out));
  map_assembly(lower, out);
  return Status::Ok();
}

}  // namespace gab
