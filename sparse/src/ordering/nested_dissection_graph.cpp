// Graph plumbing of the nested-dissection ordering: induced subgraphs (each
// side of a separator, each connected component) and connected components.
// The dissection itself follows George, "Nested dissection of a regular
// finite element mesh", SIAM J. Numer. Anal. 10(2), 1973: order the two
// sides of a separator first, the separator last, recursively.
#include <algorithm>

#include "ordering/nested_dissection_graph.h"

namespace gab {
namespace nd {

int64_t max_side_weight(const Graph& g, double imbalance) {
  return static_cast<int64_t>((1.0 + imbalance) * 0.5 * static_cast<double>(g.total_weight));
}

void Workspace::grow(int32_t n) {
  if (static_cast<int32_t>(local.size()) >= n) return;
  local.assign(n, -1);
  slot.assign(n, -1);
  queue.resize(n);
  mark.resize(n);
  refine.ext.resize(2 * static_cast<size_t>(n));
  refine.locked.assign(n, 0);

  for (int s = 0; s < 2; ++s) {
    refine.pos[s].assign(n, -1);
    refine.key[s].resize(n);
    refine.stored[s].resize(n);
  }
}

void induced_subgraph(const Graph& g, const std::vector<int32_t>& vertices, Workspace* ws, Graph* sub) {
  const int32_t m = static_cast<int32_t>(vertices.size());
  for (int32_t k = 0; k < m; ++k) ws->local[vertices[k]] = k;
  // One sweep of the lists, written into room for all of them (the arrays are
  // not zero-filled) and cut to size after.
  size_t bound = 0;
  for (int32_t v : vertices) bound += static_cast<size_t>(g.xadj[v + 1] - g.xadj[v]);
  const bool unit_edges = g.adjw.empty();
  sub->n = m;
  sub->xadj.resize(static_cast<size_t>(m) + 1);
  sub->adj.resize(bound);
  sub->adjw.resize(unit_edges ? 0 : bound);
  sub->vw.resize(static_cast<size_t>(m));
  sub->total_weight = 0;
  const int32_t* local = ws->local.data();
  int32_t* adj = sub->adj.data();
  int32_t q = 0;
  sub->xadj[0] = 0;
  for (int32_t k = 0; k < m; ++k) {
    const int32_t v = vertices[k];
    for (int32_t p = g.xadj[v]; p < g.xadj[v + 1]; ++p) {
      const int32_t u = local[g.adj[p]];
      if (!unit_edges) sub->adjw[q] = g.adjw[p];
      adj[q] = u;
      q += u >= 0;
    }
    sub->xadj[k + 1] = q;
    sub->vw[k] = g.vw[v];
    sub->total_weight += g.vw[v];
  }
  sub->adj.resize(static_cast<size_t>(q));
  if (!unit_edges) sub->adjw.resize(static_cast<size_t>(q));
  for (int32_t v : vertices) ws->local[v] = -1;
}

int32_t connected_components(const Graph& g, Workspace* ws, std::vector<int32_t>* component) {
  component->assign(static_cast<size_t>(g.n), -1);
  int32_t count = 0;
  for (int32_t root = 0; root < g.n; ++root) {
    if ((*component)[root] >= 0) continue;
    int32_t head = 0, tail = 0;
    ws->queue[tail++] = root;
    (*component)[root] = count;
    while (head < tail) {
      const int32_t v = ws->queue[head++];
      for (int32_t p = g.xadj[v]; p < g.xadj[v + 1]; ++p) {
        const int32_t u = g.adj[p];
        if ((*component)[u] >= 0) continue;
        (*component)[u] = count;
        ws->queue[tail++] = u;
      }
    }
    ++count;
  }
  return count;
}

}  // namespace nd
}  // namespace gab
