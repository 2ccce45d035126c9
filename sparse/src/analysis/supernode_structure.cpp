// From a supernode partition to the supernodal structure: the supernode
// tree, each supernode's rows, and the layout of the dense blocks.
#include "gab/sparse/supernode_structure.h"

#include <algorithm>
#include <vector>

namespace gab {

void link_supernodes(SymbolicFactor* f) {
  f->num_supernodes = static_cast<int32_t>(f->first_col.size()) - 1;
  const int32_t ns = f->num_supernodes;
  f->supernode_of.resize(f->n);
  for (int32_t s = 0; s < ns; ++s) {
    for (int32_t j = f->first_col[s]; j < f->first_col[s + 1]; ++j) f->supernode_of[j] = s;
  }
  f->supernode_parent.assign(ns, -1);
  for (int32_t s = 0; s < ns; ++s) {
    // A panel's parent is the next panel of its chain, whose columns come
    // first below its own (supernode_rows): in an amalgamated supernode its
    // last column's etree parent may lie further up the chain.
    const int32_t p = f->etree.parent[f->first_col[s + 1] - 1];
    f->supernode_parent[s] = f->continues(s) ? s + 1 : p == -1 ? -1 : f->supernode_of[p];
  }
}

void supernode_rows(const CscMatrix& graph, SymbolicFactor* f) {
  const int32_t ns = f->num_supernodes;
  // mark[i] == s: row i is already among the rows below the supernode (or
  // chain) starting at s.
  std::vector<int32_t> mark(f->n, -1);
  std::vector<std::vector<int32_t>> children(ns);
  for (int32_t s = 0; s < ns; ++s) {
    if (f->supernode_parent[s] != -1) children[f->supernode_parent[s]].push_back(s);
  }
  f->row_ptr.assign(ns + 1, 0);
  f->row_ind.clear();
  std::vector<int32_t> below;
  for (int32_t s = 0; s < ns; ++s) {
    // A chain of panels s..e has the rows of the supernode it was cut from:
    // panel t holds the chain's columns from its own on, then the rows below
    // the chain (a superset of its own structure where the supernode was
    // amalgamated; the same rows its block had before the cut).
    const int32_t e = f->chain_last(s);
    const int32_t first = f->first_col[s], last = f->first_col[e + 1] - 1;
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
    // Children come before their parent (postorder): their rows are known.
    for (int32_t t = s; t <= e; ++t) {
      for (int32_t child : children[t]) {
        if (child >= s) continue;  // the chain's previous panel
        for (int64_t p = f->row_ptr[child]; p < f->row_ptr[child + 1]; ++p) {
          const int32_t i = f->row_ind[p];
          if (i > last && mark[i] != s) {
            mark[i] = s;
            below.push_back(i);
          }
        }
      }
    }
    std::sort(below.begin(), below.end());
    for (int32_t t = s; t <= e; ++t) {
      for (int32_t j = f->first_col[t]; j <= last; ++j) f->row_ind.push_back(j);
      f->row_ind.insert(f->row_ind.end(), below.begin(), below.end());
      f->row_ptr[t + 1] = static_cast<int64_t>(f->row_ind.size());
    }
    s = e;
  }
}

void lay_out_blocks(SymbolicFactor* f) {
  const int32_t ns = f->num_supernodes;
  f->value_ptr.assign(ns + 1, 0);
  f->stored_L = 0;
  f->max_front_rows = 0;
  for (int32_t s = 0; s < ns; ++s) {
    const int64_t m = f->rows(s), k = f->cols(s);
    f->value_ptr[s + 1] = f->value_ptr[s] + m * k;
    // The block is m x k; the k (k - 1) / 2 entries above its diagonal are
    // allocated but not part of L (panels keep these few: AnalyzeOptions).
    f->stored_L += k * m - k * (k - 1) / 2;
    f->max_front_rows = std::max(f->max_front_rows, static_cast<int32_t>(m));
  }
}

}  // namespace gab
