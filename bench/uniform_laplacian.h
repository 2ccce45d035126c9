// The lower triangle of a mesh's uniform graph Laplacian L = D - A (degrees on
// the diagonal, -1 per edge), the matrix the spectral benchmarks take
// eigenpairs of. O(V + E).
#pragma once

#include <cstdint>

#include "gab/mesh/edge_graph.h"
#include "gab/sparse/csc.h"

namespace gab_bench {

inline gab::CscMatrix uniform_laplacian_lower(const gab::EdgeGraph& graph) {
  const int32_t n = graph.num_vertices();
  gab::CscMatrix lower;
  lower.nrows = lower.ncols = n;
  lower.colptr.assign(n + 1, 0);
  for (int32_t v = 0; v < n; ++v) {
    lower.rowind.push_back(v);
    lower.values.push_back(graph.degree(v));
    for (int32_t p = graph.offsets[v]; p < graph.offsets[v + 1]; ++p) {
      if (graph.neighbors[p] <= v) continue;  // neighbours sorted: the lower triangle's rows ascend
      lower.rowind.push_back(graph.neighbors[p]);
      lower.values.push_back(-1.0);
    }
    lower.colptr[v + 1] = static_cast<int32_t>(lower.rowind.size());
  }
  return lower;
}

}  // namespace gab_bench
