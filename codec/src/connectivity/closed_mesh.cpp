// A manifold cut closed for the valence coder: one dummy vertex per
// boundary loop, and the count of connected components.
#include "connectivity/closed_mesh.h"

#include <algorithm>

namespace gab {

int32_t count_components(const ClosedMesh& mesh) {
  const int32_t count = static_cast<int32_t>(mesh.triangles.size() / 3);
  int32_t components = 0;
  std::vector<uint8_t> seen(static_cast<size_t>(count), 0);
  std::vector<int32_t> queue;
  for (int32_t t = 0; t < count; ++t) {
    if (seen[t]) continue;
    ++components;
    seen[t] = 1;
    queue.assign(1, t);
    while (!queue.empty()) {
      const int32_t u = queue.back();
      queue.pop_back();
      for (int i = 0; i < 3; ++i) {
        const int32_t o = mesh.opposite[3 * u + i] / 3;
        if (!seen[o]) {
          seen[o] = 1;
          queue.push_back(o);
        }
      }
    }
  }
  return components;
}

namespace {

// Closes a cut's triangles and opposites (already in `closed`, over
// closed->num_vertices vertices) in place: a boundary half-edge is one
// whose opposite is still -1 (the loops already closed have theirs set).
void close_loops(ClosedMesh* closed) {
  const int32_t cut_vertices = closed->num_vertices;
  const int32_t halves = static_cast<int32_t>(closed->triangles.size());
  std::vector<int32_t>& tri = closed->triangles;
  std::vector<int32_t>& opposite = closed->opposite;
  // Each cut vertex is one fan, so a boundary vertex has exactly one
  // outgoing boundary half-edge: the loop continues from there.
  std::vector<int32_t> leaving(static_cast<size_t>(cut_vertices), -1);
  for (int32_t h = 0; h < halves; ++h) {
    if (opposite[h] < 0) leaving[tri[h]] = h;
  }
  for (int32_t start = 0; start < halves; ++start) {
    if (opposite[start] >= 0) continue;
    const int32_t d = closed->num_vertices++;
    // One triangle (b, a, d) per boundary half-edge a -> b, glued to it and
    // to its neighbours in the loop.
    const int32_t first = static_cast<int32_t>(tri.size());
    int32_t h = start, previous = -1;
    do {
      const int32_t a = tri[h], b = tri[next_corner(h)];
      const int32_t t = static_cast<int32_t>(tri.size());
      tri.insert(tri.end(), {b, a, d});
      opposite.insert(opposite.end(), {h, -1, -1});
      opposite[h] = t;
      if (previous >= 0) {  // previous: (a, z, d); its d -> a meets our a -> d
        opposite[previous + 2] = t + 1;
        opposite[t + 1] = previous + 2;
      }
      previous = t;
      h = leaving[b];
    } while (h != start);
    opposite[previous + 2] = first + 1;
    opposite[first + 1] = previous + 2;
  }
  closed->dummy.assign(static_cast<size_t>(closed->num_vertices), 0);
  std::fill(closed->dummy.begin() + cut_vertices, closed->dummy.end(), 1);
}

}  // namespace

ClosedMesh close_boundaries(const ManifoldCut& cut) {
  ClosedMesh closed;
  closed.num_vertices = cut.num_vertices;
  closed.triangles = cut.triangles;
  closed.opposite = cut.opposite;
  close_loops(&closed);
  return closed;
}

ClosedMesh close_boundaries(ManifoldCut* cut) {
  ClosedMesh closed;
  closed.num_vertices = cut->num_vertices;
  closed.triangles.swap(cut->triangles);
  closed.opposite.swap(cut->opposite);
  close_loops(&closed);
  return closed;
}

}  // namespace gab
