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
  return out;
}

}  // namespace gab
