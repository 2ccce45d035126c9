// Attributes through the whole codec (encode_mesh, decode_mesh): every kind,
// per vertex and per corner with seams, in either vertex numbering, at any
// level of detail, and what a file cut inside a section keeps.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "attributes/attribute_section.h"
#include "attributes/corner_table.h"
#include "codec/attributes/attribute_checks.h"
#include "common/gab_files.h"
#include "common/test_meshes.h"
#include "gab/codec/decoder.h"
#include "gab/codec/encoder.h"
#include "gab/mesh/vertex_normals.h"

namespace gab {
namespace {

using testing_util::bumpy_torus;
using testing_util::decode_or_die;
using testing_util::encode_or_die;

MeshAttribute vertex_normals(const Mesh& m) { return area_weighted_normals(m); }

// The torus's (u, v) parameters per corner, with the seams where they wrap
// (a corner of a triangle across the wrap takes 1, not 0): n x m quads.
MeshAttribute torus_uvs(int n, int m) {
  MeshAttribute a;
  a.kind = AttributeKind::kTexCoord;
  a.components = 2;
  // Elements: the (n + 1) x (m + 1) grid of parameters.
  for (int i = 0; i <= n; ++i) {
    for (int j = 0; j <= m; ++j) a.values.insert(a.values.end(), {static_cast<double>(i) / n, static_cast<double>(j) / m});
  }
  auto e = [m](int i, int j) { return i * (m + 1) + j; };
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < m; ++j) {
      a.corners.insert(a.corners.end(), {e(i, j), e(i + 1, j), e(i + 1, j + 1), e(i, j), e(i + 1, j + 1), e(i, j + 1)});
    }
  }
  return a;
}

MeshAttribute byte_colors(const Mesh& m) {
  MeshAttribute a;
  a.kind = AttributeKind::kColor;
  a.type = ValueType::kUint8;
  a.components = 3;
  for (int32_t v = 0; v < m.num_vertices(); ++v) {
    const double* p = &m.positions[3 * static_cast<size_t>(v)];
    for (int c = 0; c < 3; ++c) a.values.push_back(std::floor(127.5 + 127 * std::sin(2 * p[c] + c)));
  }
  return a;
}

MeshAttribute generic(const Mesh& m, const std::string& name, ValueType type) {
  MeshAttribute a;
  a.kind = AttributeKind::kGeneric;
  a.type = type;
  a.name = name;
  a.components = 1;
  for (int32_t v = 0; v < m.num_vertices(); ++v) {
    const double x = std::cos(3 * m.positions[3 * static_cast<size_t>(v)]) * 1000;
    a.values.push_back(type == ValueType::kInt32 ? std::floor(x) : x / 7);
  }
  return a;
}

Mesh attributed_torus() {
  Mesh m = bumpy_torus(40, 24);
  m.attributes.push_back(vertex_normals(m));
  m.attributes.push_back(torus_uvs(40, 24));
  m.attributes.push_back(byte_colors(m));
  m.attributes.push_back(generic(m, "quality", ValueType::kFloat32));
  m.attributes.push_back(generic(m, "segment", ValueType::kInt32));
  return m;
}

double largest_error(const Mesh& input, const Mesh& decoded, const std::vector<int32_t>& new_index, size_t which) {
  return testing_util::largest_attribute_error(input, decoded, new_index, which);
}

TEST(AttributeRoundTrip, EveryKindComesBackWithinItsQuantizationInEitherNumbering) {
  const Mesh input = attributed_torus();
  for (bool reorder : {true, false}) {
    SCOPED_TRACE(reorder ? "traversal order" : "kept order");
    EncodeOptions o;
    o.target_rms_rel = 1e-3;
    o.reorder = reorder;
    EncodeStats stats;
    const std::vector<uint8_t> file = encode_or_die(input, o, &stats);
    ASSERT_EQ(stats.attributes.size(), 5u);
    DecodeStats ds;
    const Mesh out = decode_or_die(file, DecodeOptions(), &ds);
    ASSERT_EQ(out.attributes.size(), 5u);
    EXPECT_GT(stats.attribute_bytes, 0u);
    EXPECT_EQ(stats.bytes, file.size());
    EXPECT_EQ(stats.connectivity_bytes + stats.order_bytes + stats.geometry_bytes + stats.attribute_bytes, stats.bytes);
    // Normals: the 8-bit lattice (step 1/128 of the octahedron) is within about one step, 0.6 degrees.
    EXPECT_EQ(stats.attributes[0].label, "normals");
    EXPECT_FALSE(stats.attributes[0].per_corner);
    EXPECT_LE(largest_error(input, out, stats.new_index, 0), stats.attributes[0].max_error + 1e-9);
    EXPECT_LT(stats.attributes[0].max_error, 0.6);
    // UVs: per corner, the torus's two seams kept, half a 10-bit step of the span 1.
    EXPECT_EQ(stats.attributes[1].label, "texture_coordinates");
    EXPECT_TRUE(stats.attributes[1].per_corner);
    EXPECT_TRUE(out.attributes[1].per_corner());
    EXPECT_EQ(stats.attributes[1].elements, 41 * 25);
    EXPECT_LE(largest_error(input, out, stats.new_index, 1), 0.5 / 1023 + 1e-12);
    // Byte colours and integer properties: exact.
    EXPECT_EQ(stats.attributes[2].label, "vertex_colors");
    EXPECT_EQ(largest_error(input, out, stats.new_index, 2), 0.0);
    EXPECT_EQ(out.attributes[2].type, ValueType::kUint8);
    EXPECT_EQ(stats.attributes[4].label, "generic:segment");
    EXPECT_EQ(largest_error(input, out, stats.new_index, 4), 0.0);
    EXPECT_EQ(out.attributes[4].name, "segment");
    // A float property: half a 16-bit step of its span.
    const double span = 2000.0 / 7;
    EXPECT_LE(largest_error(input, out, stats.new_index, 3), 0.5 * span / 65535 * 1.0001);
  }
}

// A level of detail decodes every attribute predicted from the connectivity
// whole, and skips normals predicted from the decoded surface (they need
// the whole shape), as does a decode without the detail layer.
TEST(AttributeRoundTrip, ALevelOfDetailDecodesTheAttributesTheConnectivityPredicts) {
  const Mesh input = attributed_torus();
  for (double target : {1e-3, 1e-4}) {
    SCOPED_TRACE(target);
    EncodeOptions o;
    o.target_rms_rel = target;
    EncodeStats stats;
    const std::vector<uint8_t> file = encode_or_die(input, o, &stats);
    DecodeStats ds;
    const Mesh whole = decode_or_die(file, DecodeOptions(), &ds);
    ASSERT_EQ(whole.attributes.size(), 5u);
    EXPECT_EQ(ds.skipped_sections, 0);
    std::vector<DecodeOptions> partial(2);
    partial[0].max_anchors = 5;
    partial[1].detail = false;
    for (const DecodeOptions& options : partial) {
      if (!options.detail && !stats.detail) continue;
      const Mesh coarse = decode_or_die(file, options, &ds);
      size_t j = 0;
      for (size_t i = 0; i < whole.attributes.size(); ++i) {
        if (stats.attributes[i].from_surface) continue;
        ASSERT_LT(j, coarse.attributes.size());
        EXPECT_EQ(coarse.attributes[j].values, whole.attributes[i].values);
        EXPECT_EQ(coarse.attributes[j].corners, whole.attributes[i].corners);
        ++j;
      }
      EXPECT_EQ(j, coarse.attributes.size());
      EXPECT_EQ(static_cast<size_t>(ds.skipped_sections), whole.attributes.size() - j);
    }
  }
}

// Where the decoded shape is fine, normals are predicted from it: smaller
// than from their neighbours' values, and decoded as exactly.
TEST(AttributeRoundTrip, NormalsOverAFineShapeArePredictedFromTheSurface) {
  const Mesh input = attributed_torus();
  EncodeOptions o;
  o.target_rms_rel = 1e-4;
  EncodeStats stats;
  const std::vector<uint8_t> file = encode_or_die(input, o, &stats);
  ASSERT_TRUE(stats.attributes[0].from_surface);
  EXPECT_FALSE(stats.attributes[1].from_surface);
  DecodeStats ds;
  const Mesh out = decode_or_die(file, DecodeOptions(), &ds);
  EXPECT_LE(largest_error(input, out, stats.new_index, 0), stats.attributes[0].max_error + 1e-9);
  // The decoded normals coded again over the decoded mesh: the same bytes
  // from the surface, more from their neighbours alone.
  const CornerTable table = build_corner_table(out.num_vertices(), out.triangles);
  AttributeCoding from_surface, from_neighbours;
  const size_t with = encode_attribute_section(out.attributes[0], table, 8, &out.positions, &from_surface).size();
  const size_t without = encode_attribute_section(out.attributes[0], table, 8, nullptr, &from_neighbours).size();
  EXPECT_TRUE(from_surface.surface);
  EXPECT_FALSE(from_neighbours.surface);
  EXPECT_EQ(with + 8, stats.attributes[0].bytes);
  EXPECT_LT(with, without * 3 / 4);
}

TEST(AttributeRoundTrip, AFileCutInsideASectionKeepsTheSectionsBeforeIt) {
  const Mesh input = attributed_torus();
  EncodeOptions o;
  o.target_rms_rel = 1e-3;
  EncodeStats stats;
  const std::vector<uint8_t> file = encode_or_die(input, o, &stats);
  // Cut inside the last section: four attributes and the whole shape.
  const size_t cut = file.size() - stats.attributes.back().bytes / 2;
  Mesh out;
  DecodeStats ds;
  ASSERT_TRUE(decode_mesh(file.data(), cut, DecodeOptions(), &out, &ds).ok());
  EXPECT_TRUE(ds.truncated);
  EXPECT_EQ(out.attributes.size(), 4u);
  EXPECT_EQ(ds.anchors, stats.anchors);
  // Cut before the sections: none.
  const size_t geometry_end = file.size() - stats.attribute_bytes;
  ASSERT_TRUE(decode_mesh(file.data(), geometry_end, DecodeOptions(), &out, &ds).ok());
  EXPECT_TRUE(ds.truncated);
  EXPECT_TRUE(out.attributes.empty());
}

TEST(AttributeRoundTrip, PerCornerValuesWithoutSeamsAreCodedPerVertex) {
  Mesh m = bumpy_torus(20, 12);
  MeshAttribute normals = vertex_normals(m);
  // The same normals given per corner (OBJ's f v//vn with vn per vertex).
  normals.corners = m.triangles;
  m.attributes.push_back(normals);
  EncodeOptions o;
  o.target_rms_rel = 1e-3;
  EncodeStats stats;
  const std::vector<uint8_t> file = encode_or_die(m, o, &stats);
  ASSERT_EQ(stats.attributes.size(), 1u);
  EXPECT_FALSE(stats.attributes[0].per_corner);
  DecodeStats ds;
  const Mesh out = decode_or_die(file, DecodeOptions(), &ds);
  ASSERT_EQ(out.attributes.size(), 1u);
  EXPECT_FALSE(out.attributes[0].per_corner());
  EXPECT_LE(largest_error(m, out, stats.new_index, 0), stats.attributes[0].max_error + 1e-9);
}

// A triangle soup (every triangle its own vertices, a per-vertex value on
// each copy) is welded in traversal order: the file codes the torus once,
// the values per corner; with the input's order kept nothing is merged.
TEST(AttributeRoundTrip, CopiesOfAVertexAreMergedTheirValuesKeptPerCorner) {
  const Mesh m = bumpy_torus(16, 10);
  Mesh soup;
  MeshAttribute normals = vertex_normals(m);
  MeshAttribute copies = normals;
  copies.values.clear();
  for (int32_t t = 0; t < m.num_triangles(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const int32_t v = m.triangles[3 * t + k];
      soup.positions.insert(soup.positions.end(), m.positions.begin() + 3 * v, m.positions.begin() + 3 * v + 3);
      soup.triangles.push_back(3 * t + k);
      // Each copy its triangle's own normal: flat shading, a seam at every edge.
      const double* p0 = &m.positions[3 * static_cast<size_t>(m.triangles[3 * t])];
      const double* p1 = &m.positions[3 * static_cast<size_t>(m.triangles[3 * t + 1])];
      const double* p2 = &m.positions[3 * static_cast<size_t>(m.triangles[3 * t + 2])];
      const double e1[3] = {p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]};
      const double e2[3] = {p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2]};
      copies.values.insert(copies.values.end(), {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                                                 e1[0] * e2[1] - e1[1] * e2[0]});
    }
  }
  soup.attributes.push_back(copies);
  EncodeOptions o;
  o.target_rms_rel = 1e-3;
  EncodeStats stats;
  const std::vector<uint8_t> file = encode_or_die(soup, o, &stats);
  EXPECT_EQ(stats.merged_vertices, soup.num_vertices() - m.num_vertices());
  EXPECT_EQ(stats.num_vertices, m.num_vertices());
  DecodeStats ds;
  const Mesh out = decode_or_die(file, DecodeOptions(), &ds);
  EXPECT_EQ(out.num_vertices(), m.num_vertices());
  ASSERT_EQ(out.attributes.size(), 1u);
  EXPECT_TRUE(out.attributes[0].per_corner());
  EXPECT_LE(largest_error(soup, out, stats.new_index, 0), stats.attributes[0].max_error + 1e-9);
  // Faceted normals (a triangle's corners alike) are predicted from the
  // values already decoded in their triangle (predictors 5 and 6).
  GabFileInfo info;
  ASSERT_TRUE(read_gab_info(file.data(), file.size(), &info).ok());
  ASSERT_EQ(info.section_list.size(), 1u);
  EXPECT_GE(info.section_list[0].predictor, 5);
  // Kept order: every copy stays a vertex.
  o.reorder = false;
  EncodeStats kept;
  encode_or_die(soup, o, &kept);
  EXPECT_EQ(kept.merged_vertices, 0);
  EXPECT_EQ(kept.num_vertices, soup.num_vertices());
  EXPECT_GT(kept.bytes, 2 * stats.bytes);
}

TEST(AttributeRoundTrip, GabInfoListsTheSections) {
  const Mesh input = attributed_torus();
  EncodeOptions o;
  o.target_rms_rel = 1e-3;
  EncodeStats stats;
  const std::vector<uint8_t> file = encode_or_die(input, o, &stats);
  GabFileInfo info;
  ASSERT_TRUE(read_gab_info(file.data(), file.size(), &info).ok());
  ASSERT_EQ(info.section_list.size(), 5u);
  EXPECT_EQ(info.sections, 5);
  EXPECT_EQ(info.section_bytes, stats.attribute_bytes);
  EXPECT_EQ(info.section_list[1].attribute, "texture_coordinates");
  EXPECT_TRUE(info.section_list[1].per_corner);
  EXPECT_EQ(info.section_list[1].elements, 41 * 25);
  EXPECT_EQ(info.section_list[1].bits, 10);
  EXPECT_EQ(info.section_list[3].attribute, "generic:quality");
  EXPECT_EQ(info.geometry_bytes, stats.geometry_bytes);
}

TEST(AttributeRoundTrip, OptionErrors) {
  Mesh m = bumpy_torus(8, 6);
  std::vector<uint8_t> file;
  EncodeStats stats;
  EncodeOptions o;
  o.max_anchors = 10;
  o.normal_bits = 17;
  EXPECT_EQ(encode_mesh(m, o, &file, &stats).message(), "normal bits must be in 2..16");
  o.normal_bits = 8;
  o.texcoord_bits = 0;
  EXPECT_EQ(encode_mesh(m, o, &file, &stats).message(), "texture coordinate, colour and generic bits must be in 1..31");
}

}  // namespace
}  // namespace gab
