// Coarsening by heavy-edge matching (Karypis & Kumar, "A fast and high
// quality multilevel scheme for partitioning irregular graphs", SIAM J. Sci.
// Comput. 20(1), 1998, sec. 3.1 and 5.1): visit the vertices in random order;
// match each unmatched vertex with the unmatched neighbour joined by the
// heaviest edge; contract each pair. Heavy edges hidden inside coarse vertices
// are edges no coarse separator can cut, so the coarse graph's cuts are the
// fine graph's expensive ones.
#include <algorithm>

#include "ordering/fork_join.h"
#include "ordering/nested_dissection_graph.h"

namespace gab {
namespace nd {

namespace {

// Contracts the coarse vertices whose first fine vertex lies in [v_begin,
// v_end), c_begin being the first of them: coarse vertex c's list is the
// union of its fine vertices' lists, parallel edges merged (weights summed)
// through slot[] (-1 on entry and on exit for every coarse vertex), self
// loops dropped, entries in order of first appearance. Writes the lists to
// adj / adjw from 0, each row's end to row_end[c - c_begin] and its weight
// to vw[c - c_begin]; returns the entries written.
//
// A plain branch on whether a neighbour is new: a branch-free merge (every
// entry written at its slot) made each entry's load wait on the stores
// before it and ran at 26-33 ns an entry on igea and the 603k-vertex mesh
// (Zen 5), this at 9-13 ns, the mispredictions included; sorting each row's
// keys instead, 20 ns.
int32_t contract_rows(const Graph& fine, const int32_t* match, const int32_t* to_coarse, int32_t c_begin,
                      int32_t v_begin, int32_t v_end, int32_t* slot, int32_t* adj_out, int32_t* adjw_out,
                      int32_t* row_end, int32_t* vw) {
  const int32_t* xadj = fine.xadj.data();
  const int32_t* adj = fine.adj.data();
  const int32_t* adjw = fine.adjw.empty() ? nullptr : fine.adjw.data();
  int32_t q = 0, c = c_begin;
  for (int32_t v = v_begin; v < v_end; ++v) {
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
          adj_out[q] = cu;
          adjw_out[q] = w;
          ++q;
        } else {
          adjw_out[s] += w;
        }
      }
    }
    for (int32_t r = row_start; r < q; ++r) slot[adj_out[r]] = -1;
    vw[c - c_begin] = weight;
    row_end[c - c_begin] = q;
    ++c;
  }
  return q;
}

}  // namespace

void coarsen(const Graph& fine, int64_t max_vertex_weight, size_t thread_entries, Rng* rng, Workspace* ws,
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

  // Contract, rows in coarse-vertex order; for a large graph with a pool,
  // the second half of the rows is a task (any worker, or this one at the
  // join) writing buffers of its own, copied after the first (the result is
  // the same). The task touches no workspace: the join may run other tasks
  // on this thread, with this workspace, and coarsen reads it no more.
  const size_t fine_entries = fine.adj.size();
  coarse->n = nc;
  coarse->xadj.resize(static_cast<size_t>(nc) + 1);
  coarse->adj.resize(fine_entries);  // contraction never adds entries
  coarse->adjw.resize(fine_entries);
  coarse->vw.resize(static_cast<size_t>(nc));
  coarse->total_weight = fine.total_weight;
  coarse->xadj[0] = 0;
  if (ws->pool == nullptr || fine_entries < thread_entries || nc < 2) {
    const int32_t q = contract_rows(fine, match.data(), fine_to_coarse->data(), 0, 0, n, ws->slot.data(),
                                    coarse->adj.data(), coarse->adjw.data(), coarse->xadj.data() + 1,
                                    coarse->vw.data());
    coarse->adj.resize(static_cast<size_t>(q));
    coarse->adjw.resize(static_cast<size_t>(q));
    return;
  }
  // The second half starts at the first fine vertex of coarse vertex nc / 2.
  const int32_t c_split = nc / 2;
  int32_t v_split = 0;
  while ((*fine_to_coarse)[v_split] != c_split) ++v_split;
  size_t second_bound = 0;
  for (int32_t v = v_split; v < n; ++v) second_bound += static_cast<size_t>(fine.xadj[v + 1] - fine.xadj[v]);
  IntArray adj2(second_bound), adjw2(second_bound), xadj2(static_cast<size_t>(nc - c_split));
  std::vector<int32_t> slot2(static_cast<size_t>(nc), -1);
  int32_t q2 = 0;
  const std::vector<int32_t> pairs_copy(match.begin(), match.begin() + n);  // match is the workspace's
  const int32_t* pairs = pairs_copy.data();
  ForkJoinPool::Task second;
  second.fn = [&](int32_t) {
    q2 = contract_rows(fine, pairs, fine_to_coarse->data(), c_split, v_split, n, slot2.data(), adj2.data(),
                       adjw2.data(), xadj2.data(), coarse->vw.data() + c_split);
  };
  int32_t q1 = 0;
  ws->pool->fork_run_join(&second, [&] {
    q1 = contract_rows(fine, pairs, fine_to_coarse->data(), 0, 0, v_split, ws->slot.data(), coarse->adj.data(),
                       coarse->adjw.data(), coarse->xadj.data() + 1, coarse->vw.data());
  }, ws->worker);
  std::copy(adj2.begin(), adj2.begin() + q2, coarse->adj.begin() + q1);
  std::copy(adjw2.begin(), adjw2.begin() + q2, coarse->adjw.begin() + q1);
  for (int32_t c = c_split; c < nc; ++c) coarse->xadj[c + 1] = q1 + xadj2[c - c_split];
  coarse->adj.resize(static_cast<size_t>(q1) + q2);
  coarse->adjw.resize(static_cast<size_t>(q1) + q2);
}

}  // namespace nd
}  // namespace gab
