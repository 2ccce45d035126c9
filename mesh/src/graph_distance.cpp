// BFS hop distances and farthest-point sampling on the edge graph.
// Farthest-point sampling is the greedy k-center heuristic (Gonzalez 1985)
// with hop distance: after each pick a BFS from the new vertex lowers the
// distance field only where it shrinks (unit edge lengths make a FIFO order
// from one source exact), and a lazy max-heap finds the farthest vertex.
#include "gab/mesh/graph_distance.h"

#include <algorithm>
#include <string>
#include <utility>

namespace gab {

namespace {

Status check_vertices(const EdgeGraph& graph, const std::vector<int32_t>& vertices, const char* what, bool distinct) {
  const int32_t n = graph.num_vertices();
  std::vector<char> seen(distinct ? n : 0, 0);
  for (int32_t v : vertices) {
    if (v < 0 || v >= n) {
      return Status::Error(StatusCode::kInvalidArgument, std::string(what) + " " + std::to_string(v) +
                                                             " is not a vertex (n = " + std::to_string(n) + ")");
    }
    if (distinct) {
      if (seen[v]) return Status::Error(StatusCode::kInvalidArgument, std::string(what) + " " + std::to_string(v) + " given twice");
      seen[v] = 1;
    }
  }
  return Status::Ok();
}

}  // namespace

Status bfs_distances(const EdgeGraph& graph, const std::vector<int32_t>& sources, std::vector<int32_t>* distance) {
  GAB_RETURN_IF_ERROR(check_vertices(graph, sources, "source", false));
  const int32_t n = graph.num_vertices();
  std::vector<int32_t> dist(n, -1), queue;
  queue.reserve(n);
  for (int32_t s : sources) {
    if (dist[s] == -1) {
      dist[s] = 0;
      queue.push_back(s);
    }
  }
  for (size_t q = 0; q < queue.size(); ++q) {
    const int32_t v = queue[q];
    for (int32_t p = graph.offsets[v]; p < graph.offsets[v + 1]; ++p) {
      const int32_t u = graph.neighbors[p];
      if (dist[u] == -1) {
        dist[u] = dist[v] + 1;
        queue.push_back(u);
      }
    }
  }
  *distance = std::move(dist);
  return Status::Ok();
}

Status farthest_point_sampling(const EdgeGraph& graph, int32_t count, const std::vector<int32_t>& seeds,
                               std::vector<int32_t>* picked) {
  return farthest_point_sampling(graph, count, seeds, nullptr, picked);
}

Status farthest_point_sampling(const EdgeGraph& graph, int32_t count, const std::vector<int32_t>& seeds,
                               const std::vector<int32_t>* candidates, std::vector<int32_t>* picked) {
  GAB_RETURN_IF_ERROR(check_vertices(graph, seeds, "seed", true));
  if (candidates) GAB_RETURN_IF_ERROR(check_vertices(graph, *candidates, "candidate", true));
  if (count < 0) return Status::Error(StatusCode::kInvalidArgument, "negative sample count " + std::to_string(count));
  const int32_t n = graph.num_vertices();
  const int32_t kFar = INT32_MAX;  // not reachable from any chosen vertex
  std::vector<char> candidate(n, candidates ? 0 : 1);
  if (candidates) {
    for (int32_t v : *candidates) candidate[v] = 1;
  }
  std::vector<int32_t> dist(n, kFar), queue;
  // A bucket per distance, and the unreached (every candidate at first, in
  // increasing index: taken first), each taken in increasing vertex index
  // once it is the farthest left: the farthest first, ties to the smaller
  // index. Past the unreached a pick only brings vertices closer than the
  // farthest, so a bucket being taken gets no new entries. An entry goes
  // stale when its vertex comes closer (a fresh one is put in a lower
  // bucket); stale ones are skipped. Sorting a bucket once costs far less
  // than a heap's work per entry.
  std::vector<std::vector<int32_t>> buckets;
  std::vector<int32_t> out;
  out.reserve(std::min(count, n));

  // Breadth-first from the queue's vertices (at distance 0), only where it
  // brings a vertex closer; first-in first-out visits in order of distance,
  // so each vertex settles at its new distance when first reached.
  auto spread_from_queue = [&]() {
    for (size_t q = 0; q < queue.size(); ++q) {
      const int32_t v = queue[q];
      for (int32_t p = graph.offsets[v]; p < graph.offsets[v + 1]; ++p) {
        const int32_t u = graph.neighbors[p];
        if (dist[v] + 1 < dist[u]) {
          dist[u] = dist[v] + 1;
          queue.push_back(u);
          if (!candidate[u]) continue;
          if (static_cast<size_t>(dist[u]) >= buckets.size()) buckets.resize(static_cast<size_t>(dist[u]) + 1);
          buckets[dist[u]].push_back(u);
        }
      }
    }
  };
  auto add = [&](int32_t s) {
    out.push_back(s);
    dist[s] = 0;
    queue.assign(1, s);
    spread_from_queue();
  };
  auto full = [&]() { return static_cast<int32_t>(out.size()) >= count; };

  // The seeds (as many as count allows) at once: one search from all of them.
  queue.clear();
  for (size_t i = 0; i < seeds.size() && !full(); ++i) {
    out.push_back(seeds[i]);
    dist[seeds[i]] = 0;
    queue.push_back(seeds[i]);
  }
  spread_from_queue();
  for (int32_t v = 0; v < n && !full(); ++v) {
    if (candidate[v] && dist[v] == kFar) add(v);  // the smallest of a component nothing reaches yet
  }
  // Distance 0 is a chosen vertex: every candidate is then chosen.
  for (size_t d = buckets.size(); d-- > 1 && !full();) {
    std::vector<int32_t>& bucket = buckets[d];
    std::sort(bucket.begin(), bucket.end());
    for (size_t i = 0; i < bucket.size() && !full(); ++i) {
      if (dist[bucket[i]] == static_cast<int32_t>(d)) add(bucket[i]);  // puts go below d: no reallocation
    }
    std::vector<int32_t>().swap(bucket);
  }
  *picked = std::move(out);
  return Status::Ok();
}

}  // namespace gab
