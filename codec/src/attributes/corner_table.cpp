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
  std::vector<int32_t> offsets(static_cast<size_t>(n) + 1, 0), edges;
  auto low = [&](int32_t c) { return std::min(triangles[c], triangles[CornerTable::next(c)]); };
  auto high = [&](int32_t c) { return std::max(triangles[c], triangles[CornerTable::next(c)]); };
  for (int32_t c = 0; c < corners; ++c) {
    if (triangles[c] != triangles[CornerTable::next(c)]) ++offsets[low(c) + 1];
  }
  for (int32_t v = 0; v < n; ++v) offsets[v + 1] += offsets[v];
  edges.resize(offsets[n]);
  {
    std::vector<int32_t> fill(offsets.begin(), offsets.end() - 1);
    for (int32_t c = 0; c < corners; ++c) {
      if (triangles[c] != triangles[CornerTable::next(c)]) edges[fill[low(c)]++] = c;
    }
  }
  for (int32_t v = 0; v < n; ++v) {
    const auto first = edges.begin() + offsets[v], last = edges.begin() + offsets[v + 1];
    std::sort(first, last, [&](int32_t a, int32_t b) { return high(a) != high(b) ? high(a) < high(b) : a < b; });
    for (auto run = first; run != last;) {
      auto end = run;
      while (end != last && high(*end) == high(*run)) ++end;
      if (end - run == 2) {
        const int32_t a = run[0], b = run[1];
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
