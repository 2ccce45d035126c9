// weld_coincident_vertices: copies of a vertex merged, their data kept per corner.
#include "gab/mesh/weld.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "common/test_meshes.h"

namespace gab {
namespace {

// Every triangle of `m` with its own three vertices, each copy carrying
// its triangle's index as a colour: what a PLY export split at every edge holds.
Mesh soup_of(const Mesh& m) {
  Mesh s;
  MeshAttribute tag;
  tag.kind = AttributeKind::kGeneric;
  tag.type = ValueType::kInt32;
  tag.name = "triangle";
  for (int32_t t = 0; t < m.num_triangles(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const int32_t v = m.triangles[3 * t + k];
      s.positions.insert(s.positions.end(), m.positions.begin() + 3 * v, m.positions.begin() + 3 * v + 3);
      s.triangles.push_back(3 * t + k);
      tag.values.push_back(t);
    }
  }
  s.attributes.push_back(tag);
  return s;
}

TEST(Weld, ASoupBecomesTheMeshItWasCutFromWithItsDataPerCorner) {
  const Mesh m = testing_util::bumpy_torus(9, 7);
  const Mesh s = soup_of(m);
  Mesh w;
  std::vector<int32_t> index;
  ASSERT_EQ(weld_coincident_vertices(s, &w, &index), s.num_vertices() - m.num_vertices());
  ASSERT_TRUE(validate_mesh(w, "welded").ok());
  EXPECT_EQ(w.num_vertices(), m.num_vertices());
  // Numbered by first copies: the torus's vertices meet in the soup in the
  // order its triangles first use them, which a renumbering maps back.
  ASSERT_EQ(index.size(), static_cast<size_t>(s.num_vertices()));
  for (size_t i = 0; i < s.triangles.size(); ++i) {
    EXPECT_EQ(w.triangles[i], index[s.triangles[i]]);
    for (int c = 0; c < 3; ++c) EXPECT_EQ(w.positions[3 * w.triangles[i] + c], s.positions[3 * s.triangles[i] + c]);
  }
  // The tag per corner: each corner still its own triangle's.
  ASSERT_EQ(w.attributes.size(), 1u);
  ASSERT_TRUE(w.attributes[0].per_corner());
  for (size_t c = 0; c < w.triangles.size(); ++c) {
    EXPECT_EQ(w.attributes[0].values[w.attributes[0].corners[c]], static_cast<double>(c / 3));
  }
}

TEST(Weld, NothingCoincidesOrAnUnusedVertexHoldsData) {
  Mesh m = testing_util::bumpy_torus(6, 5);
  Mesh w;
  std::vector<int32_t> index = {7};
  EXPECT_EQ(weld_coincident_vertices(m, &w, &index), 0);
  EXPECT_EQ(index, std::vector<int32_t>{7});  // untouched
  // A copy of vertex 0 in no triangle, with a per-vertex value: kept apart.
  m.positions.insert(m.positions.end(), m.positions.begin(), m.positions.begin() + 3);
  MeshAttribute q;
  q.name = "q";
  q.values.assign(m.num_vertices(), 1.5);
  m.attributes.push_back(q);
  EXPECT_EQ(weld_coincident_vertices(m, &w, &index), 0);
  // Without the value it merges.
  m.attributes.clear();
  EXPECT_EQ(weld_coincident_vertices(m, &w, &index), 1);
  EXPECT_EQ(w.num_vertices(), m.num_vertices() - 1);
  EXPECT_EQ(index.back(), 0);
}

}  // namespace
}  // namespace gab
