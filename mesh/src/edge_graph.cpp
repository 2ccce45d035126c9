#include "gab/mesh/edge_graph.h"

#include <algorithm>

namespace gab {

EdgeGraph build_edge_graph(const Mesh& mesh) { return build_edge_graph(mesh.num_vertices(), mesh.triangles); }

EdgeGraph build_edge_graph(int32_t num_vertices, const std::vector<int32_t>& triangles) {
  const int32_t n = num_vertices;
  const int32_t nt = static_cast<int32_t>(triangles.size() / 3);
  const int32_t* tri = triangles.data();
  EdgeGraph g;
  g.offsets.assign(n + 1, 0);
  // Each triangle offers each of its vertices two neighbours; count, fill,
  // then sort and deduplicate each vertex's list in place.
  for (int32_t t = 0; t < 3 * nt; ++t) g.offsets[tri[t] + 1] += 2;
  for (int32_t v = 0; v < n; ++v) g.offsets[v + 1] += g.offsets[v];
  std::vector<int32_t> cursor(g.offsets.begin(), g.offsets.end() - 1);
  std::vector<int32_t> raw(g.offsets[n]);
  for (int32_t t = 0; t < nt; ++t) {
    for (int c = 0; c < 3; ++c) {
      const int32_t v = tri[3 * t + c];
      raw[cursor[v]++] = tri[3 * t + (c + 1) % 3];
      raw[cursor[v]++] = tri[3 * t + (c + 2) % 3];
    }
  }
  g.neighbors.reserve(raw.size() / 2);
  std::vector<int32_t> offsets(n + 1, 0);
  for (int32_t v = 0; v < n; ++v) {
    auto begin = raw.begin() + g.offsets[v], end = raw.begin() + g.offsets[v + 1];
    if (end - begin <= 32) {
      // A usual list (twice the vertex's triangles): insertion sort, a few
      // times quicker than std::sort at this length.
      for (auto it = begin + (begin != end); it < end; ++it) {
        const int32_t x = *it;
        auto hole = it;
        for (; hole != begin && *(hole - 1) > x; --hole) *hole = *(hole - 1);
        *hole = x;
      }
    } else {
      std::sort(begin, end);
    }
    int32_t last = -1;
    for (auto it = begin; it != end; ++it) {
      if (*it != last && *it != v) g.neighbors.push_back(*it);
      last = *it;
    }
    offsets[v + 1] = static_cast<int32_t>(g.neighbors.size());
  }
  g.offsets = std::move(offsets);
  return g;
}

std::vector<int32_t> connected_components(const EdgeGraph& graph, int32_t* count) {
  const int32_t n = graph.num_vertices();
  std::vector<int32_t> comp(n, -1), queue;
  queue.reserve(n);
  int32_t c = 0;
  for (int32_t s = 0; s < n; ++s) {
    if (comp[s] != -1) continue;
    comp[s] = c;
    queue.clear();
    queue.push_back(s);
    for (size_t q = 0; q < queue.size(); ++q) {
      const int32_t v = queue[q];
      for (int32_t p = graph.offsets[v]; p < graph.offsets[v + 1]; ++p) {
        const int32_t u = graph.neighbors[p];
        if (comp[u] == -1) {
          comp[u] = c;
          queue.push_back(u);
        }
      }
    }
    ++c;
  }
  if (count != nullptr) *count = c;
  return comp;
}

}  // namespace gab
