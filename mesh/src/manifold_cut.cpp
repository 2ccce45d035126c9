#include "gab/mesh/manifold_cut.h"

#include <algorithm>


namespace gab {

namespace {

// Glues the half-edges of every edge that exactly two triangles share in
// opposite directions. Half-edges are bucketed by their lower endpoint
// (counting sort, so each bucket lists its half-edges in increasing order),
// each stored with its higher endpoint so that the search within a bucket
// (a vertex's few edges) reads memory in order.
std::vector<int32_t> glue_edges(int32_t n, const std::vector<int32_t>& tri) {
  struct Entry {
    int32_t half, high;
  };
  const int32_t halves = static_cast<int32_t>(tri.size());
  std::vector<int32_t> start(static_cast<size_t>(n) + 2, 0);
  for (int32_t h = 0; h < halves; ++h) ++start[std::min(tri[h], tri[next_corner(h)]) + 2];
  for (int32_t v = 0; v < n; ++v) start[v + 2] += start[v + 1];
  // start[v + 1] is now bucket v's first slot; filling advances it to the
  // next bucket's, leaving start[v] = bucket v's first slot.
  std::vector<Entry> bucket(static_cast<size_t>(halves));
  for (int32_t h = 0; h < halves; ++h) {
    const int32_t a = tri[h], b = tri[next_corner(h)];
    bucket[start[std::min(a, b) + 1]++] = {h, std::max(a, b)};
  }

  std::vector<int32_t> opposite(static_cast<size_t>(halves), -1);
  for (int32_t v = 0; v < n; ++v) {
    const Entry* first = bucket.data() + start[v];
    const int32_t size = start[v + 1] - start[v];
    for (int32_t i = 0; i < size; ++i) {
      const int32_t h = first[i].half, high = first[i].high;
      if (opposite[h] != -1) continue;
      // Every half-edge of h's edge after h in the bucket (earlier ones
      // would have claimed h already).
      int32_t count = 1, other = -1;
      for (int32_t j = i + 1; j < size; ++j) {
        if (first[j].high == high) {
          ++count;
          other = first[j].half;
        }
      }
      if (count == 2 && tri[h] == tri[next_corner(other)]) {
        opposite[h] = other;
        opposite[other] = h;
      } else {
        // Cut: mark the whole edge so that its later half-edges skip it.
        for (int32_t j = i; j < size; ++j) {
          if (first[j].high == high) opposite[first[j].half] = -2;
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
  cut.triangles.reserve(3 * static_cast<size_t>(count));
  cut.source_triangle.reserve(static_cast<size_t>(count));
  for (int32_t t = 0; t < count; ++t) {
    const int32_t a = triangles[3 * t], b = triangles[3 * t + 1], c = triangles[3 * t + 2];
    const bool degenerate = a == b || b == c || a == c;
    std::vector<int32_t>& to = degenerate ? cut.degenerate : cut.triangles;
    to.insert(to.end(), {a, b, c});
    (degenerate ? cut.degenerate_source : cut.source_triangle).push_back(t);
  }
  cut.opposite = glue_edges(n, cut.triangles);

  // Fans: the corners around a vertex linked through glued edges, walked
  // from their first (smallest) corner: forward across each corner's
  // outgoing half-edge, then, if the fan is open, backward across its
  // incoming one. A vertex keeps its index for the fan met first; each
  // further fan gets a copy, in the order of the fans' first corners.
  const int32_t corners = static_cast<int32_t>(cut.triangles.size());
  std::vector<uint8_t> done(static_cast<size_t>(corners), 0), met(static_cast<size_t>(n), 0);
  cut.num_vertices = n;
  for (int32_t c = 0; c < corners; ++c) {
    if (done[c]) continue;
    const int32_t v = cut.triangles[c];
    int32_t id = v;
    if (met[v]) {
      id = cut.num_vertices++;
      cut.copy_of.push_back(v);
    }
    met[v] = 1;
    auto take = [&](int32_t d) {
      done[d] = 1;
      cut.triangles[d] = id;
    };
    take(c);
    int32_t d = c;
    bool closed = false;
    while (cut.opposite[d] >= 0) {
      d = next_corner(cut.opposite[d]);
      if (d == c) {
        closed = true;
        break;
      }
      take(d);
    }
    if (closed) continue;
    for (int32_t e = cut.opposite[prev_corner(c)]; e >= 0; e = cut.opposite[prev_corner(e)]) take(e);
  }
  return cut;
}

}  // namespace gab
