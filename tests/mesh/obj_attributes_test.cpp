// OBJ attributes: vn and vt per corner with their own indices, colours of
// `v x y z r g b`, what is noted, the errors, and the writer.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "gab/mesh/obj_io.h"
#include "mesh_test_util.h"

namespace gab {
namespace {

// Two triangles sharing the edge 2-3; vertex 1's corners use different
// texture coordinates (a seam) and the faces different normals.
const std::string kSeam =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
    "vt 0 0\nvt 0.25 0\nvt 0.5 0.5\nvt 0 0.5\nvt 0.75 0\n"
    "vn 0 0 1\nvn 0 0 -1\n"
    "f 1/1/1 2/2/1 3/3/1\n"
    "f 2/5/2 4/4/2 3/3/2\n";

TEST(ObjAttributesTest, NormalsAndTexcoordsPerCornerWithTheirOwnIndices) {
  Mesh m;
  MeshReadNotes notes;
  const Status s = parse_obj(kSeam, "seam.obj", &m, &notes);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_TRUE(notes.empty()) << notes.dropped_summary();
  ASSERT_EQ(m.attributes.size(), 2u);
  const MeshAttribute& n = m.attributes[0];
  const MeshAttribute& uv = m.attributes[1];
  EXPECT_EQ(n.kind, AttributeKind::kNormal);
  EXPECT_EQ(n.type, ValueType::kFloat32);
  EXPECT_EQ(n.values, (std::vector<double>{0, 0, 1, 0, 0, -1}));
  EXPECT_EQ(n.corners, (std::vector<int32_t>{0, 0, 0, 1, 1, 1}));
  EXPECT_EQ(uv.kind, AttributeKind::kTexCoord);
  EXPECT_EQ(uv.components, 2);
  EXPECT_EQ(uv.values, (std::vector<double>{0, 0, 0.25, 0, 0.5, 0.5, 0, 0.5, 0.75, 0}));
  EXPECT_EQ(uv.corners, (std::vector<int32_t>{0, 1, 2, 4, 3, 2}));
  EXPECT_TRUE(validate_mesh(m, "seam.obj").ok());
}

TEST(ObjAttributesTest, FannedPolygonsKeepEachCornersElements) {
  // A pentagon with relative and forward indices: the fan (0 1 2) (0 2 3)
  // (0 3 4) takes each polygon corner's vt.
  const std::string text =
      "vt 0 0\nvt 1 0\nv 0 0 0\nv 1 0 0\nv 1 1 0\nvt 1 1\nvt 0 1\n"
      "f 1/-4 2/-3 3/-2 4/4 5/5\n"
      "v 0 1 0\nv -1 0.5 0\nvt 0.5 0.5\n";
  Mesh m;
  const Status s = parse_obj(text, "fan.obj", &m);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(m.triangles, (std::vector<int32_t>{0, 1, 2, 0, 2, 3, 0, 3, 4}));
  ASSERT_EQ(m.attributes.size(), 1u);
  EXPECT_EQ(m.attributes[0].corners, (std::vector<int32_t>{0, 1, 2, 0, 2, 3, 0, 3, 4}));
  EXPECT_EQ(m.attributes[0].num_elements(), 5);
}

TEST(ObjAttributesTest, TexcoordWOnlyWhenOneIsNotZero) {
  const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1 2/2 3/3\n";
  Mesh m;
  ASSERT_TRUE(parse_obj("vt 0.5\nvt 1 0 0\nvt 0 1 0\n" + tri, "w.obj", &m).ok());
  EXPECT_EQ(m.attributes[0].components, 2);
  EXPECT_EQ(m.attributes[0].values, (std::vector<double>{0.5, 0, 1, 0, 0, 1}));  // vt u: v is 0
  ASSERT_TRUE(parse_obj("vt 0.5 0 0\nvt 1 0 0.25\nvt 0 1\n" + tri, "w.obj", &m).ok());
  EXPECT_EQ(m.attributes[0].components, 3);
  EXPECT_EQ(m.attributes[0].values, (std::vector<double>{0.5, 0, 0, 1, 0, 0.25, 0, 1, 0}));
}

TEST(ObjAttributesTest, FacesWithoutAnIndexReferToAnAddedElement) {
  // The second face has no vt: its corners refer to a zero element added
  // after the file's two, and a warning says so.
  const std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0.5 0.5\nvt 1 1\nf 1/1 2/2 3/1\nf 2 4 3\n";
  Mesh m;
  MeshReadNotes notes;
  ASSERT_TRUE(parse_obj(text, "some.obj", &m, &notes).ok());
  ASSERT_EQ(m.attributes.size(), 1u);
  EXPECT_EQ(m.attributes[0].values, (std::vector<double>{0.5, 0.5, 1, 1, 0, 0}));
  EXPECT_EQ(m.attributes[0].corners, (std::vector<int32_t>{0, 1, 0, 2, 2, 2}));
  EXPECT_TRUE(notes.dropped.empty()) << notes.dropped_summary();
  ASSERT_EQ(notes.warnings.size(), 1u);
  EXPECT_EQ(notes.warnings[0], "some.obj:8: 1 faces have no vt index; their corners refer to texture coordinate 3 "
                               "(all zeros), added after the file's 2");
}

TEST(ObjAttributesTest, RecordsNoFaceRefersToAreNoted) {
  Mesh m;
  MeshReadNotes notes;
  ASSERT_TRUE(parse_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nvt 0 0\nvt 1 1\nf 1 2 3\n", "n.obj", &m, &notes).ok());
  EXPECT_TRUE(m.attributes.empty());
  EXPECT_EQ(notes.dropped_summary(),
            "1 normals (vn; no face refers to them), 2 texture coordinates (vt; no face refers to them)");
  EXPECT_TRUE(notes.warnings.empty());
}

TEST(ObjAttributesTest, VertexColoursWhenEveryVertexHasThem) {
  Mesh m;
  MeshReadNotes notes;
  ASSERT_TRUE(parse_obj("v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 0.1\nf 1 2 3\n", "c.obj", &m, &notes).ok());
  EXPECT_TRUE(notes.empty());
  ASSERT_EQ(m.attributes.size(), 1u);
  const MeshAttribute& c = m.attributes[0];
  EXPECT_EQ(c.kind, AttributeKind::kColor);
  EXPECT_EQ(c.type, ValueType::kFloat32);
  EXPECT_FALSE(c.per_corner());
  // Values are the decimals rounded to float.
  EXPECT_EQ(c.values, (std::vector<double>{1, 0, 0, 0, 1, 0, 0, 0, static_cast<double>(0.1f)}));
  ASSERT_TRUE(parse_obj("v 0 0 0 1 0 0\nv 1 0 0\nv 0 1 0 0 0 1\nf 1 2 3\n", "c.obj", &m, &notes).ok());
  EXPECT_TRUE(m.attributes.empty());
  EXPECT_EQ(notes.dropped_summary(), "2 vertex colours (v x y z r g b; not on every vertex)");
}

TEST(ObjAttributesTest, ValuesBeyondFloatStayDoubleAndNotFiniteOnesAreNoted) {
  const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  Mesh m;
  MeshReadNotes notes;
  ASSERT_TRUE(parse_obj(tri + "vt 1e39 0.1\nf 1/1 2/1 3/1\n", "big.obj", &m, &notes).ok());
  ASSERT_EQ(m.attributes.size(), 1u);
  EXPECT_EQ(m.attributes[0].type, ValueType::kFloat64);
  EXPECT_EQ(m.attributes[0].values, (std::vector<double>{1e39, 0.1}));
  ASSERT_TRUE(parse_obj(tri + "vn 0 0 1\nvn nan 0 1\nf 1//1 2//2 3//1\n", "nan.obj", &m, &notes).ok());
  EXPECT_TRUE(m.attributes.empty());
  EXPECT_EQ(notes.dropped_summary(), "2 normals (vn; line 5 has a value that is not finite)");
}

TEST(ObjAttributesTest, MalformedAttributeDataNamesTheLine) {
  const std::string v3 = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  const struct {
    std::string text, message;
  } cases[] = {
      {v3 + "vt 0 0\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/4\n", "x.obj:7: face 0: texture coordinate index 4 out of range [1, 3]"},
      {v3 + "vn 0 0 1\nf 1//1 2//1 3//2\n", "x.obj:5: face 0: normal index 2 out of range [1, 1]"},
      {v3 + "vt 0 0\nf 1/1 2/-2 3/1\n",
       "x.obj:5: face 0: relative texture coordinate index -2 reaches before the first texture coordinate (1 defined "
       "so far)"},
      {v3 + "vt 0 0\nf 1/0 2/1 3/1\n", "x.obj:5: face 0: texture coordinate index 0 (OBJ indices start at 1)"},
      {v3 + "vn 0 0 1\nf 1//0 2//1 3//1\n", "x.obj:5: face 0: normal index 0 (OBJ indices start at 1)"},
      {v3 + "vn 0 1\nf 1//1 2//1 3//1\n", "x.obj:4: normal 0: needs 3 values, has 2"},
      {v3 + "vn 0 0 1\nvn 0 x 1\nf 1//1 2//1 3//1\n", "x.obj:5: normal 1: bad value 'x'"},
      {v3 + "vt \nf 1/1 2/1 3/1\n", "x.obj:4: texture coordinate 0: needs 1 to 3 values, has 0"},
      {v3 + "vt 0 0.5.5\nf 1/1 2/1 3/1\n", "x.obj:4: texture coordinate 0: bad value '0.5.5'"},
      {"v 0 0 0 1 0 0\nv 1 0 0 1 red 0\nv 0 1 0 0 0 1\nf 1 2 3\n", "x.obj:2: colour of vertex 1: bad value 'red'"},
      {v3 + "f 1/1/1/1 2 3\n", "x.obj:4: face 0: bad vertex index '1/1/1/1'"},
      {v3 + "vt 0 0\nf 1/99999999999 2/1 3/1\n", "x.obj:5: face 0: bad vertex index '1/99999999999'"},
  };
  for (const auto& c : cases) {
    Mesh m;
    const Status s = parse_obj(c.text, "x.obj", &m);
    EXPECT_EQ(s.code(), StatusCode::kParseError) << c.text;
    EXPECT_EQ(s.message(), c.message);
  }
}

TEST(ObjAttributesTest, ReadWriteReadKeepsSeamsExactly) {
  Mesh m;
  ASSERT_TRUE(parse_obj(kSeam + "v 2 2 2\n", "seam.obj", &m).ok());  // and an isolated vertex
  MeshWriteNotes notes;
  const std::string text = format_obj(m, &notes);
  EXPECT_TRUE(notes.empty()) << notes.not_written_summary();
  EXPECT_EQ(text,
            "# written by gab\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 2 2\n"
            "vt 0 0\nvt 0.25 0\nvt 0.5 0.5\nvt 0 0.5\nvt 0.75 0\nvn 0 0 1\nvn 0 0 -1\n"
            "f 1/1/1 2/2/1 3/3/1\nf 2/5/2 4/4/2 3/3/2\n");
  Mesh back;
  ASSERT_TRUE(parse_obj(text, "back.obj", &back).ok());
  EXPECT_EQ(back.positions, m.positions);
  EXPECT_EQ(back.triangles, m.triangles);
  EXPECT_TRUE(testing_util::same_attributes(back, m));
}

TEST(ObjAttributesTest, FloatValuesReadBackExactly) {
  // Values with all of a float's digits, and colours, through text twice.
  Mesh m = testing_util::grid(3, 2);
  MeshAttribute uv;
  uv.kind = AttributeKind::kTexCoord;
  uv.components = 2;
  MeshAttribute color;
  color.kind = AttributeKind::kColor;
  color.components = 3;
  for (int v = 0; v < m.num_vertices(); ++v) {
    for (int c = 0; c < 3; ++c) {
      const float f = std::nextafter(static_cast<float>(0.1 * v + 0.01 * c), 1.0f);
      if (c < 2) uv.values.push_back(f * 7.0f);
      color.values.push_back(f);
    }
  }
  m.attributes = {uv, color};
  Mesh back;
  ASSERT_TRUE(parse_obj(format_obj(m), "f.obj", &back).ok());
  ASSERT_EQ(back.attributes.size(), 2u);
  EXPECT_EQ(back.attributes[0].values, uv.values);  // now per corner, indexed as the vertices
  EXPECT_EQ(back.attributes[0].corners, m.triangles);
  EXPECT_EQ(back.attributes[1].values, color.values);
}

TEST(ObjAttributesTest, WriterIndexesPerVertexDataByVertexAndNamesWhatItCannotHold) {
  Mesh m;
  m.positions = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  m.triangles = {0, 1, 2};
  MeshAttribute normal;
  normal.kind = AttributeKind::kNormal;
  normal.components = 3;
  normal.values = {0, 0, 1, 0, 0, 1, 0, 0.5, 1};
  MeshAttribute color;  // uchar with alpha: fractions, the alpha not written
  color.kind = AttributeKind::kColor;
  color.type = ValueType::kUint8;
  color.components = 4;
  color.values = {255, 0, 0, 128, 0, 51, 0, 128, 0, 0, 255, 128};
  MeshAttribute quality;
  quality.kind = AttributeKind::kGeneric;
  quality.name = "quality";
  quality.values = {1, 2, 3};
  MeshAttribute second_normal = normal;
  m.attributes = {normal, color, quality, second_normal};
  ASSERT_TRUE(validate_mesh(m, "m").ok());
  MeshWriteNotes notes;
  EXPECT_EQ(format_obj(m, &notes),
            "# written by gab\nv 0 0 0 1 0 0\nv 1 0 0 0 0.2 0\nv 0 1 0 0 0 1\n"
            "vn 0 0 1\nvn 0 0 1\nvn 0 0.5 1\nf 1//1 2//2 3//3\n");
  EXPECT_EQ(notes.not_written_summary(),
            "3 generic attribute 'quality' (OBJ has no place for it), 3 normals (OBJ holds one of each kind), 3 colour "
            "alpha values (OBJ holds r g b)");
  EXPECT_EQ(notes.split_vertices, 0);
}

TEST(ObjAttributesTest, PerCornerColoursAreSplit) {
  Mesh m;
  m.positions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  m.triangles = {0, 1, 2, 0, 2, 3};
  MeshAttribute color;
  color.kind = AttributeKind::kColor;
  color.components = 3;
  color.values = {1, 0, 0, 0, 1, 0};
  color.corners = {0, 0, 0, 1, 1, 1};  // vertices 0 and 2 on the seam
  m.attributes = {color};
  MeshWriteNotes notes;
  const std::string text = format_obj(m, &notes);
  EXPECT_EQ(notes.split_vertices, 2);
  EXPECT_TRUE(notes.not_written.empty());
  EXPECT_EQ(text,
            "# written by gab\nv 0 0 0 1 0 0\nv 1 0 0 1 0 0\nv 1 1 0 1 0 0\nv 0 1 0 0 1 0\nv 0 0 0 0 1 0\n"
            "v 1 1 0 0 1 0\nf 1 2 3\nf 5 6 4\n");
}

TEST(ObjAttributesTest, WriteObjReportsOnlyOnSuccess) {
  Mesh m = testing_util::grid(1, 1);
  MeshAttribute quality;
  quality.kind = AttributeKind::kGeneric;
  quality.name = "quality";
  quality.values = {1, 2, 3, 4};
  m.attributes = {quality};
  const std::string path = testing_util::temp_path("generic.obj");
  MeshWriteNotes notes;
  ASSERT_TRUE(write_obj(path, m, &notes).ok());
  EXPECT_EQ(notes.not_written_summary(), "4 generic attribute 'quality' (OBJ has no place for it)");
  ASSERT_EQ(notes.not_written.size(), 1u);
  EXPECT_EQ(notes.not_written[0].key, "generic:quality");
  std::remove(path.c_str());
}

}  // namespace
}  // namespace gab
