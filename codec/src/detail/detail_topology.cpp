#include "detail/detail_topology.h"

#include <algorithm>

namespace gab {

namespace {

// The third vertex of triangle t other than a and b, or -1 (degenerate).
int32_t third_vertex(const std::vector<int32_t>& triangles, int32_t t, int32_t a, int32_t b) {
  int32_t found = -1;
  bool has_a = false, has_b = false;
  for (int k = 0; k < 3; ++k) {
    const int32_t w = triangles[3 * static_cast<size_t>(t) + k];
    if (w == a && !has_a) {
      has_a = true;
    } else if (w == b && !has_b) {
      has_b = true;
    } else {
      found = w;
    }
  }
  return has_a && has_b && found != a && found != b ? found : -1;
}

// Maximum cardinality search: per count of decoded neighbours a FIFO of
// candidates, stale entries (visited, or since counted higher) skipped.
std::vector<int32_t> cardinality_order(const EdgeGraph& graph) {
  const int32_t n = graph.num_vertices();
  std::vector<int32_t> order, count(static_cast<size_t>(n), 0);
  order.reserve(static_cast<size_t>(n));
  std::vector<char> visited(static_cast<size_t>(n), 0);
  std::vector<std::vector<int32_t>> queues(1);
  std::vector<size_t> heads(1, 0);
  int32_t top = -1, seed = 0;
  while (static_cast<int32_t>(order.size()) < n) {
    int32_t v = -1;
    while (top >= 0 && v < 0) {
      std::vector<int32_t>& q = queues[top];
      while (heads[top] < q.size()) {
        const int32_t u = q[heads[top]++];
        if (!visited[u] && count[u] == top) {
          v = u;
          break;
        }
      }
      if (v < 0) --top;
    }
    if (v < 0) {
      while (visited[seed]) ++seed;
      v = seed;
    }
    visited[v] = 1;
    order.push_back(v);
    for (int32_t p = graph.offsets[v]; p < graph.offsets[v + 1]; ++p) {
      const int32_t u = graph.neighbors[p];
      if (visited[u]) continue;
      const int32_t c = ++count[u];
      if (static_cast<int32_t>(queues.size()) <= c) {
        queues.resize(static_cast<size_t>(c) + 1);
        heads.resize(static_cast<size_t>(c) + 1, 0);
      }
      queues[c].push_back(u);
      top = std::max(top, c);
    }
  }
  return order;
}

}  // namespace

DetailTopology build_detail_topology(int32_t num_vertices, const std::vector<int32_t>& triangles,
                                     const EdgeGraph& graph) {
  DetailTopology topo;
  topo.num_vertices = num_vertices;
  topo.triangles = &triangles;
  topo.order = cardinality_order(graph);
  const int32_t num_triangles = static_cast<int32_t>(triangles.size() / 3);

  // Incident triangles, each listed once per vertex (a degenerate triangle
  // repeats a vertex: listed once there too).
  std::vector<int32_t> offsets(static_cast<size_t>(num_vertices) + 1, 0), incident;
  auto for_corners = [&](auto&& visit) {
    for (int32_t t = 0; t < num_triangles; ++t) {
      for (int k = 0; k < 3; ++k) {
        const int32_t v = triangles[3 * static_cast<size_t>(t) + k];
        bool repeated = false;
        for (int j = 0; j < k; ++j) repeated |= triangles[3 * static_cast<size_t>(t) + j] == v;
        if (!repeated) visit(v, t);
      }
    }
  };
  for_corners([&](int32_t v, int32_t) { ++offsets[v + 1]; });
  for (int32_t v = 0; v < num_vertices; ++v) offsets[v + 1] += offsets[v];
  incident.assign(static_cast<size_t>(offsets[num_vertices]), 0);
  std::vector<int32_t> fill(offsets.begin(), offsets.end() - 1);
  for_corners([&](int32_t v, int32_t t) { incident[fill[v]++] = t; });

  // What each step finds decoded.
  std::vector<int32_t> position(static_cast<size_t>(num_vertices), -1);  // step of a decoded vertex
  topo.parallelogram_offsets.assign(1, 0);
  topo.known_offsets.assign(1, 0);
  for (size_t i = 0; i < topo.order.size(); ++i) {
    const int32_t v = topo.order[i];
    const size_t begin = topo.parallelograms.size();
    int32_t count = 0, earliest = 0;
    for (int32_t p = offsets[v]; p < offsets[v + 1]; ++p) {
      const int32_t t = incident[p];
      const size_t t3 = 3 * static_cast<size_t>(t);
      int k = 0;
      while (k < 3 && triangles[t3 + k] != v) ++k;
      const int32_t a = triangles[t3 + (k + 1) % 3], b = triangles[t3 + (k + 2) % 3];
      if (a == v || b == v || a == b || position[a] < 0 || position[b] < 0) continue;
      for (int32_t q = offsets[a]; q < offsets[a + 1] && count < kMaxParallelograms; ++q) {
        const int32_t other = incident[q];
        if (other == t) continue;
        const int32_t c = third_vertex(triangles, other, a, b);
        if (c < 0 || c == v || position[c] < 0) continue;
        const int32_t key = std::min(position[a], position[b]);
        if (count == 0 || key < earliest) {
          earliest = key;
          // The new earliest goes first; the one it displaces moves to the end.
          topo.parallelograms.insert(topo.parallelograms.end(), {a, b, c});
          std::swap_ranges(topo.parallelograms.begin() + begin, topo.parallelograms.begin() + begin + 3,
                           topo.parallelograms.end() - 3);
        } else {
          topo.parallelograms.insert(topo.parallelograms.end(), {a, b, c});
        }
        ++count;
      }
    }
    topo.parallelogram_offsets.push_back(static_cast<int32_t>(topo.parallelograms.size() / 3));
    for (int32_t p = graph.offsets[v]; p < graph.offsets[v + 1]; ++p) {
      if (position[graph.neighbors[p]] >= 0) topo.known.push_back(graph.neighbors[p]);
    }
    topo.known_offsets.push_back(static_cast<int32_t>(topo.known.size()));
    position[v] = static_cast<int32_t>(i);
  }
  return topo;
}

}  // namespace gab
