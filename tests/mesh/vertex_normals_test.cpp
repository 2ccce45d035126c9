// area_weighted_normals: the unit sum of a vertex's triangles' area vectors.
#include "gab/mesh/vertex_normals.h"

#include <gtest/gtest.h>

#include <cmath>

#include "common/test_meshes.h"

namespace gab {
namespace {

TEST(VertexNormals, ATorusGetsItsOutwardNormalsAndAnIsolatedVertexUp) {
  Mesh m = testing_util::torus(48, 32);
  m.positions.insert(m.positions.end(), {5, 5, 5});  // in no triangle
  const MeshAttribute n = area_weighted_normals(m);
  ASSERT_TRUE(validate_attribute(n, m.num_vertices(), m.num_triangles(), "normals").ok());
  EXPECT_EQ(n.kind, AttributeKind::kNormal);
  EXPECT_FALSE(n.per_corner());
  for (int32_t v = 0; v + 1 < m.num_vertices(); ++v) {
    // The torus's normal at (u, v): from the tube's centre to the vertex.
    const double* p = &m.positions[3 * static_cast<size_t>(v)];
    const double r = std::hypot(p[0], p[1]);
    const double out[3] = {p[0] - p[0] / r, p[1] - p[1] / r, p[2]};
    const double length = std::sqrt(out[0] * out[0] + out[1] * out[1] + out[2] * out[2]);
    const double* x = &n.values[3 * static_cast<size_t>(v)];
    EXPECT_NEAR(std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]), 1.0, 1e-12);
    EXPECT_GT((x[0] * out[0] + x[1] * out[1] + x[2] * out[2]) / length, std::cos(0.05)) << v;
  }
  const double* last = &n.values[n.values.size() - 3];
  EXPECT_EQ(last[0], 0.0);
  EXPECT_EQ(last[1], 0.0);
  EXPECT_EQ(last[2], 1.0);
}

}  // namespace
}  // namespace gab
