#include "gab/mesh/weld.h"

#include <algorithm>
#include <numeric>

namespace gab {

int32_t weld_coincident_vertices(const Mesh& mesh, Mesh* welded, std::vector<int32_t>* new_index) {
  const int32_t n = mesh.num_vertices();
  const double* p = mesh.positions.data();
  auto less = [p](int32_t a, int32_t b) {
    for (int c = 0; c < 3; ++c) {
      if (p[3 * static_cast<size_t>(a) + c] != p[3 * static_cast<size_t>(b) + c]) {
        return p[3 * static_cast<size_t>(a) + c] < p[3 * static_cast<size_t>(b) + c];
      }
    }
    return a < b;
  };
  auto same = [p](int32_t a, int32_t b) {
    return p[3 * static_cast<size_t>(a)] == p[3 * static_cast<size_t>(b)] &&
           p[3 * static_cast<size_t>(a) + 1] == p[3 * static_cast<size_t>(b) + 1] &&
           p[3 * static_cast<size_t>(a) + 2] == p[3 * static_cast<size_t>(b) + 2];
  };
  std::vector<int32_t> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), less);
  // Each vertex's first copy (the smallest index of its group).
  std::vector<int32_t> first(n);
  int32_t removed = 0;
  for (int32_t i = 0; i < n; ++i) {
    const bool joins = i > 0 && same(order[i - 1], order[i]);
    first[order[i]] = joins ? first[order[i - 1]] : order[i];
    removed += joins ? 1 : 0;
  }
  if (removed == 0) return 0;
  bool per_vertex = false;
  for (const MeshAttribute& a : mesh.attributes) per_vertex = per_vertex || !a.per_corner();
  if (per_vertex) {
    std::vector<char> used(n, 0);
    for (int32_t v : mesh.triangles) used[v] = 1;
    if (std::find(used.begin(), used.end(), 0) != used.end()) return 0;
  }

  new_index->assign(n, -1);
  int32_t next = 0;
  for (int32_t v = 0; v < n; ++v) {
    if (first[v] == v) (*new_index)[v] = next++;
  }
  for (int32_t v = 0; v < n; ++v) (*new_index)[v] = (*new_index)[first[v]];
  Mesh out;
  out.positions.resize(3 * static_cast<size_t>(next));
  for (int32_t v = 0; v < n; ++v) {
    if (first[v] != v) continue;
    std::copy(p + 3 * static_cast<size_t>(v), p + 3 * static_cast<size_t>(v) + 3,
              out.positions.begin() + 3 * static_cast<std::ptrdiff_t>((*new_index)[v]));
  }
  out.triangles.reserve(mesh.triangles.size());
  for (int32_t v : mesh.triangles) out.triangles.push_back((*new_index)[v]);
  out.attributes = mesh.attributes;
  for (MeshAttribute& a : out.attributes) {
    if (!a.per_corner()) a.corners = mesh.triangles;  // each corner its own copy's value
  }
  *welded = std::move(out);
  return removed;
}

}  // namespace gab
