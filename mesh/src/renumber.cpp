#include "gab/mesh/renumber.h"

namespace gab {

Mesh renumber_vertices(const Mesh& mesh, const std::vector<int32_t>& new_index) {
  Mesh out;
  out.positions.resize(mesh.positions.size());
  for (int32_t v = 0; v < mesh.num_vertices(); ++v) {
    for (int c = 0; c < 3; ++c) {
      out.positions[3 * static_cast<size_t>(new_index[v]) + c] = mesh.positions[3 * static_cast<size_t>(v) + c];
    }
  }
  out.triangles.reserve(mesh.triangles.size());
  for (int32_t v : mesh.triangles) out.triangles.push_back(new_index[v]);
  // Per-vertex attributes move with their vertices; per-corner ones follow
  // the triangles, which keep their order.
  out.attributes = mesh.attributes;
  for (MeshAttribute& a : out.attributes) {
    if (a.per_corner()) continue;
    const size_t k = static_cast<size_t>(a.components);
    const std::vector<double>& from = mesh.attributes[&a - out.attributes.data()].values;
    for (int32_t v = 0; v < mesh.num_vertices(); ++v) {
      for (size_t c = 0; c < k; ++c) a.values[k * static_cast<size_t>(new_index[v]) + c] = from[k * static_cast<size_t>(v) + c];
    }
  }
  return out;
}

}  // namespace gab
