// PLY attributes: the common kinds under each spelling, generics with
// their types, MeshLab's per-corner texcoord lists, what is dropped and
// why, and round trips through every encoding.
#include <gtest/gtest.h>

#include <cstring>
#include <limits>
#include <string>

#include "gab/mesh/attribute_seams.h"
#include "gab/mesh/ply_io.h"
#include "mesh_test_util.h"

namespace gab {
namespace {

std::string labels(const Mesh& m) {
  std::string out;
  for (const MeshAttribute& a : m.attributes) out += (out.empty() ? "" : " ") + attribute_label(a);
  return out;
}

// An ASCII PLY of a triangle whose vertices have `properties` (after x y
// z) with the values `rows` (one per vertex, after the coordinates).
std::string ascii_triangle(const std::string& properties, const std::string rows[3],
                           const std::string& face_properties = "", const std::string& face_row = "") {
  return "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n" +
         properties + "element face 1\nproperty list uchar int vertex_indices\n" + face_properties +
         "end_header\n0 0 0 " + rows[0] + "\n1 0 0 " + rows[1] + "\n0 1 0 " + rows[2] + "\n3 0 1 2" +
         (face_row.empty() ? "" : " " + face_row) + "\n";
}

TEST(PlyAttributesTest, KindsTypesAndGenerics) {
  const std::string properties =
      "property float nx\nproperty float ny\nproperty float nz\nproperty uchar red\nproperty uchar green\n"
      "property uchar blue\nproperty uchar alpha\nproperty double u\nproperty double v\nproperty ushort id\n"
      "property list uchar short bones\n";
  const std::string rows[3] = {"0 0 1 255 0 0 255 0.1 0.2 7 2 3 4", "0 0 1 0 255 0 128 1 0 8 2 5 6",
                               "0 0 1 0 0 255 0 0 1 9 2 7 8"};
  Mesh m;
  MeshReadNotes notes;
  const Status s = parse_ply(ascii_triangle(properties, rows), "k.ply", &m, &notes);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_TRUE(notes.empty()) << notes.dropped_summary();
  EXPECT_EQ(labels(m), "normals texture_coordinates vertex_colors generic:id generic:bones");
  const MeshAttribute& n = m.attributes[0];
  EXPECT_EQ(n.type, ValueType::kFloat32);
  EXPECT_EQ(n.values, (std::vector<double>{0, 0, 1, 0, 0, 1, 0, 0, 1}));
  const MeshAttribute& uv = m.attributes[1];
  EXPECT_EQ(uv.type, ValueType::kFloat64);
  EXPECT_EQ(uv.values, (std::vector<double>{0.1, 0.2, 1, 0, 0, 1}));  // double: as written
  const MeshAttribute& c = m.attributes[2];
  EXPECT_EQ(c.type, ValueType::kUint8);
  EXPECT_EQ(c.components, 4);
  EXPECT_EQ(c.values, (std::vector<double>{255, 0, 0, 255, 0, 255, 0, 128, 0, 0, 255, 0}));
  EXPECT_EQ(m.attributes[3].type, ValueType::kUint16);
  EXPECT_EQ(m.attributes[3].values, (std::vector<double>{7, 8, 9}));
  const MeshAttribute& bones = m.attributes[4];
  EXPECT_EQ(bones.type, ValueType::kInt16);
  EXPECT_EQ(bones.components, 2);
  EXPECT_EQ(bones.values, (std::vector<double>{3, 4, 5, 6, 7, 8}));
  EXPECT_TRUE(validate_mesh(m, "k.ply").ok());
}

TEST(PlyAttributesTest, ColourSpellingsAndTypes) {
  const struct {
    std::string properties, row, label;
    ValueType type;
    int components;
  } cases[] = {
      {"property float r\nproperty float g\nproperty float b\nproperty float a\n", "0.5 0.25 1 1", "vertex_colors",
       ValueType::kFloat32, 4},
      {"property uchar diffuse_red\nproperty uchar diffuse_green\nproperty uchar diffuse_blue\n", "10 20 30",
       "vertex_colors", ValueType::kUint8, 3},
      // Mixed types are no colour: three generics.
      {"property uchar red\nproperty float green\nproperty uchar blue\n", "10 0.5 30",
       "generic:red generic:green generic:blue", ValueType::kUint8, 1},
      // An alpha of another type stays apart.
      {"property uchar red\nproperty uchar green\nproperty uchar blue\nproperty float alpha\n", "10 20 30 0.5",
       "vertex_colors generic:alpha", ValueType::kUint8, 3},
  };
  for (const auto& c : cases) {
    const std::string rows[3] = {c.row, c.row, c.row};
    Mesh m;
    MeshReadNotes notes;
    const Status s = parse_ply(ascii_triangle(c.properties, rows), "c.ply", &m, &notes);
    ASSERT_TRUE(s.ok()) << s.message();
    EXPECT_EQ(labels(m), c.label);
    EXPECT_EQ(m.attributes[0].type, c.type) << c.label;
    EXPECT_EQ(m.attributes[0].components, c.components) << c.label;
    EXPECT_TRUE(notes.empty()) << notes.dropped_summary();
  }
}

TEST(PlyAttributesTest, FaceTexcoordListsArePerCornerWithSharedElements) {
  // MeshLab's form: a quad and a triangle, u v per corner; equal pairs share
  // an element.
  const std::string text =
      "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 2\nproperty list uchar float texcoord\nproperty list uchar int vertex_indices\n"
      "property int texnumber\nend_header\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 2 0\n"
      "8 0 0 1 0 1 1 0 1 4 0 1 2 3 0\n"
      "6 1 0 0.5 0.5 1 1 3 1 4 2 0\n";
  Mesh m;
  MeshReadNotes notes;
  const Status s = parse_ply(text, "ml.ply", &m, &notes);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(m.triangles, (std::vector<int32_t>{0, 1, 2, 0, 2, 3, 1, 4, 2}));
  ASSERT_EQ(m.attributes.size(), 1u);
  const MeshAttribute& uv = m.attributes[0];
  EXPECT_EQ(uv.kind, AttributeKind::kTexCoord);
  EXPECT_EQ(uv.values, (std::vector<double>{0, 0, 1, 0, 1, 1, 0, 1, 0.5, 0.5}));
  EXPECT_EQ(uv.corners, (std::vector<int32_t>{0, 1, 2, 0, 2, 3, 1, 4, 2}));
  EXPECT_EQ(notes.dropped_summary(), "2 face property 'texnumber', 1 polygons of 4 or more corners (fan-triangulated)");
  EXPECT_TRUE(validate_mesh(m, "ml.ply").ok());

  // A list that does not match its face's corners: dropped, named.
  const std::string bad =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar int vertex_indices\nproperty list uchar float texcoord\nend_header\n"
      "0 0 0\n1 0 0\n0 1 0\n3 0 1 2 4 0 0 1 0\n";
  ASSERT_TRUE(parse_ply(bad, "bad.ply", &m, &notes).ok());
  EXPECT_TRUE(m.attributes.empty());
  EXPECT_EQ(notes.dropped_summary(), "1 face property 'texcoord' (face 0: 4 values for 3 corners)");
}

// Per-corner texture coordinates beside generics: written per vertex, they
// come back in the same place among the attributes (kinds, then generics).
TEST(PlyAttributesTest, FaceTexcoordsAndGenericsRoundTripInOrder) {
  const std::string text =
      "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
      "property ushort id\nelement face 2\nproperty list uchar float texcoord\n"
      "property list uchar int vertex_indices\nend_header\n0 0 0 1\n1 0 0 2\n1 1 0 3\n0 1 0 4\n"
      "6 0 0 1 0 1 1 3 0 1 2\n6 0.5 0 1 1 0 1 3 0 2 3\n";
  Mesh m;
  ASSERT_TRUE(parse_ply(text, "o.ply", &m).ok());
  EXPECT_EQ(labels(m), "texture_coordinates generic:id");
  const Mesh split = split_attribute_seams(m);
  Mesh back;
  ASSERT_TRUE(parse_ply(format_ply(m), "back.ply", &back).ok());
  EXPECT_EQ(back.num_vertices(), 5);  // vertex 0 has two UVs
  EXPECT_TRUE(testing_util::same_attributes(back, split));
}

TEST(PlyAttributesTest, ValuesAnAttributeCannotKeepDropItWithANote) {
  const struct {
    std::string properties;
    std::string rows[3];
    std::string summary;
  } cases[] = {
      {"property float nx\nproperty float ny\nproperty float nz\n",
       {"0 0 1", "nan 0 1", "0 0 1"},
       "3 normals (nx ny nz; vertex 1: a value that is not finite)"},
      {"property uchar quality\n", {"1", "300", "2"}, "3 vertex property 'quality' (vertex 1: a value that is not a uchar)"},
      {"property short q\n", {"1", "2.5", "2"}, "3 vertex property 'q' (vertex 1: a value that is not a short)"},
      {"property float s\nproperty float t\n",
       {"0 0", "1 0", "1e39 1"},
       "3 texture coordinates (s t; vertex 2: a value beyond float's range)"},
      {"property list uchar float w\n", {"2 1 1", "3 1 1 1", "2 1 1"}, "3 vertex property 'w' (vertex 1: 3 items where vertex 0 has 2)"},
      {"property list uchar float w\n", {"5 1 1 1 1 1", "0", "0"},
       "3 vertex property 'w' (vertex 0: 5 items (a generic attribute holds 1 to 4))"},
  };
  for (const auto& c : cases) {
    Mesh m;
    MeshReadNotes notes;
    const Status s = parse_ply(ascii_triangle(c.properties, c.rows), "d.ply", &m, &notes);
    ASSERT_TRUE(s.ok()) << s.message();
    EXPECT_TRUE(m.attributes.empty()) << labels(m);
    EXPECT_EQ(notes.dropped_summary(), c.summary);
  }
  // A malformed value is still an error.
  const std::string rows[3] = {"0 0 1", "0 zero 1", "0 0 1"};
  Mesh m;
  EXPECT_EQ(parse_ply(ascii_triangle("property float nx\nproperty float ny\nproperty float nz\n", rows), "e.ply", &m)
                .message(),
            "e.ply:14: vertex 1: bad value 'zero' for property 'ny'");
}

TEST(PlyAttributesTest, AsciiFloatValuesAreRoundedToFloat) {
  const std::string rows[3] = {"0.1", "0.2", "0.3"};
  Mesh m;
  ASSERT_TRUE(parse_ply(ascii_triangle("property float quality\n", rows), "f.ply", &m).ok());
  EXPECT_EQ(m.attributes[0].values,
            (std::vector<double>{static_cast<double>(0.1f), static_cast<double>(0.2f), static_cast<double>(0.3f)}));
}

// A mesh with every kind, several types and generics, for the round trips.
Mesh attributed_torus() {
  Mesh m = testing_util::torus(8, 5);
  const size_t n = static_cast<size_t>(m.num_vertices());
  auto add = [&m, n](AttributeKind kind, ValueType type, const char* name, int components, double scale) {
    MeshAttribute a;
    a.kind = kind;
    a.type = type;
    a.name = name;
    a.components = components;
    for (size_t i = 0; i < n * static_cast<size_t>(components); ++i) {
      const double x = std::fmod(static_cast<double>(i) * 0.37, 1.0) * scale;
      a.values.push_back(type == ValueType::kFloat32 ? static_cast<double>(static_cast<float>(x))
                         : is_integer_type(type)     ? std::floor(x) + 0.0  // not -0
                                                     : x);
    }
    m.attributes.push_back(a);
  };
  add(AttributeKind::kNormal, ValueType::kFloat32, "", 3, 2.0);
  add(AttributeKind::kTexCoord, ValueType::kFloat64, "", 2, 1.0);
  add(AttributeKind::kColor, ValueType::kUint8, "", 4, 255.0);
  add(AttributeKind::kGeneric, ValueType::kInt8, "offset", 1, 100.0);
  add(AttributeKind::kGeneric, ValueType::kUint32, "id", 1, 4e9);
  add(AttributeKind::kGeneric, ValueType::kFloat32, "weights", 4, 1.0);
  add(AttributeKind::kGeneric, ValueType::kInt16, "pair", 2, -3000.0);
  return m;
}

TEST(PlyAttributesTest, RoundTripsEveryEncodingExactly) {
  const Mesh m = attributed_torus();
  ASSERT_TRUE(validate_mesh(m, "m").ok());
  for (PlyEncoding e : {PlyEncoding::kAscii, PlyEncoding::kBinaryLittleEndian, PlyEncoding::kBinaryBigEndian}) {
    PlyWriteOptions o;
    o.encoding = e;
    MeshWriteNotes notes;
    const std::string bytes = format_ply(m, o, &notes);
    EXPECT_TRUE(notes.empty()) << notes.not_written_summary();
    Mesh back;
    MeshReadNotes read_notes;
    const Status s = parse_ply(bytes, "r.ply", &back, &read_notes);
    ASSERT_TRUE(s.ok()) << s.message();
    EXPECT_TRUE(read_notes.empty()) << read_notes.dropped_summary();
    EXPECT_EQ(back.positions, m.positions);
    EXPECT_EQ(back.triangles, m.triangles);
    EXPECT_TRUE(testing_util::same_attributes(back, m)) << static_cast<int>(e);
  }
}

TEST(PlyAttributesTest, WriterSpellsEachKindInItsTypeAndAvoidsTakenNames) {
  Mesh m = attributed_torus();
  PlyWriteOptions o;
  o.encoding = PlyEncoding::kAscii;
  std::string bytes = format_ply(m, o);
  const std::string header = bytes.substr(0, bytes.find("end_header"));
  EXPECT_NE(header.find("property float nx\nproperty float ny\nproperty float nz\nproperty double s\nproperty double "
                        "t\nproperty uchar red\nproperty uchar green\nproperty uchar blue\nproperty uchar alpha\n"
                        "property char offset\nproperty uint id\nproperty list uchar float weights\n"
                        "property list uchar short pair\n"),
            std::string::npos)
      << header;
  // A generic named "red" keeps its name; the colours take r g b a.
  m.attributes[3].name = "red";
  MeshWriteNotes notes;
  bytes = format_ply(m, o, &notes);
  EXPECT_TRUE(notes.empty()) << notes.not_written_summary();
  EXPECT_NE(bytes.find("property uchar r\nproperty uchar g\nproperty uchar b\nproperty uchar a\nproperty char red\n"),
            std::string::npos);
  Mesh back;
  ASSERT_TRUE(parse_ply(bytes, "r.ply", &back).ok());
  EXPECT_TRUE(testing_util::same_attributes(back, m));
  // A second attribute of a kind, or of a generic's name, is not written.
  m.attributes.push_back(m.attributes[0]);
  m.attributes.push_back(m.attributes[4]);
  bytes = format_ply(m, o, &notes);
  EXPECT_EQ(notes.not_written_summary(),
            "40 generic attribute 'id' (a property of that name is written already), 40 normals (PLY holds one of "
            "each kind)");
  // A texture coordinate's w: texture_u texture_v texture_w.
  Mesh uvw = testing_util::grid(1, 1);
  MeshAttribute t;
  t.kind = AttributeKind::kTexCoord;
  t.components = 3;
  t.values = {0, 0, 1, 1, 0, 2, 0, 1, 3, 1, 1, 4};
  uvw.attributes = {t};
  bytes = format_ply(uvw, o);
  EXPECT_NE(bytes.find("property float texture_u\nproperty float texture_v\nproperty float texture_w\n"),
            std::string::npos);
  ASSERT_TRUE(parse_ply(bytes, "w.ply", &back).ok());
  EXPECT_TRUE(testing_util::same_attributes(back, uvw));
}

TEST(PlyAttributesTest, PerCornerAttributesAreSplitAtTheirSeams) {
  // The square of two triangles whose shared diagonal 0-2 is a UV seam.
  Mesh m = testing_util::grid(1, 1);  // triangles (0 1 3) (0 3 2)
  MeshAttribute uv;
  uv.kind = AttributeKind::kTexCoord;
  uv.components = 2;
  uv.values = {0, 0, 1, 0, 1, 1, 0, 1, 0.5, 0.5, 0.875, 0.875};
  uv.corners = {0, 1, 2, 4, 5, 3};
  m.attributes = {uv};
  ASSERT_TRUE(validate_mesh(m, "m").ok());
  for (PlyEncoding e : {PlyEncoding::kAscii, PlyEncoding::kBinaryLittleEndian}) {
    PlyWriteOptions o;
    o.encoding = e;
    MeshWriteNotes notes;
    const std::string bytes = format_ply(m, o, &notes);
    EXPECT_EQ(notes.split_vertices, 2);
    Mesh back;
    ASSERT_TRUE(parse_ply(bytes, "s.ply", &back).ok());
    EXPECT_EQ(back.num_vertices(), 6);
    const Mesh split = split_attribute_seams(m);
    EXPECT_EQ(back.positions, split.positions);
    EXPECT_EQ(back.triangles, split.triangles);
    EXPECT_TRUE(testing_util::same_attributes(back, split));
  }
  // write_ply and write_mesh report it too, on success.
  const std::string path = testing_util::temp_path("split.ply");
  MeshWriteNotes notes;
  ASSERT_TRUE(write_ply(path, m, PlyWriteOptions(), &notes).ok());
  EXPECT_EQ(notes.split_vertices, 2);
  std::remove(path.c_str());
}

TEST(PlyAttributesTest, WriterRefusesFloatValuesBeyondFloat) {
  Mesh m = testing_util::grid(1, 1);
  MeshAttribute q;
  q.kind = AttributeKind::kGeneric;
  q.name = "q";
  q.values = {0, 1e39, 0, 0};
  m.attributes = {q};
  const std::string path = testing_util::temp_path("big.ply");
  EXPECT_EQ(write_ply(path, m).message(), path + ": generic:q: element 1: value does not fit a float");
  EXPECT_FALSE(testing_util::exists(path));
  m.attributes[0].type = ValueType::kFloat64;
  EXPECT_TRUE(write_ply(path, m).ok());
  std::remove(path.c_str());
}

}  // namespace
}  // namespace gab
