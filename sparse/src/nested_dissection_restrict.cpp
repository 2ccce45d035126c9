// A part's coarsening taken from its parent's instead of built afresh. Once a
// separator splits g, each side (and each connected component of a side) is
// dissected in turn, and coarsening it again by matching and contraction was
// most of the ordering's time. Its coarse graphs are instead read off g's: at
// each level, the coarse vertices holding at least one of the part's vertices,
// weighing what they hold of it, and g's coarse edges among them. A pass over
// each coarse level's lists replaces a matching and a contraction of every
// level; the matchings are those g's coarsening chose (heavy-edge matching is
// local: away from the separator, the part's own matching would look the same;
// Karypis & Kumar 1998, sec. 5, on how little the matching scheme moves the
// result).
//
// Coarse edges kept this way may stand only for edges to vertices outside the
// part (a coarse vertex cut by the separator): a superset of the part's coarse
// edges. A separator of a coarse level therefore still separates the part's
// vertices when projected down; only the edge weights the matching reads are
// approximate near the cut.
#include "nested_dissection_graph.h"

namespace gab {
namespace nd {

void restrict_hierarchy(const Graph& g, const Hierarchy& h, const std::vector<int32_t>& vertices, int32_t target,
                        Workspace* ws, Hierarchy* part) {
  part->depth = 0;
  int32_t finer_n = static_cast<int32_t>(vertices.size());
  // local[c]: c's index in the part's level (-1 outside); the previous level's in prev.
  std::vector<int32_t>& local = ws->restrict_local[0];
  std::vector<int32_t>& prev = ws->restrict_local[1];
  std::vector<int32_t>& weight = ws->restrict_weight;
  for (size_t k = 0; k < h.depth && finer_n > std::max(2, target); ++k) {
    const Graph& coarse = h.levels[k];
    const std::vector<int32_t>& map = h.maps[k];
    std::fill(weight.begin(), weight.begin() + coarse.n, 0);
    if (k == 0) {
      for (int32_t v : vertices) weight[map[v]] += g.vw[v];
    } else {
      const Graph& finer = part->levels[k - 1];
      for (int32_t c = 0; c < h.levels[k - 1].n; ++c) {
        if (prev[c] >= 0) weight[map[c]] += finer.vw[prev[c]];
      }
    }
    int32_t n = 0;
    for (int32_t c = 0; c < coarse.n; ++c) local[c] = weight[c] > 0 ? n++ : -1;

    if (part->levels.size() == k) {
      part->levels.emplace_back();
      part->maps.emplace_back();
    }
    Graph& level = part->levels[k];
    level.n = n;
    level.xadj.resize(static_cast<size_t>(n) + 1);
    level.adj.clear();
    level.adjw.clear();
    level.vw.resize(static_cast<size_t>(n));
    level.total_weight = 0;
    level.xadj[0] = 0;
    for (int32_t c = 0; c < coarse.n; ++c) {
      const int32_t i = local[c];
      if (i < 0) continue;
      for (int32_t p = coarse.xadj[c]; p < coarse.xadj[c + 1]; ++p) {
        const int32_t j = local[coarse.adj[p]];
        if (j < 0) continue;
        level.adj.push_back(j);
        level.adjw.push_back(coarse.adjw.empty() ? 1 : coarse.adjw[p]);
      }
      level.xadj[i + 1] = static_cast<int32_t>(level.adj.size());
      level.vw[i] = weight[c];
      level.total_weight += weight[c];
    }

    std::vector<int32_t>& part_map = part->maps[k];
    part_map.resize(static_cast<size_t>(finer_n));
    if (k == 0) {
      for (int32_t i = 0; i < finer_n; ++i) part_map[i] = local[map[vertices[i]]];
    } else {
      for (int32_t c = 0; c < h.levels[k - 1].n; ++c) {
        if (prev[c] >= 0) part_map[prev[c]] = local[map[c]];
      }
    }
    part->depth = k + 1;
    finer_n = n;
    local.swap(prev);
  }
}

}  // namespace nd
}  // namespace gab
