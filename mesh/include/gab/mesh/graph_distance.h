// Hop distances on the edge graph, and farthest-point sampling with them
// (the "well-spread" initial anchors of Sorkine et al. 2005's anchor selection).
#pragma once

#include <cstdint>
#include <vector>

#include "gab/mesh/edge_graph.h"
#include "gab/status.h"

namespace gab {

// Hops from the nearest of `sources` (multi-source BFS) for every vertex; -1
// where no source is reachable. Sources must be in range (repeats allowed).
// O(V + E).
Status bfs_distances(const EdgeGraph& graph, const std::vector<int32_t>& sources, std::vector<int32_t>* distance);

// Farthest-point sampling in hops. Starts from `seeds` (distinct, in range),
// then repeatedly adds the vertex farthest from all chosen so far, ties going
// to the smallest vertex index. A vertex in a component with nothing chosen
// is infinitely far, so every component gets a vertex (its smallest) before
// any is refined; with no seeds the first pick is vertex 0. Stops at `count`
// vertices in all or when every vertex is chosen. `picked` = seeds, then
// picks in order. Deterministic. O(V + E) per pick in the worst case (each
// pick re-runs BFS only where distances shrink) plus a sort of each
// distance's entries (one per distance change).
Status farthest_point_sampling(const EdgeGraph& graph, int32_t count, const std::vector<int32_t>& seeds,
                               std::vector<int32_t>* picked);
// The same with the picks made among `candidates` alone (distinct, in
// range; null: every vertex), distances still from every chosen vertex: a
// candidate that is a seed is never picked again, and the picks stop when
// the candidates run out.
Status farthest_point_sampling(const EdgeGraph& graph, int32_t count, const std::vector<int32_t>& seeds,
                               const std::vector<int32_t>* candidates, std::vector<int32_t>* picked);

}  // namespace gab
