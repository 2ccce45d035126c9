#include "gab/mesh/mesh.h"

#include <cmath>
#include <cstdint>

namespace gab {

Status validate_mesh(const Mesh& mesh, const std::string& name) {
  auto invalid = [&name](const std::string& what) {
    return Status::Error(StatusCode::kInvalidArgument, name + ": " + what);
  };
  if (mesh.positions.size() % 3 != 0) return invalid("positions are not a multiple of 3 values");
  if (mesh.triangles.size() % 3 != 0) return invalid("triangles are not a multiple of 3 indices");
  if (mesh.positions.size() / 3 > static_cast<size_t>(INT32_MAX) ||
      mesh.triangles.size() / 3 > static_cast<size_t>(INT32_MAX)) {
    return Status::Error(StatusCode::kOverflow, name + ": more than 2^31-1 vertices or triangles");
  }
  if (mesh.positions.empty()) return invalid("mesh has no vertices");
  if (mesh.triangles.empty()) return invalid("mesh has no faces");
  for (size_t i = 0; i < mesh.positions.size(); ++i) {
    if (!std::isfinite(mesh.positions[i])) {
      return invalid("vertex " + std::to_string(i / 3) + ": coordinate is not finite");
    }
  }
  const int64_t n = mesh.num_vertices();
  for (size_t i = 0; i < mesh.triangles.size(); ++i) {
    const int32_t v = mesh.triangles[i];
    if (v < 0 || v >= n) {
      return invalid("triangle " + std::to_string(i / 3) + ": vertex index " + std::to_string(v) +
                     " out of range [0, " + std::to_string(n) + ")");
    }
  }
  if (mesh.attributes.size() > static_cast<size_t>(kMaxMeshAttributes)) {
    return invalid(std::to_string(mesh.attributes.size()) + " attributes, over the " +
                   std::to_string(kMaxMeshAttributes) + " a mesh carries");
  }
  for (const MeshAttribute& a : mesh.attributes) {
    GAB_RETURN_IF_ERROR(validate_attribute(a, n, mesh.num_triangles(), name));
  }
  return Status::Ok();
}

}  // namespace gab
