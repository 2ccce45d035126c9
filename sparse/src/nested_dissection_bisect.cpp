// One vertex separator by the multilevel scheme (Karypis & Kumar, "A fast and
// high quality multilevel scheme for partitioning irregular graphs", SIAM J.
// Sci. Comput. 20(1), 1998, sec. 2): coarsen by heavy-edge matching until the
// graph is small, separate the coarsest graph, then carry the separator back
// up level by level (a coarse vertex's side is both its fine vertices' side)
// and refine it at every level, where the finer graph has room to thin it.
#include <algorithm>

#include "nested_dissection_graph.h"

namespace gab {
namespace nd {

void find_separator(const Graph& g, const BisectParams& params, Rng* rng, Workspace* ws,
                    std::vector<uint8_t>* where) {
  // levels[0] is g's first coarsening; maps[k] takes level k-1 (g for k = 0) to level k.
  std::vector<Graph> levels;
  std::vector<std::vector<int32_t>> maps;
  const int32_t target = std::max(2, params.coarsest_size);
  // Coarse vertices heavier than this could not sit on a side of a balanced split.
  const int64_t max_vertex_weight =
      std::max<int64_t>(1, static_cast<int64_t>(1.5 * static_cast<double>(g.total_weight) / target));
  const Graph* fine = &g;
  while (fine->n > target) {
    Graph coarse;
    std::vector<int32_t> map;
    coarsen(*fine, max_vertex_weight, rng, ws, &map, &coarse);
    // A matching that barely shrinks the graph (stars, heavy vertices) ends the coarsening.
    const bool stalled = coarse.n > fine->n - fine->n / 20;
    if (coarse.n == fine->n) break;
    levels.push_back(std::move(coarse));
    maps.push_back(std::move(map));
    fine = &levels.back();
    if (stalled) break;
  }

  initial_separator(*fine, params, rng, ws, where);
  std::vector<uint8_t> finer;
  for (size_t k = levels.size(); k-- > 0;) {
    const Graph& target_graph = k == 0 ? g : levels[k - 1];
    const std::vector<int32_t>& map = maps[k];
    finer.resize(static_cast<size_t>(target_graph.n));
    for (int32_t v = 0; v < target_graph.n; ++v) finer[v] = (*where)[map[v]];
    where->swap(finer);
    refine_separator(target_graph, params, where);
  }
}

}  // namespace nd
}  // namespace gab
