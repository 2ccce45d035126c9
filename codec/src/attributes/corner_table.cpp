#include "attributes/corner_table.h"

#include <algorithm>

namespace gab {

CornerTable build_corner_table(int32_t n, const std::vector<int32_t>& triangles) {
  CornerTable t;
  t.num_vertices = n;
  t.triangles = &triangles;
  const int32_t corners = static_cast<int32_t>(triangles.size());
  t.corner_offsets.assign(static_cast<size_t>(n) + 1, 0);
  for (int32_t v : triangles) ++t.corner_offsets[v + 1];
  for (int32_t v = 0; v < n; ++v) t.corner_offsets[v + 1] += t.corner_offsets[v];
  t.corners.resize(triangles.size());
  {
    std::vector<int32_t> fill(t.corner_offsets.begin(), t.corner_offsets.end() - 1);
    for (int32_t c = 0; c < corners; ++c) t.corners[fill[triangles[c]]++] = c;
  }
  // Corner c's edge runs from v = vertex(c) to w = vertex(next(c)). The
  // edges are grouped by their lower end (a counting sort), each group
  // sorted by the upper end: an edge held by exactly two corners, one each
  // way, joins them (the corner across c is at v in the other triangle:
  // next of the other corner). Non-manifold and boundary edges join none.
  // O(T log degree), whatever the degrees.
  t.across.assign(triangles.size(), -1);
  std::vector<int32_t> offsets(static_cast<size_t>(n) + 1, 0);
  for (int32_t c = 0; c < corners; ++c) {
    const int32_t v = triangles[c], w = triangles[CornerTable::next(c)];
    if (v != w) ++offsets[std::min(v, w) + 1];
  }
  for (int32_t v = 0; v < n; ++v) offsets[v + 1] += offsets[v];
  // Each entry: the upper end in the high half, the corner in the low one,
  // so a group sorts as plain integers.
  std::vector<uint64_t> edges(static_cast<size_t>(offsets[n]));
  {
    std::vector<int32_t> fill(offsets.begin(), offsets.end() - 1);
    for (int32_t c = 0; c < corners; ++c) {
      const int32_t v = triangles[c], w = triangles[CornerTable::next(c)];
      if (v == w) continue;
      edges[fill[std::min(v, w)]++] = (static_cast<uint64_t>(std::max(v, w)) << 32) | static_cast<uint32_t>(c);
    }
  }
  for (int32_t v = 0; v < n; ++v) {
    const auto first = edges.begin() + offsets[v], last = edges.begin() + offsets[v + 1];
    std::sort(first, last);
    for (auto run = first; run != last;) {
      auto end = run;
      while (end != last && (*end >> 32) == (*run >> 32)) ++end;
      if (end - run == 2) {
        const int32_t a = static_cast<int32_t>(run[0] & 0xFFFFFFFFu), b = static_cast<int32_t>(run[1] & 0xFFFFFFFFu);
        if (triangles[a] != triangles[b]) {  // one each way
          t.across[a] = CornerTable::next(b);
          t.across[b] = CornerTable::next(a);
        }
      }
      run = end;
    }
  }
  t.rank.assign(n, -1);
  t.visit.reserve(n);
  for (int32_t v : triangles) {
    if (t.rank[v] < 0) {
      t.rank[v] = static_cast<int32_t>(t.visit.size());
      t.visit.push_back(v);
    }
  }
  for (int32_t v = 0; v < n; ++v) {
    if (t.rank[v] < 0) {
      t.rank[v] = static_cast<int32_t>(t.visit.size());
      t.visit.push_back(v);
    }
  }
  return t;
}

}  // namespace gab
