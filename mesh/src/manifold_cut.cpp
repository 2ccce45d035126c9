#include "gab/mesh/manifold_cut.h"

#include <algorithm>

#include "gab/sparse/disjoint_set.h"

namespace gab {

namespace {

// Glues the half-edges of every edge that exactly two triangles share in
// opposite directions. Half-edges are bucketed by their lower endpoint
// (counting sort); a bucket holds a vertex's few edges, searched linearly.
std::vector<int32_t> glue_edges(int32_t n, const std::vector<int32_t>& tri) {
  const int32_t halves = static_cast<int32_t>(tri.size());
  std::vector<int32_t> start(static_cast<size_t>(n) + 1, 0);
  auto low = [&](int32_t h) { return std::min(tri[h], tri[next_corner(h)]); };
  auto high = [&](int32_t h) { return std::max(tri[h], tri[next_corner(h)]); };
  for (int32_t h = 0; h < halves; ++h) ++start[low(h) + 1];
  for (int32_t v = 0; v < n; ++v) start[v + 1] += start[v];
  std::vector<int32_t> bucket(static_cast<size_t>(halves));
  std::vector<int32_t> fill(start.begin(), start.end() - 1);
  for (int32_t h = 0; h < halves; ++h) bucket[fill[low(h)]++] = h;

  std::vector<int32_t> opposite(static_cast<size_t>(halves), -1);
  for (int32_t v = 0; v < n; ++v) {
    const int32_t* first = bucket.data() + start[v];
    const int32_t size = start[v + 1] - start[v];
    for (int32_t i = 0; i < size; ++i) {
      const int32_t h = first[i];
      if (opposite[h] != -1) continue;
      // Every half-edge of h's edge after h in the bucket (earlier ones
      // would have claimed h already).
      int32_t count = 1, other = -1;
      for (int32_t j = i + 1; j < size; ++j) {
        if (high(first[j]) == high(h)) {
          ++count;
          other = first[j];
        }
      }
      if (count == 2 && tri[h] == tri[next_corner(other)]) {
        opposite[h] = other;
        opposite[other] = h;
      } else {
        // Cut: mark the whole edge so that its later half-edges skip it.
        for (int32_t j = i; j < size; ++j) {
          if (high(first[j]) == high(h)) opposite[first[j]] = -2;
        }
      }
    }
  }
  for (int32_t& o : opposite) o = std::max(o, -1);
  return opposite;
}

}  // namespace

ManifoldCut cut_to_manifold(int32_t n, const std::vector<int32_t>& triangles) {
  ManifoldCut cut;
  const int32_t count = static_cast<int32_t>(triangles.size() / 3);
  for (int32_t t = 0; t < count; ++t) {
    const int32_t a = triangles[3 * t], b = triangles[3 * t + 1], c = triangles[3 * t + 2];
    const bool degenerate = a == b || b == c || a == c;
    std::vector<int32_t>& to = degenerate ? cut.degenerate : cut.triangles;
    to.insert(to.end(), {a, b, c});
    (degenerate ? cut.degenerate_source : cut.source_triangle).push_back(t);
  }
  cut.opposite = glue_edges(n, cut.triangles);

  // Fans: corner c and the corner of the same vertex across c's outgoing
  // half-edge, next(opposite[c]), lie in one fan.
  const int32_t corners = static_cast<int32_t>(cut.triangles.size());
  std::vector<int32_t> fan(static_cast<size_t>(corners));
  for (int32_t c = 0; c < corners; ++c) fan[c] = c;
  for (int32_t c = 0; c < corners; ++c) {
    if (cut.opposite[c] < 0) continue;
    const int32_t a = find_set_root(&fan, c), b = find_set_root(&fan, next_corner(cut.opposite[c]));
    if (a != b) fan[std::max(a, b)] = std::min(a, b);  // the root is the fan's first corner
  }
  // A vertex keeps its index for the fan met first; each further fan gets
  // a copy. vertex_of_fan is indexed by the fan's root corner.
  std::vector<int32_t> first_fan(static_cast<size_t>(n), -1);
  std::vector<int32_t> vertex_of_fan(static_cast<size_t>(corners), -1);
  cut.num_vertices = n;
  for (int32_t c = 0; c < corners; ++c) {
    const int32_t root = find_set_root(&fan, c);
    if (vertex_of_fan[root] < 0) {
      const int32_t v = cut.triangles[c];
      if (first_fan[v] < 0) {
        first_fan[v] = root;
        vertex_of_fan[root] = v;
      } else {
        vertex_of_fan[root] = cut.num_vertices++;
        cut.copy_of.push_back(v);
      }
    }
    cut.triangles[c] = vertex_of_fan[root];
  }
  return cut;
}

}  // namespace gab
