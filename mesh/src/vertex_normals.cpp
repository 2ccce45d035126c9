#include "gab/mesh/vertex_normals.h"

#include <cmath>

namespace gab {

MeshAttribute area_weighted_normals(const Mesh& mesh) {
  MeshAttribute a;
  a.kind = AttributeKind::kNormal;
  a.components = 3;
  a.values.assign(mesh.positions.size(), 0.0);
  const auto at = [&mesh](int32_t v) { return &mesh.positions[3 * static_cast<size_t>(v)]; };
  for (int32_t t = 0; t < mesh.num_triangles(); ++t) {
    const int32_t* v = &mesh.triangles[3 * static_cast<size_t>(t)];
    const double *p0 = at(v[0]), *p1 = at(v[1]), *p2 = at(v[2]);
    const double e1[3] = {p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]};
    const double e2[3] = {p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]};
    const double n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
    for (int k = 0; k < 3; ++k) {
      for (int c = 0; c < 3; ++c) a.values[3 * static_cast<size_t>(v[k]) + c] += n[c];
    }
  }
  for (size_t i = 0; i < a.values.size(); i += 3) {
    double* n = &a.values[i];
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (length > 0) {
      for (int c = 0; c < 3; ++c) n[c] /= length;
    } else {
      n[0] = n[1] = 0;
      n[2] = 1;
    }
  }
  return a;
}

}  // namespace gab
