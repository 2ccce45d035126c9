// Separator of the coarsest graph by greedy graph growing (Karypis & Kumar
// 1998, sec. 4, "GGP"): grow a region breadth-first from a seed until it
// holds half the weight; the region's boundary facing the rest (or the rest's
// boundary facing the region, whichever weighs less) separates them; FM
// refinement then trims it. The coarsest graph has ~100 vertices, so several
// seeds are tried and the smallest balanced separators kept.
#include <algorithm>

#include "ordering/nested_dissection_graph.h"

namespace gab {
namespace nd {
namespace {

// Region grown from `seed` to half of g's weight: where[v] = kLeft inside,
// kRight outside. A region that runs out of reachable vertices restarts from
// the first vertex outside (g may be disconnected at this level).
void grow_region(const Graph& g, int32_t seed, Workspace* ws, std::vector<uint8_t>* where) {
  std::fill(where->begin(), where->end(), kRight);
  const int64_t half = g.total_weight / 2;
  int64_t grown = 0;
  int32_t head = 0, tail = 0, next_restart = 0;
  (*where)[seed] = kLeft;
  ws->queue[tail++] = seed;
  grown += g.vw[seed];
  while (grown < half) {
    if (head == tail) {
      while (next_restart < g.n && (*where)[next_restart] == kLeft) ++next_restart;
      if (next_restart == g.n) break;
      (*where)[next_restart] = kLeft;
      ws->queue[tail++] = next_restart;
      grown += g.vw[next_restart];
      continue;
    }
    const int32_t v = ws->queue[head++];
    for (int32_t p = g.xadj[v]; p < g.xadj[v + 1] && grown < half; ++p) {
      const int32_t u = g.adj[p];
      if ((*where)[u] == kLeft) continue;
      (*where)[u] = kLeft;
      ws->queue[tail++] = u;
      grown += g.vw[u];
    }
  }
}

// Turns the two-way split into a vertex separator: the lighter of the two
// boundaries (vertices with a neighbour on the other side) becomes it.
void boundary_to_separator(const Graph& g, std::vector<uint8_t>* where) {
  int64_t boundary_weight[2] = {0, 0};
  for (int32_t v = 0; v < g.n; ++v) {
    for (int32_t p = g.xadj[v]; p < g.xadj[v + 1]; ++p) {
      if ((*where)[g.adj[p]] != (*where)[v]) {
        boundary_weight[(*where)[v]] += g.vw[v];
        break;
      }
    }
  }
  const uint8_t side = boundary_weight[0] <= boundary_weight[1] ? kLeft : kRight;
  for (int32_t v = 0; v < g.n; ++v) {
    if ((*where)[v] != side) continue;
    for (int32_t p = g.xadj[v]; p < g.xadj[v + 1]; ++p) {
      if ((*where)[g.adj[p]] == 1 - side) {
        (*where)[v] = kSeparator;
        break;
      }
    }
  }
}

// A vertex far from `start`: the last one reached breadth-first (one sweep of
// the pseudo-peripheral search; its region grows across the graph).
int32_t far_vertex(const Graph& g, int32_t start, Workspace* ws) {
  std::vector<int32_t>& seen = ws->mark;
  std::fill(seen.begin(), seen.begin() + g.n, 0);
  int32_t head = 0, tail = 0;
  ws->queue[tail++] = start;
  seen[start] = 1;
  while (head < tail) {
    const int32_t v = ws->queue[head++];
    for (int32_t p = g.xadj[v]; p < g.xadj[v + 1]; ++p) {
      if (!seen[g.adj[p]]) {
        seen[g.adj[p]] = 1;
        ws->queue[tail++] = g.adj[p];
      }
    }
  }
  return ws->queue[tail - 1];
}

}  // namespace

void initial_separators(const Graph& g, const NestedDissectionOptions& params, int32_t tries, int32_t count,
                        Rng* rng, Workspace* ws, std::vector<std::vector<uint8_t>>* separators) {
  separators->clear();
  if (g.n < 2) {
    separators->emplace_back(static_cast<size_t>(g.n), kRight);
    return;
  }
  const int64_t max_side = max_side_weight(g, params.imbalance);
  // Each distinct refined trial with its cost (weight beyond the side bound,
  // separator weight) and try number, the tie-break: the earliest stays first.
  struct Trial {
    int64_t excess, separator;
    int32_t index;
  };
  std::vector<Trial> trials;
  std::vector<std::vector<uint8_t>> kept;
  std::vector<uint8_t> trial(static_cast<size_t>(g.n));
  tries = std::max(1, tries);
  for (int32_t t = 0; t < tries; ++t) {
    const int32_t seed = t == 0 ? far_vertex(g, 0, ws) : rng->below(g.n);
    grow_region(g, seed, ws, &trial);
    boundary_to_separator(g, &trial);
    refine_separator(g, params, ws, &trial);
    if (std::find(kept.begin(), kept.end(), trial) != kept.end()) continue;
    int64_t weight[3] = {0, 0, 0};
    for (int32_t v = 0; v < g.n; ++v) weight[trial[v]] += g.vw[v];
    const int64_t excess = std::max<int64_t>(0, std::max(weight[0], weight[1]) - max_side);
    trials.push_back({excess, weight[2], static_cast<int32_t>(kept.size())});
    kept.push_back(trial);
  }
  std::stable_sort(trials.begin(), trials.end(), [](const Trial& a, const Trial& b) {
    return a.excess != b.excess ? a.excess < b.excess : a.separator < b.separator;
  });
  const size_t wanted = std::min(trials.size(), static_cast<size_t>(std::max(1, count)));
  for (size_t k = 0; k < wanted; ++k) separators->push_back(std::move(kept[trials[k].index]));
}

}  // namespace nd
}  // namespace gab
