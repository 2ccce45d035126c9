// split_attribute_seams: per-corner attributes made per vertex, one vertex
// per distinct combination of elements at a vertex's corners.
#include "gab/mesh/attribute_seams.h"

#include <gtest/gtest.h>

#include <set>
#include <tuple>

#include "mesh_test_util.h"

namespace gab {
namespace {

// A unit square as two triangles (0 1 2), (0 2 3) and an isolated vertex 4.
Mesh square() {
  Mesh m;
  m.positions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 5, 5, 5};
  m.triangles = {0, 1, 2, 0, 2, 3};
  return m;
}

MeshAttribute per_corner(AttributeKind kind, int components, std::vector<double> values, std::vector<int32_t> corners) {
  MeshAttribute a;
  a.kind = kind;
  a.components = components;
  a.values = std::move(values);
  a.corners = std::move(corners);
  return a;
}

// Every corner of `split` carries the value `mesh`'s corner had.
void expect_corner_values_kept(const Mesh& mesh, const Mesh& split, size_t attribute) {
  const MeshAttribute& from = mesh.attributes[attribute];
  const MeshAttribute& to = split.attributes[attribute];
  const size_t k = static_cast<size_t>(from.components);
  ASSERT_EQ(split.triangles.size(), mesh.triangles.size());
  for (size_t c = 0; c < mesh.triangles.size(); ++c) {
    const size_t e = static_cast<size_t>(from.per_corner() ? from.corners[c] : mesh.triangles[c]);
    const size_t v = static_cast<size_t>(to.per_corner() ? to.corners[c] : split.triangles[c]);
    for (size_t i = 0; i < k; ++i) EXPECT_EQ(to.values[k * v + i], from.values[k * e + i]) << "corner " << c;
    for (int i = 0; i < 3; ++i) {
      EXPECT_EQ(split.positions[3 * static_cast<size_t>(split.triangles[c]) + i],
                mesh.positions[3 * static_cast<size_t>(mesh.triangles[c]) + i]);
    }
  }
}

TEST(AttributeSeamsTest, NoPerCornerAttributeLeavesTheMeshAlone) {
  Mesh m = square();
  MeshAttribute color;
  color.kind = AttributeKind::kColor;
  color.type = ValueType::kUint8;
  color.components = 3;
  color.values.assign(15, 7);
  m.attributes.push_back(color);
  int64_t added = -1;
  const Mesh out = split_attribute_seams(m, {}, &added);
  EXPECT_EQ(added, 0);
  EXPECT_EQ(out.positions, m.positions);
  EXPECT_EQ(out.triangles, m.triangles);
  EXPECT_TRUE(testing_util::same_attributes(out, m));
}

TEST(AttributeSeamsTest, ASeamVertexBecomesOneVertexPerElement) {
  // Vertex 0's corners refer to UV 0 in the first triangle and UV 4 in the
  // second (a seam); vertex 2's to UV 2 in both (no seam).
  Mesh m = square();
  m.attributes.push_back(per_corner(AttributeKind::kTexCoord, 2, {0, 0, 1, 0, 1, 1, 0, 1, 9, 9}, {0, 1, 2, 4, 2, 3}));
  int64_t added = -1;
  const Mesh out = split_attribute_seams(m, {}, &added);
  EXPECT_EQ(added, 1);
  ASSERT_EQ(out.num_vertices(), 6);
  // Vertex 0 keeps its index for its first corner's UV; the new vertex 5
  // copies its position.
  EXPECT_EQ(out.triangles, (std::vector<int32_t>{0, 1, 2, 5, 2, 3}));
  EXPECT_EQ(std::vector<double>(out.positions.begin() + 15, out.positions.end()), (std::vector<double>{0, 0, 0}));
  const MeshAttribute& uv = out.attributes[0];
  EXPECT_FALSE(uv.per_corner());
  // The isolated vertex 4 gets zeros.
  EXPECT_EQ(uv.values, (std::vector<double>{0, 0, 1, 0, 1, 1, 0, 1, 0, 0, 9, 9}));
  EXPECT_TRUE(validate_mesh(out, "out").ok());
  expect_corner_values_kept(m, out, 0);
}

TEST(AttributeSeamsTest, CombinationsAcrossAttributesAndPerVertexOnesCopied) {
  // Six triangles around vertex 0 whose corners there refer to (uv, normal)
  // pairs (0, 0), (0, 0), (0, 1), (1, 0), (1, 0), (0, 1): three combinations.
  Mesh m;
  m.positions = {0, 0, 0};
  for (int i = 0; i < 6; ++i) {
    m.positions.insert(m.positions.end(), {std::cos(i * 1.0), std::sin(i * 1.0), 0});
  }
  for (int i = 0; i < 6; ++i) m.triangles.insert(m.triangles.end(), {0, 1 + i, 1 + (i + 1) % 6});
  std::vector<int32_t> uv_corners, normal_corners;
  const int uv_at_0[6] = {0, 0, 0, 1, 1, 0}, normal_at_0[6] = {0, 0, 1, 0, 0, 1};
  for (int i = 0; i < 6; ++i) {
    uv_corners.insert(uv_corners.end(), {uv_at_0[i], 2, 2});
    normal_corners.insert(normal_corners.end(), {normal_at_0[i], 0, 0});
  }
  m.attributes.push_back(per_corner(AttributeKind::kTexCoord, 2, {0, 0, 1, 1, 0.5, 0.5}, uv_corners));
  m.attributes.push_back(per_corner(AttributeKind::kNormal, 3, {0, 0, 1, 0, 1, 0}, normal_corners));
  MeshAttribute weight;  // per vertex
  weight.kind = AttributeKind::kGeneric;
  weight.name = "weight";
  for (int v = 0; v < 7; ++v) weight.values.push_back(10 + v);
  m.attributes.push_back(weight);
  ASSERT_TRUE(validate_mesh(m, "m").ok());

  int64_t added = -1;
  const Mesh out = split_attribute_seams(m, {}, &added);
  EXPECT_EQ(added, 2);
  ASSERT_EQ(out.num_vertices(), 9);
  // New vertices in the order first met: (0, 1) at triangle 2, (1, 0) at 3.
  EXPECT_EQ(out.triangles[6], 7);
  EXPECT_EQ(out.triangles[9], 8);
  EXPECT_EQ(out.triangles[12], 8);
  EXPECT_EQ(out.triangles[15], 7);
  EXPECT_EQ(out.attributes[2].values[7], 10.0);  // the copies keep vertex 0's weight
  EXPECT_EQ(out.attributes[2].values[8], 10.0);
  EXPECT_TRUE(validate_mesh(out, "out").ok());
  for (size_t a = 0; a < 3; ++a) expect_corner_values_kept(m, out, a);

  // Only the normals selected: the UVs stay per corner, valid for the new triangles.
  const Mesh normals_only = split_attribute_seams(m, {false, true, false}, &added);
  EXPECT_EQ(added, 1);
  EXPECT_TRUE(normals_only.attributes[0].per_corner());
  EXPECT_FALSE(normals_only.attributes[1].per_corner());
  EXPECT_TRUE(validate_mesh(normals_only, "normals only").ok());
  for (size_t a = 0; a < 3; ++a) expect_corner_values_kept(m, normals_only, a);
}

TEST(AttributeSeamsTest, AddedCountIsTheDistinctCombinationsOnAGrid) {
  // A grid whose every corner has its own UV element: each vertex splits
  // into as many vertices as it has distinct elements at its corners.
  Mesh m = testing_util::grid(6, 4);
  std::vector<int32_t> corners(m.triangles.size());
  std::vector<double> values;
  for (size_t c = 0; c < corners.size(); ++c) {
    // Corners of even triangles share their vertex's element; odd ones have their own.
    const bool own = (c / 3) % 2 == 1;
    corners[c] = static_cast<int32_t>(own ? m.num_vertices() + c : m.triangles[c]);
  }
  values.assign(2 * (static_cast<size_t>(m.num_vertices()) + corners.size()), 0.0);
  for (size_t i = 0; i < values.size(); ++i) values[i] = static_cast<double>(i);
  m.attributes.push_back(per_corner(AttributeKind::kTexCoord, 2, values, corners));
  std::set<std::pair<int32_t, int32_t>> combinations;
  std::set<int32_t> used;
  for (size_t c = 0; c < corners.size(); ++c) {
    combinations.insert({m.triangles[c], corners[c]});
    used.insert(m.triangles[c]);
  }
  int64_t added = -1;
  const Mesh out = split_attribute_seams(m, {}, &added);
  EXPECT_EQ(added, static_cast<int64_t>(combinations.size() - used.size()));
  EXPECT_EQ(out.num_vertices(), m.num_vertices() + added);
  expect_corner_values_kept(m, out, 0);
}

}  // namespace
}  // namespace gab
