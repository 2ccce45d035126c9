// Mesh: the minimal triangle-mesh type of the mesh layer.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "gab/mesh/mesh_attribute.h"
#include "gab/status.h"

namespace gab {

// The most attributes a mesh carries (a PLY file with more scalar properties
// is read with the first ones and the rest named as dropped).
constexpr int32_t kMaxMeshAttributes = 64;

struct Mesh {
  std::vector<double> positions;   // 3 per vertex: x0 y0 z0 x1 y1 z1 ...
  std::vector<int32_t> triangles;  // 3 per triangle, 0-based vertex indices
  // Normals, texture coordinates, colours, named scalars: per vertex (in
  // vertex order) or per corner (following `triangles`).
  std::vector<MeshAttribute> attributes;

  int32_t num_vertices() const { return static_cast<int32_t>(positions.size() / 3); }
  int32_t num_triangles() const { return static_cast<int32_t>(triangles.size() / 3); }
};

// Checks what every reader guarantees: at least one vertex and one triangle,
// array sizes multiples of 3 and within int32, finite coordinates, indices in
// range, every attribute valid (validate_attribute, at most
// kMaxMeshAttributes of them). Degenerate or duplicate triangles and
// unreferenced vertices are legal. Messages start with `name`. O(V + T +
// attribute values).
Status validate_mesh(const Mesh& mesh, const std::string& name);

}  // namespace gab
