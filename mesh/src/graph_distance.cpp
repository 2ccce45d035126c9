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
  GAB_RETURN_IF_ERROR(check_vertices(graph, seeds, "seed", true));
  if (count < 0) return Status::Error(StatusCode::kInvalidArgument, "negative sample count " + std::to_string(count));
  const int32_t n = graph.num_vertices();
  const int32_t kFar = INT32_MAX;  // not reachable from any chosen vertex
  std::vector<int32_t> dist(n, kFar), queue;
  // Heap of (distance, -vertex): the top is the farthest, smallest index
  // first. Entries go stale when a distance shrinks; they are skipped.
  std::vector<std::pair<int32_t, int32_t>> heap;
  heap.reserve(static_cast<size_t>(n) * 2);
  for (int32_t v = 0; v < n; ++v) heap.emplace_back(kFar, -v);
  std::make_heap(heap.begin(), heap.end());
  std::vector<int32_t> out;
  out.reserve(std::min(count, n));

  auto add = [&](int32_t s) {
    out.push_back(s);
    dist[s] = 0;
    queue.assign(1, s);
    for (size_t q = 0; q < queue.size(); ++q) {
      const int32_t v = queue[q];
      for (int32_t p = graph.offsets[v]; p < graph.offsets[v + 1]; ++p) {
        const int32_t u = graph.neighbors[p];
        if (dist[v] + 1 < dist[u]) {
          dist[u] = dist[v] + 1;
          queue.push_back(u);
          heap.emplace_back(dist[u], -u);
          std::push_heap(heap.begin(), heap.end());
        }
      }
    }
  };

  for (int32_t s : seeds) {
    if (static_cast<int32_t>(out.size()) >= count) break;
    add(s);
  }
  while (static_cast<int32_t>(out.size()) < count) {
    while (!heap.empty() && dist[-heap.front().second] != heap.front().first) {
      std::pop_heap(heap.begin(), heap.end());
      heap.pop_back();
    }
    if (heap.empty() || heap.front().first == 0) break;  // every vertex chosen
    const int32_t v = -heap.front().second;
    add(v);
  }
  *picked = std::move(out);
  return Status::Ok();
}

}  // namespace gab
