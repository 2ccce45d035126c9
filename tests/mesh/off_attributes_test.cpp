// OFF attributes: the N, C and ST prefixes' per-vertex data, the colours'
// type, the errors of a vertex line that does not fit its prefixes, and the
// prefixed form the writer chooses.
#include <gtest/gtest.h>

#include "gab/mesh/attribute_seams.h"
#include "gab/mesh/off_io.h"
#include "mesh_test_util.h"

namespace gab {
namespace {

std::string labels(const Mesh& m) {
  std::string out;
  for (const MeshAttribute& a : m.attributes) out += (out.empty() ? "" : " ") + attribute_label(a);
  return out;
}

// A triangle in the OFF form `keyword`, each vertex followed by `extra[v]`.
std::string off_triangle(const std::string& keyword, const std::string extra[3]) {
  return keyword + "\n3 1 0\n0 0 0 " + extra[0] + "\n1 0 0 " + extra[1] + "\n0 1 0 " + extra[2] + "\n3 0 1 2\n";
}

TEST(OffAttributesTest, EveryPrefixInItsOrder) {
  const std::string extra[3] = {"0 0 1 255 0 0 255 0.25 0.5", "0 0 1 0 255 0 128 1 0", "0 0.6 0.8 0 0 255 0 0 1"};
  Mesh m;
  MeshReadNotes notes;
  const Status s = parse_off(off_triangle("STCNOFF", extra), "a.off", &m, &notes);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_TRUE(notes.empty());
  EXPECT_EQ(labels(m), "normals vertex_colors texture_coordinates");
  EXPECT_EQ(m.attributes[0].values,
            (std::vector<double>{0, 0, 1, 0, 0, 1, 0, static_cast<double>(0.6f), static_cast<double>(0.8f)}));
  EXPECT_EQ(m.attributes[0].type, ValueType::kFloat32);
  EXPECT_EQ(m.attributes[1].type, ValueType::kUint8);
  EXPECT_EQ(m.attributes[1].components, 4);
  EXPECT_EQ(m.attributes[1].values, (std::vector<double>{255, 0, 0, 255, 0, 255, 0, 128, 0, 0, 255, 0}));
  EXPECT_EQ(m.attributes[2].components, 2);
  EXPECT_EQ(m.attributes[2].values, (std::vector<double>{0.25, 0.5, 1, 0, 0, 1}));
  EXPECT_TRUE(validate_mesh(m, "a.off").ok());
}

TEST(OffAttributesTest, ColourTypeFollowsTheFilesValues) {
  const struct {
    std::string extra[3];
    ValueType type;
    std::vector<double> values;
  } cases[] = {
      // Integers, one above 1: 0..255.
      {{"255 0 0", "0 2 0", "0 0 1"}, ValueType::kUint8, {255, 0, 0, 0, 2, 0, 0, 0, 1}},
      // No value above 1: fractions, as Geomview reads them.
      {{"1 0 0", "0 1 0", "0 0 1"}, ValueType::kFloat32, {1, 0, 0, 0, 1, 0, 0, 0, 1}},
      // A decimal point anywhere: fractions.
      {{"1 0.5 0", "0 1 0", "0 0 255"}, ValueType::kFloat32, {1, 0.5, 0, 0, 1, 0, 0, 0, 255}},
      // An integer beyond 255: not 0..255.
      {{"256 0 0", "0 1 0", "0 0 1"}, ValueType::kFloat32, {256, 0, 0, 0, 1, 0, 0, 0, 1}},
  };
  for (const auto& c : cases) {
    Mesh m;
    ASSERT_TRUE(parse_off(off_triangle("COFF", c.extra), "c.off", &m).ok());
    ASSERT_EQ(m.attributes.size(), 1u);
    EXPECT_EQ(m.attributes[0].type, c.type) << c.extra[0];
    EXPECT_EQ(m.attributes[0].values, c.values) << c.extra[0];
  }
}

TEST(OffAttributesTest, VertexLinesThatDoNotFitTheirPrefixesNameTheLine) {
  const struct {
    std::string keyword, extra[3], message;
  } cases[] = {
      {"COFF", {"255 0 0", "255 0", "0 0 255"}, "x.off:4: vertex 1: 2 values after the coordinates, COFF needs 3 or 4 (r g b [a])"},
      {"COFF", {"255 0 0 1 2", "255 0 0", "0 0 255"},
       "x.off:3: vertex 0: 5 values after the coordinates, COFF needs 3 or 4 (r g b [a])"},
      {"COFF", {"255 0 0", "255 0 0 255", "0 0 255"}, "x.off:4: vertex 1: 4 colour values where vertex 0 has 3"},
      {"NOFF", {"0 0 1", "0 0", "0 0 1"}, "x.off:4: vertex 1: 2 values after the coordinates, NOFF needs 3 (nx ny nz)"},
      {"STCNOFF", {"0 0 1 1 1 1 0 0", "0 0 1 1 1 1", "0 0 1 1 1 1 0 0"},
       "x.off:4: vertex 1: 6 values after the coordinates, STCNOFF needs 8 or 9 (nx ny nz r g b [a] s t)"},
      {"STOFF", {"0 0", "0 x", "0 0"}, "x.off:4: vertex 1: bad texture coordinate 'x'"},
      {"CNOFF", {"0 0 1 1 1 1", "0 0 1 1 one 1", "0 0 1 1 1 1"}, "x.off:4: vertex 1: bad colour value 'one'"},
      {"NOFF", {"0 0 1", "0 0 1 # a comment", "0 z 1"}, "x.off:5: vertex 2: bad normal value 'z'"},
  };
  for (const auto& c : cases) {
    Mesh m;
    const Status s = parse_off(off_triangle(c.keyword, c.extra), "x.off", &m);
    EXPECT_EQ(s.code(), StatusCode::kParseError) << c.message;
    EXPECT_EQ(s.message(), c.message);
  }
  // Dimensions other than 3 stay refused.
  Mesh m;
  EXPECT_EQ(parse_off("nOFF 4\n3 1 0\n", "x.off", &m).message(), "x.off:1: nOFF dimension '4' is not supported (only 3)");
}

TEST(OffAttributesTest, NotFiniteValuesDropTheirAttributeWithANote) {
  const std::string extra[3] = {"0 0 1 0.5 0.5", "inf 0 1 0 0", "0 0 1 1 1"};
  Mesh m;
  MeshReadNotes notes;
  ASSERT_TRUE(parse_off(off_triangle("STNOFF", extra), "n.off", &m, &notes).ok());
  EXPECT_EQ(labels(m), "texture_coordinates");
  EXPECT_EQ(notes.dropped_summary(), "3 normals (STNOFF; line 4 has a value that is not finite)");
}

TEST(OffAttributesTest, ReadWriteReadIsExact) {
  const std::string forms[] = {
      "STCNOFF\n3 1 0\n0 0 0 0 0 1 255 0 0 255 0.25 0.5\n1 0 0 0 0 1 0 255 0 128 1 0\n0 1 0 0 0.6 0.8 0 0 255 0 0 1\n"
      "3 0 1 2\n",
      "COFF\n3 1 0\n0 0 0 1 0.5 0\n1 0 0 0 1 0\n0 1 0 0.1 0.2 0.3\n3 0 1 2\n",
      "COFF\n3 1 0\n0 0 0 2 0 0\n1 0 0 0 1 0\n0 1 0 0 0 1\n3 0 1 2\n",
      "NOFF\n3 1 0\n0 0 0 1e-5 2e38 -0\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n",
  };
  for (const std::string& text : forms) {
    Mesh m;
    ASSERT_TRUE(parse_off(text, "r.off", &m).ok()) << text;
    MeshWriteNotes notes;
    const std::string written = format_off(m, &notes);
    EXPECT_TRUE(notes.empty()) << notes.not_written_summary();
    EXPECT_EQ(written.substr(0, written.find('\n')), text.substr(0, text.find('\n')));  // the same prefixes
    Mesh back;
    ASSERT_TRUE(parse_off(written, "back.off", &back).ok()) << written;
    EXPECT_EQ(back.positions, m.positions);
    EXPECT_EQ(back.triangles, m.triangles);
    EXPECT_TRUE(testing_util::same_attributes(back, m)) << written;
  }
}

TEST(OffAttributesTest, WriterText) {
  Mesh m;
  ASSERT_TRUE(parse_off("STCOFF\n3 1 0\n0 0 0 1 0.5 0 0.25 0.5\n1 0 0 0 1 0 1 0\n0 1 0 0 0 1 0 1\n3 0 1 2\n", "w.off",
                        &m).ok());
  // Fractions keep a decimal point, so that they read back as fractions.
  EXPECT_EQ(format_off(m), "STCOFF\n3 1 0\n0 0 0 1.0 0.5 0.0 0.25 0.5\n1 0 0 0.0 1.0 0.0 1 0\n0 1 0 0.0 0.0 1.0 0 1\n"
                           "3 0 1 2\n");
}

TEST(OffAttributesTest, WriterSplitsSeamsAndNamesWhatOffCannotHold) {
  Mesh m = testing_util::grid(1, 1);  // triangles (0 1 3) (0 3 2)
  MeshAttribute normal;
  normal.kind = AttributeKind::kNormal;
  normal.components = 3;
  normal.values = {0, 0, 1, 0, 0, -1};
  normal.corners = {0, 0, 0, 1, 1, 1};  // vertices 0 and 3 on the crease
  MeshAttribute uvw;
  uvw.kind = AttributeKind::kTexCoord;
  uvw.components = 3;
  uvw.values = {0, 0, 0.5, 1, 0, 0, 0, 1, 0, 1, 1, 0};
  MeshAttribute color;  // uchar, none above 1: written as fractions
  color.kind = AttributeKind::kColor;
  color.type = ValueType::kUint8;
  color.components = 3;
  color.values = {1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1};
  MeshAttribute quality;
  quality.kind = AttributeKind::kGeneric;
  quality.name = "quality";
  quality.values = {1, 2, 3, 4};
  m.attributes = {normal, uvw, color, quality};
  ASSERT_TRUE(validate_mesh(m, "m").ok());
  MeshWriteNotes notes;
  const std::string text = format_off(m, &notes);
  EXPECT_EQ(notes.split_vertices, 2);
  EXPECT_EQ(notes.not_written_summary(),
            "4 generic attribute 'quality' (OFF has no place for it), 4 texture coordinate w values (OFF holds s t)");
  EXPECT_EQ(text.substr(0, text.find('\n', text.find('\n') + 1)), "STCNOFF\n6 2 0");
  Mesh back;
  ASSERT_TRUE(parse_off(text, "back.off", &back).ok());
  const Mesh split = split_attribute_seams(m);
  EXPECT_EQ(back.triangles, split.triangles);
  ASSERT_EQ(labels(back), "normals vertex_colors texture_coordinates");
  EXPECT_EQ(back.attributes[0].values, split.attributes[0].values);
  EXPECT_EQ(back.attributes[1].type, ValueType::kFloat32);
  EXPECT_EQ(back.attributes[1].values[0], static_cast<double>(static_cast<float>(1.0 / 255)));
}

}  // namespace
}  // namespace gab
