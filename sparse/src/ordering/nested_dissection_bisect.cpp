// One vertex separator by the multilevel scheme (Karypis & Kumar, "A fast and
// high quality multilevel scheme for partitioning irregular graphs", SIAM J.
// Sci. Comput. 20(1), 1998, sec. 2): coarsen by heavy-edge matching until the
// graph is small, separate the coarsest graph, then carry the separator back
// up level by level (a coarse vertex's side is both its fine vertices' side)
// and refine it at every level, where the finer graph has room to thin it.
//
// Which cut the coarsest graph picks (around which limb, along which axis)
// decides most of the final separator, and the coarsest graph's weights judge
// that choice poorly: several candidates are carried up to a middle level,
// small enough to be cheap and fine enough to judge by, and the best one goes
// on (the idea of METIS's multiple separators, Karypis & Kumar sec. 6).
#include <algorithm>

#include "ordering/nested_dissection_graph.h"

namespace gab {
namespace nd {
namespace {

// Coarsens g's hierarchy h further until its coarsest level has at most
// coarsest_size vertices (or matching stalls): levels[0 .. depth) are g's
// coarsenings, maps[k] takes level k-1 (g for k = 0) to level k.
void build_hierarchy(const Graph& g, const NestedDissectionOptions& params, Rng* rng, Workspace* ws, Hierarchy* hierarchy) {
  Hierarchy& h = *hierarchy;
  const int32_t target = std::max(2, params.coarsest_size);
  // Coarse vertices heavier than this could not sit on a side of a balanced split.
  const int64_t max_vertex_weight =
      std::max<int64_t>(1, static_cast<int64_t>(1.5 * static_cast<double>(g.total_weight) / target));
  for (;;) {
    const Graph& fine = h.depth == 0 ? g : h.levels[h.depth - 1];
    if (fine.n <= target) break;
    if (h.levels.size() == h.depth) {
      h.levels.emplace_back();
      h.maps.emplace_back();
    }
    // emplace_back may have moved the levels: take fine again.
    const Graph& finer = h.depth == 0 ? g : h.levels[h.depth - 1];
    Graph& coarse = h.levels[h.depth];
    coarsen(finer, max_vertex_weight, static_cast<size_t>(std::max<int64_t>(0, params.thread_entries)), rng, ws,
            &h.maps[h.depth], &coarse);
    // A matching that barely shrinks the graph (stars, heavy vertices) ends the coarsening.
    const bool stalled = coarse.n > finer.n - finer.n / 20;
    if (coarse.n == finer.n) break;
    ++h.depth;
    if (stalled) break;
  }
}

const Graph& level(const Graph& g, const Hierarchy& h, size_t k) { return k == 0 ? g : h.levels[k - 1]; }

// Projects `where` from level k + 1 to level k and refines it there, for
// k = from - 1 down to to (levels numbered as level()).
void uncoarsen(const Graph& g, const Hierarchy& h, size_t from, size_t to, const NestedDissectionOptions& params,
               Workspace* ws, std::vector<uint8_t>* where, std::vector<uint8_t>* scratch) {
  for (size_t k = from; k-- > to;) {
    const Graph& finer = level(g, h, k);
    const IntArray& map = h.maps[k];
    scratch->resize(static_cast<size_t>(finer.n));
    for (int32_t v = 0; v < finer.n; ++v) (*scratch)[v] = (*where)[map[v]];
    where->swap(*scratch);
    refine_separator(finer, params, ws, where);
  }
}

// Weight beyond the side bound, then separator weight: smaller is better.
std::pair<int64_t, int64_t> cost(const Graph& g, const NestedDissectionOptions& params, const std::vector<uint8_t>& where) {
  int64_t weight[3] = {0, 0, 0};
  for (int32_t v = 0; v < g.n; ++v) weight[where[v]] += g.vw[v];
  const int64_t excess = std::max<int64_t>(0, std::max(weight[0], weight[1]) - max_side_weight(g, params.imbalance));
  return {excess, weight[2]};
}

// The coarse levels below `mid`, moved out of a hierarchy (which keeps
// levels[0 .. mid)) so another coarsening can be tried in their place.
struct Tail {
  std::vector<Graph> levels;
  std::vector<IntArray> maps;
};

Tail take_tail(Hierarchy* h, size_t mid) {
  Tail tail;
  for (size_t k = mid; k < h->depth; ++k) {
    tail.levels.push_back(std::move(h->levels[k]));
    tail.maps.push_back(std::move(h->maps[k]));
  }
  h->depth = mid;
  return tail;
}

void put_tail(Hierarchy* h, size_t mid, Tail* tail) {
  const size_t depth = mid + tail->levels.size();
  if (h->levels.size() < depth) {
    h->levels.resize(depth);
    h->maps.resize(depth);
  }
  for (size_t k = 0; k < tail->levels.size(); ++k) {
    h->levels[mid + k] = std::move(tail->levels[k]);
    h->maps[mid + k] = std::move(tail->maps[k]);
  }
  h->depth = depth;
}

// A separator of level `top` of g's hierarchy h: initial separators of h's
// coarsest level, carried up to the judging level, the best of them carried
// on up to `top`.
void separate_from(const Graph& g, const Hierarchy& h, size_t top, const NestedDissectionOptions& params, Rng* rng,
                   Workspace* ws, std::vector<uint8_t>* where, std::vector<uint8_t>* scratch) {
  const size_t coarsest = h.depth;
  // The judging level: the finest with at most trial_size vertices.
  size_t judge = coarsest;
  while (judge > top && level(g, h, judge - 1).n <= params.trial_size) --judge;
  // Pieces already this small take their first candidate: their separators weigh little in the factor.
  const int32_t wanted = g.n >= params.large_size ? params.large_candidates : params.candidates;
  const int32_t candidates = judge > top && judge < coarsest ? std::max(1, wanted) : 1;

  // The candidates: the best distinct separators of candidate_tries tries
  // per candidate (one candidate: the best of initial_tries).
  std::vector<std::vector<uint8_t>> initial;
  const int32_t tries = candidates > 1 ? candidates * std::max(1, params.candidate_tries) : params.initial_tries;
  initial_separators(level(g, h, coarsest), params, tries, candidates, rng, ws, &initial);
  std::vector<uint8_t> best;
  std::pair<int64_t, int64_t> best_cost{-1, 0};
  for (std::vector<uint8_t>& candidate : initial) {
    uncoarsen(g, h, coarsest, judge, params, ws, &candidate, scratch);
    const std::pair<int64_t, int64_t> candidate_cost = cost(level(g, h, judge), params, candidate);
    if (best_cost.first < 0 || candidate_cost < best_cost) {
      best_cost = candidate_cost;
      best.swap(candidate);
    }
  }
  uncoarsen(g, h, judge, top, params, ws, &best, scratch);
  where->swap(best);
}

}  // namespace

void find_separator(const Graph& g, const NestedDissectionOptions& params, Rng* rng, Workspace* ws, Hierarchy* hierarchy,
                    std::vector<uint8_t>* where) {
  build_hierarchy(g, params, rng, ws, hierarchy);
  Hierarchy& h = *hierarchy;
  std::vector<uint8_t> scratch;
  // Large graphs: several coarsenings below a middle level, each separated
  // and refined up to it, the best carried on (METIS's scheme, Karypis &
  // Kumar sec. 6: the matchings differ, and with them the cuts the coarse
  // graphs can see).
  size_t mid = 0;
  if (params.runs > 1 && g.n >= params.runs_from) {
    const int32_t mid_size = std::max(params.coarsest_size, g.n / std::max(2, params.runs_ratio));
    while (mid < h.depth && mid < static_cast<size_t>(params.runs_levels) && level(g, h, mid).n > mid_size) ++mid;
  }
  if (mid == 0 || mid >= h.depth) {
    separate_from(g, h, 0, params, rng, ws, where, &scratch);
    return;
  }
  std::vector<uint8_t> best, run;
  separate_from(g, h, mid, params, rng, ws, &best, &scratch);
  std::pair<int64_t, int64_t> best_cost = cost(level(g, h, mid), params, best);
  Tail best_tail = take_tail(&h, mid);
  for (int32_t r = 1; r < params.runs; ++r) {
    build_hierarchy(g, params, rng, ws, &h);
    separate_from(g, h, mid, params, rng, ws, &run, &scratch);
    const std::pair<int64_t, int64_t> run_cost = cost(level(g, h, mid), params, run);
    if (run_cost < best_cost) {
      best_cost = run_cost;
      best.swap(run);
      best_tail = take_tail(&h, mid);
    } else {
      h.depth = mid;
    }
  }
  put_tail(&h, mid, &best_tail);
  uncoarsen(g, h, mid, 0, params, ws, &best, &scratch);
  where->swap(best);
}

}  // namespace nd
}  // namespace gab
