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
#include "ordering/nested_dissection_graph.h"

namespace gab {
namespace nd {

void restrict_hierarchy(const Graph& g, const Hierarchy& h, const std::vector<int32_t>& vertices, int32_t target,
                        Workspace* ws, Hierarchy* part) {
  part->depth = 0;
  // source[i]: the vertex of h's level k (g for k = 0) that is vertex i of the
  // part's level k. Only the part's vertices and lists are read: O(its size).
  std::vector<int32_t>& source = ws->restrict_source[0];
  std::vector<int32_t>& next_source = ws->restrict_source[1];
  source.assign(vertices.begin(), vertices.end());
  std::vector<int32_t>& local = ws->local;  // -1 outside the level being built
  for (size_t k = 0; k < h.depth && static_cast<int32_t>(source.size()) > std::max(2, target); ++k) {
    const Graph& coarse = h.levels[k];
    const IntArray& map = h.maps[k];
    if (part->levels.size() == k) {  // before any reference into part->levels: this may move them
      part->levels.emplace_back();
      part->maps.emplace_back();
    }
    const IntArray& finer_vw = k == 0 ? g.vw : part->levels[k - 1].vw;
    Graph& level = part->levels[k];
    IntArray& part_map = part->maps[k];
    const int32_t finer_n = static_cast<int32_t>(source.size());
    part_map.resize(static_cast<size_t>(finer_n));
    level.vw.clear();
    next_source.clear();
    // The part's coarse vertices, numbered in order of their first fine
    // vertex (as coarsen numbers them), weighing what they hold of the part.
    for (int32_t i = 0; i < finer_n; ++i) {
      const int32_t c = map[source[i]];
      if (local[c] < 0) {
        local[c] = static_cast<int32_t>(next_source.size());
        next_source.push_back(c);
        level.vw.push_back(0);
      }
      level.vw[local[c]] += finer_vw[i];
      part_map[i] = local[c];
    }
    const int32_t n = static_cast<int32_t>(next_source.size());
    size_t bound = 0;
    for (int32_t c : next_source) bound += static_cast<size_t>(coarse.xadj[c + 1] - coarse.xadj[c]);
    level.n = n;
    level.xadj.resize(static_cast<size_t>(n) + 1);
    level.adj.resize(bound);
    level.adjw.resize(bound);
    level.total_weight = 0;
    int32_t* adj = level.adj.data();
    int32_t* adjw = level.adjw.data();
    const bool unit_edges = coarse.adjw.empty();
    int32_t q = 0;
    level.xadj[0] = 0;
    for (int32_t i = 0; i < n; ++i) {
      const int32_t c = next_source[i];
      for (int32_t p = coarse.xadj[c]; p < coarse.xadj[c + 1]; ++p) {
        const int32_t j = local[coarse.adj[p]];
        adj[q] = j;
        adjw[q] = unit_edges ? 1 : coarse.adjw[p];
        q += j >= 0;
      }
      level.xadj[i + 1] = q;
      level.total_weight += level.vw[i];
    }
    level.adj.resize(static_cast<size_t>(q));
    level.adjw.resize(static_cast<size_t>(q));
    for (int32_t c : next_source) local[c] = -1;
    part->depth = k + 1;
    source.swap(next_source);
  }
}

}  // namespace nd
}  // namespace gab
