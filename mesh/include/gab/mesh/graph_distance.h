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

// farthest_point_sampling taken a few picks at a time: the same picks in
// the same order, so a caller can use the first ones while the rest are
// made (a decoder's first levels while a second thread picks on). One
// object per run; next() from one thread at a time.
class FarthestPointSampler {
 public:
  // Checks as farthest_point_sampling does and searches from the seeds;
  // `graph` (and `candidates`, null: every vertex) must outlive the sampler.
  Status start(const EdgeGraph& graph, const std::vector<int32_t>& seeds, const std::vector<int32_t>* candidates);
  // Appends up to `count` more picks to *picked, the seeds first (fewer once
  // every candidate is chosen); how many it appended.
  int32_t next(int32_t count, std::vector<int32_t>* picked);

  // Per vertex, its nearest chosen vertex so far (seeds and picks): the
  // fewest hops, ties to the lowest vertex index, as (hops << 32) | vertex
  // (kUnreached where none reaches): IterativeReconstruction's
  // kFewestHopsLowest rule, which it can take from here (its add_anchors).
  static constexpr uint64_t kUnreached = UINT64_MAX;
  const std::vector<uint64_t>& nearest() const { return nearest_; }

 private:
  void add(int32_t s);
  // Breadth-first from queue_'s vertices, only where it brings a vertex closer.
  void spread_from_queue();

  const EdgeGraph* graph_ = nullptr;
  std::vector<char> candidate_;
  std::vector<uint64_t> nearest_;
  std::vector<int32_t> queue_;
  std::vector<std::vector<int32_t>> buckets_;
  std::vector<int32_t> seeds_;
  size_t seeds_out_ = 0;
  // Where the picks go on: the scan for unreached components (at vertex
  // scan_), then the buckets from the farthest (bucket_, entry entry_).
  int32_t scan_ = 0;
  size_t bucket_ = 0, entry_ = 0;
  bool buckets_started_ = false, bucket_sorted_ = false;
};

}  // namespace gab
