// Coarsening by heavy-edge matching (Karypis & Kumar, "A fast and high
// quality multilevel scheme for partitioning irregular graphs", SIAM J. Sci.
// Comput. 20(1), 1998, sec. 3.1 and 5.1): visit the vertices in random order;
// match each unmatched vertex with the unmatched neighbour joined by the
// heaviest edge; contract each pair. Heavy edges hidden inside coarse vertices
// are edges no coarse separator can cut, so the coarse graph's cuts are the
// fine graph's expensive ones.
#include <algorithm>

#include "ordering/nested_dissection_graph.h"

namespace gab {
namespace nd {

void coarsen(const Graph& fine, int64_t max_vertex_weight, Rng* rng, Workspace* ws,
             IntArray* fine_to_coarse, Graph* coarse) {
  const int32_t n = fine.n;
  // Random visiting order (Fisher-Yates with our own generator: reproducible).
  std::vector<int32_t>& order = ws->queue;
  for (int32_t v = 0; v < n; ++v) order[v] = v;
  for (int32_t k = n - 1; k > 0; --k) std::swap(order[k], order[rng->below(k + 1)]);

  std::vector<int32_t>& match = ws->mark;
  std::fill(match.begin(), match.begin() + n, -1);
  const bool unit_edges = fine.adjw.empty();
  for (int32_t k = 0; k < n; ++k) {
    const int32_t v = order[k];
    if (match[v] >= 0) continue;
    int32_t best = v, best_weight = -1;
    for (int32_t p = fine.xadj[v]; p < fine.xadj[v + 1]; ++p) {
      const int32_t u = fine.adj[p];
      const int32_t weight = unit_edges ? 1 : fine.adjw[p];
      if (match[u] >= 0 || weight <= best_weight) continue;
      // Heavy coarse vertices would make a balanced coarse separator impossible.
      if (fine.vw[v] + fine.vw[u] > max_vertex_weight) continue;
      best = u;
      best_weight = weight;
      if (unit_edges) break;  // no later edge is heavier
    }
    match[v] = best;
    match[best] = v;
  }

  // Coarse vertices numbered in order of their smaller fine vertex.
  fine_to_coarse->assign(static_cast<size_t>(n), -1);
  int32_t nc = 0;
  for (int32_t v = 0; v < n; ++v) {
    if ((*fine_to_coarse)[v] >= 0) continue;
    (*fine_to_coarse)[v] = nc;
    (*fine_to_coarse)[match[v]] = nc;
    ++nc;
  }

  // Contract: coarse vertex c's list is the union of its fine vertices'
  // lists, parallel edges merged (weights summed) through slot[], self loops
  // dropped; entries in order of first appearance. A plain branch on whether
  // a neighbour is new: a branch-free merge (every entry written at its
  // slot) made each entry's load wait on the stores before it and ran at
  // 26-33 ns an entry on igea and the 603k-vertex mesh (Zen 5), this at
  // 9-13 ns, the mispredictions included; sorting each row's keys instead,
  // 20 ns.
  const size_t fine_entries = fine.adj.size();
  coarse->n = nc;
  coarse->xadj.resize(static_cast<size_t>(nc) + 1);
  coarse->adj.resize(fine_entries);  // contraction never adds entries
  coarse->adjw.resize(fine_entries);
  coarse->vw.resize(static_cast<size_t>(nc));
  coarse->total_weight = fine.total_weight;
  const int32_t* xadj = fine.xadj.data();
  const int32_t* adj = fine.adj.data();
  const int32_t* adjw = unit_edges ? nullptr : fine.adjw.data();
  const int32_t* to_coarse = fine_to_coarse->data();
  int32_t* cadj = coarse->adj.data();
  int32_t* cadjw = coarse->adjw.data();
  int32_t* slot = ws->slot.data();
  int32_t q = 0, c = 0;
  coarse->xadj[0] = 0;
  for (int32_t v = 0; v < n; ++v) {
    if (to_coarse[v] != c) continue;  // v is the second of its pair
    const int32_t row_start = q;
    const int32_t pair[2] = {v, match[v]};
    const int32_t members = match[v] == v ? 1 : 2;
    int32_t weight = 0;
    for (int32_t m = 0; m < members; ++m) {
      const int32_t x = pair[m];
      weight += fine.vw[x];
      for (int32_t p = xadj[x]; p < xadj[x + 1]; ++p) {
        const int32_t cu = to_coarse[adj[p]];
        if (cu == c) continue;
        const int32_t w = adjw ? adjw[p] : 1;
        const int32_t s = slot[cu];
        if (s < 0) {
          slot[cu] = q;
          cadj[q] = cu;
          cadjw[q] = w;
          ++q;
        } else {
          cadjw[s] += w;
        }
      }
    }
    for (int32_t r = row_start; r < q; ++r) slot[cadj[r]] = -1;
    coarse->vw[c] = weight;
    coarse->xadj[++c] = q;
  }
  coarse->adj.resize(static_cast<size_t>(q));
  coarse->adjw.resize(static_cast<size_t>(q));
}

}  // namespace nd
}  // namespace gab
