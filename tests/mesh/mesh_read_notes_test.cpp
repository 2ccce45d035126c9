// What the readers did not keep (MeshReadNotes) and what they forgave:
// exact counts per format (normals, texture coordinates, colours and other
// PLY vertex properties are carried as attributes, and not named), the line ends real exporters write (LF, CRLF, a
// lone CR, also in a binary PLY's header), unknown PLY header lines. The
// inputs are written here, after the features of Draco's test files
// (cube_att.obj, test_pos_color.ply, Box.ply and delim_test.ply: Rhino's CR
// lines) and assimp's (Wuson.ply's "Created by" line); assimp-testmodels'
// own files are read when the package is installed.
#include "gab/mesh/mesh_read_notes.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <string>

#include "gab/mesh/mesh_io.h"
#include "mesh_test_util.h"

namespace gab {
namespace {

// "key=count key=count ..." in the notes' order.
std::string counts(const MeshReadNotes& notes) {
  std::string out;
  for (const DroppedData& d : notes.dropped) out += (out.empty() ? "" : " ") + d.key + "=" + std::to_string(d.count);
  return out;
}

Status parse(const std::string& text, MeshFormat format, Mesh* mesh, MeshReadNotes* notes) {
  return parse_mesh(text, format, "in", mesh, notes);
}

// Every line end in `text` ('\n') replaced by `end`.
std::string with_line_ends(const std::string& text, const std::string& end) {
  std::string out;
  for (char c : text) {
    if (c == '\n') {
      out += end;
    } else {
      out += c;
    }
  }
  return out;
}

// An OBJ with every kind of record, carried or not.
const std::string kObjEverything =
    "# a cube corner, with everything\n"
    "mtllib cube.mtl\n"
    "o corner\n"
    "v 0 0 0 1 0 0\n"
    "v 1 0 0 0 1 0\n"
    "v 0 1 0 0 0 1\n"
    "v 1 1 0 1\n"
    "vn 0 0 1\n"
    "vn 0 0 -1\n"
    "vt 0 0\n"
    "vt 1 0\n"
    "vt 0 1\n"
    "vp 0.5 0.5\n"
    "g side\n"
    "usemtl red\n"
    "s 1\n"
    "f 1/1/1 2/2/1 3/3/1\n"
    "s off\n"
    "f 2//2 4//2 3//2\n"
    "usemtl blue\n"
    "f 1/1 2/2 4/3 3/1\n"
    "f 1 2 4\n"
    "l 1 2\n"
    "p 3\n"
    "curv 0 1 1 2\n";

TEST(MeshReadNotesTest, ObjCountsEveryKindItDoesNotCarry) {
  Mesh mesh;
  MeshReadNotes notes;
  ASSERT_TRUE(parse(kObjEverything, MeshFormat::kObj, &mesh, &notes).ok());
  EXPECT_EQ(mesh.num_vertices(), 4);
  EXPECT_EQ(mesh.num_triangles(), 5);
  // vn and vt are carried (per corner); colours are not on every vertex.
  ASSERT_EQ(mesh.attributes.size(), 2u);
  EXPECT_EQ(attribute_label(mesh.attributes[0]), "normals");
  EXPECT_EQ(attribute_label(mesh.attributes[1]), "texture_coordinates");
  EXPECT_EQ(counts(notes),
            "vertex_colors=3 parameter_vertices=1 vertex_weights=1 polygons=1 lines=1 points=1 groups=1 objects=1 "
            "smoothing_groups=1 material_libraries=1 material_uses=2 other_records=1");
  EXPECT_EQ(notes.dropped_summary(),
            "3 vertex colours (v x y z r g b; not on every vertex), 1 parameter-space vertices (vp), 1 vertex weights "
            "(v x y z w), 1 polygons of 4 or more corners (fan-triangulated), 1 lines (l), 1 points (p), 1 groups (g), "
            "1 object names (o), 1 smoothing groups (s), 1 material libraries (mtllib), 2 material uses (usemtl), 1 "
            "other records (the first 'curv')");
  // Faces without vn or vt refer to an added element of zeros, and say so.
  ASSERT_EQ(notes.warnings.size(), 2u);
  EXPECT_EQ(notes.warnings[0],
            "in:21: 2 faces have no vn index; their corners refer to normal 3 (all zeros), added after the file's 2");
  EXPECT_EQ(notes.warnings[1], "in:19: 2 faces have no vt index; their corners refer to texture coordinate 4 (all "
                               "zeros), added after the file's 3");
}

// Draco's cube_att.obj in kind: v, vn, vt, faces v/vt/vn.
TEST(MeshReadNotesTest, ObjWithOnlyPositionsAndTrianglesDropsNothing) {
  Mesh mesh;
  MeshReadNotes notes;
  notes.warn("left from before");
  ASSERT_TRUE(parse("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", MeshFormat::kObj, &mesh, &notes).ok());
  EXPECT_TRUE(notes.empty()) << counts(notes);
  EXPECT_EQ(notes.dropped_summary(), "");
}

TEST(MeshReadNotesTest, ObjReadsLfCrlfAndCrLineEndsAlike) {
  Mesh lf;
  MeshReadNotes lf_notes;
  ASSERT_TRUE(parse(kObjEverything, MeshFormat::kObj, &lf, &lf_notes).ok());
  for (const std::string end : {"\r\n", "\r"}) {
    Mesh mesh;
    MeshReadNotes notes;
    const Status s = parse(with_line_ends(kObjEverything, end), MeshFormat::kObj, &mesh, &notes);
    ASSERT_TRUE(s.ok()) << s.message();
    EXPECT_EQ(mesh.positions, lf.positions);
    EXPECT_EQ(mesh.triangles, lf.triangles);
    EXPECT_EQ(counts(notes), counts(lf_notes));
  }
  // Errors still name the right line with CR line ends.
  Mesh mesh;
  const Status s = parse("v 0 0 0\rv 1 0 0\rv 0 1 0\rf 1 2 4\r", MeshFormat::kObj, &mesh, nullptr);
  EXPECT_EQ(s.message(), "in:4: face 0: vertex index 4 out of range [1, 3]");
}

// Draco's test_pos_color.ply and cube_att.ply in kind, with more.
const std::string kPlyEverything =
    "ply\n"
    "format ascii 1.0\n"
    "comment made by hand\n"
    "element vertex 4\n"
    "property float x\n"
    "property float y\n"
    "property float z\n"
    "property float nx\n"
    "property float ny\n"
    "property float nz\n"
    "property float s\n"
    "property float t\n"
    "property uchar red\n"
    "property uchar green\n"
    "property uchar blue\n"
    "property uchar alpha\n"
    "property float quality\n"
    "element face 2\n"
    "property list uchar int vertex_indices\n"
    "property uchar red\n"
    "property uchar green\n"
    "property uchar blue\n"
    "property int flags\n"
    "element edge 3\n"
    "property int vertex1\n"
    "property int vertex2\n"
    "element material 1\n"
    "property uchar ambient_red\n"
    "end_header\n"
    "0 0 0 0 0 1 0 0 255 0 0 255 0.5\n"
    "1 0 0 0 0 1 1 0 255 0 0 255 0.5\n"
    "0 1 0 0 0 1 0 1 255 0 0 255 0.5\n"
    "1 1 0 0 0 1 1 1 255 0 0 255 0.5\n"
    "4 0 1 3 2 9 9 9 0\n"
    "3 0 1 2 9 9 9 0\n"
    "0 1\n1 2\n2 0\n"
    "7\n";

TEST(MeshReadNotesTest, PlyCountsFacePropertiesAndOtherElements) {
  Mesh mesh;
  MeshReadNotes notes;
  const Status s = parse(kPlyEverything, MeshFormat::kPly, &mesh, &notes);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(mesh.num_vertices(), 4);
  EXPECT_EQ(mesh.num_triangles(), 3);
  // Every vertex property is carried: normals, texture coordinates,
  // colours, and 'quality' as a generic attribute.
  std::string labels;
  for (const MeshAttribute& a : mesh.attributes) labels += attribute_label(a) + " ";
  EXPECT_EQ(labels, "normals texture_coordinates vertex_colors generic:quality ");
  EXPECT_EQ(counts(notes), "face_colors=2 face.flags=2 element.edge=3 element.material=1 polygons=1");
  EXPECT_EQ(notes.dropped_summary(),
            "2 face colours (red green blue), 2 face property 'flags', 3 'edge' elements, 1 'material' elements, 1 "
            "polygons of 4 or more corners (fan-triangulated)");
  EXPECT_TRUE(notes.warnings.empty());
}

TEST(MeshReadNotesTest, PlyTextureCoordinatesUnderEachCommonName) {
  for (const std::string uv : {"u v", "texture_u texture_v", "texture_s texture_t"}) {
    const std::string u = uv.substr(0, uv.find(' ')), v = uv.substr(uv.find(' ') + 1);
    const std::string text = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                             "property float z\nproperty float " + u + "\nproperty float " + v +
                             "\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                             "0 0 0 0 0\n1 0 0 1 0\n0 1 0 0 1\n3 0 1 2\n";
    Mesh mesh;
    MeshReadNotes notes;
    ASSERT_TRUE(parse(text, MeshFormat::kPly, &mesh, &notes).ok()) << uv;
    EXPECT_TRUE(notes.empty()) << notes.dropped_summary();
    ASSERT_EQ(mesh.attributes.size(), 1u) << uv;
    EXPECT_EQ(mesh.attributes[0].kind, AttributeKind::kTexCoord) << uv;
    EXPECT_EQ(mesh.attributes[0].values, (std::vector<double>{0, 0, 1, 0, 0, 1})) << uv;
  }
}

// assimp's PLY/Wuson.ply has "Created by Blender3D 247 - www.blender3d.com"
// as its third line.
TEST(MeshReadNotesTest, PlyUnknownHeaderLineIsSkippedWithAWarning) {
  const std::string text =
      "ply\nformat ascii 1.0\nCreated by Blender3D 247 - www.blender3d.com\nelement vertex 3\nproperty float x\n"
      "property float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  Mesh mesh;
  MeshReadNotes notes;
  const Status s = parse(text, MeshFormat::kPly, &mesh, &notes);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(mesh.num_triangles(), 1);
  ASSERT_EQ(notes.warnings.size(), 1u);
  EXPECT_EQ(notes.warnings[0], "in:3: unknown header line 'Created by Blender3D 247 - www.b...' skipped");
  EXPECT_TRUE(notes.dropped.empty());
}

TEST(MeshReadNotesTest, ManyUnknownHeaderLinesKeepFewWarnings) {
  std::string text = "ply\nformat ascii 1.0\n";
  for (int i = 0; i < 20; ++i) text += "junk " + std::to_string(i) + "\n";
  text += "element vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\n"
          "property list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  Mesh mesh;
  MeshReadNotes notes;
  ASSERT_TRUE(parse(text, MeshFormat::kPly, &mesh, &notes).ok());
  EXPECT_EQ(notes.warnings.size(), MeshReadNotes::kMaxWarnings);
  EXPECT_EQ(notes.warnings_not_listed, 12);
  EXPECT_EQ(notes.warnings.back(), "in:10: unknown header line 'junk 7' skipped");
}

// Past kMaxMeshAttributes (64) generic attributes, properties are dropped,
// and the notes name at most 32 kinds.
TEST(MeshReadNotesTest, PlyWithManyPropertiesNamesAtMost32Kinds) {
  std::string text = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n";
  std::string zeros;
  for (int i = 0; i < 100; ++i) {
    text += "property uchar p" + std::to_string(i) + "\n";
    zeros += " 0";
  }
  text += "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  text += "0 0 0" + zeros + "\n1 0 0" + zeros + "\n0 1 0" + zeros + "\n3 0 1 2\n";
  Mesh mesh;
  MeshReadNotes notes;
  ASSERT_TRUE(parse(text, MeshFormat::kPly, &mesh, &notes).ok());
  ASSERT_EQ(mesh.attributes.size(), static_cast<size_t>(kMaxMeshAttributes));
  EXPECT_EQ(mesh.attributes.back().name, "p63");
  ASSERT_EQ(notes.dropped.size(), MeshReadNotes::kMaxNamedKinds + 1);
  EXPECT_EQ(notes.dropped[0].key, "vertex.p64");
  EXPECT_EQ(notes.dropped[31].key, "vertex.p95");
  EXPECT_EQ(notes.dropped[32].key, "other");
  EXPECT_EQ(notes.dropped[32].count, 4 * 3);
}

// The little-endian float whose first byte is 0x0A ('\n').
float newline_float() {
  const uint32_t bits = 0x3F80000Au;
  float f;
  std::memcpy(&f, &bits, sizeof(f));
  return f;
}

// A binary PLY (4 vertices, x y z float + an alpha, one quad) whose header
// lines end with `end`: the body starts with byte 0x0A.
std::string binary_quad(const std::string& end) {
  std::string header = "ply\nformat binary_little_endian 1.0\ncomment Created by Rhinoceros\nelement vertex 4\n"
                       "property float x\nproperty float y\nproperty float z\nproperty uchar transparency\n"
                       "element face 1\nproperty list uchar int vertex_index\nend_header\n";
  std::string out = with_line_ends(header, end);
  const float xyz[4][3] = {{newline_float(), 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}};
  for (const auto& p : xyz) {
    out.append(reinterpret_cast<const char*>(p), sizeof(p));
    out += '\x01';
  }
  out += '\x04';
  for (int32_t i = 0; i < 4; ++i) out.append(reinterpret_cast<const char*>(&i), sizeof(i));
  return out;
}

TEST(MeshReadNotesTest, BinaryPlyHeaderWithLfCrlfOrCrLines) {
  for (const std::string end : {"\n", "\r\n", "\r"}) {
    Mesh mesh;
    MeshReadNotes notes;
    const Status s = parse(binary_quad(end), MeshFormat::kPly, &mesh, &notes);
    ASSERT_TRUE(s.ok()) << s.message();
    ASSERT_EQ(mesh.num_vertices(), 4);
    EXPECT_EQ(mesh.positions[0], static_cast<double>(newline_float()));
    EXPECT_EQ(mesh.positions[3], 2.0);
    EXPECT_EQ(mesh.num_triangles(), 2);
    EXPECT_EQ(counts(notes), "polygons=1");
    ASSERT_EQ(mesh.attributes.size(), 1u);
    EXPECT_EQ(attribute_label(mesh.attributes[0]), "generic:transparency");
    EXPECT_EQ(mesh.attributes[0].type, ValueType::kUint8);
    EXPECT_EQ(mesh.attributes[0].values, (std::vector<double>{1, 1, 1, 1}));
  }
}

TEST(MeshReadNotesTest, AsciiPlyWithCrLinesNamesTheRightLine) {
  const std::string text = with_line_ends(
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 5\n",
      "\r");
  Mesh mesh;
  const Status s = parse(text, MeshFormat::kPly, &mesh, nullptr);
  EXPECT_EQ(s.message(), "in:13: face 0: vertex index 5 out of range [0, 3)");
}

TEST(MeshReadNotesTest, OffVertexExtrasFaceColoursAndPolygons) {
  // COFF: a colour per vertex; faces with and without their own colour.
  const std::string coff =
      "COFF\n4 3 0\n0 0 0 255 0 0 255\n1 0 0 255 0 0 255\n0 1 0 255 0 0 255\n1 1 0 255 0 0 255\n"
      "3 0 1 2 0.5 0.5 0.5\n3 1 3 2 # no colour\n4 0 1 3 2 1 0 0 1\n";
  Mesh lf;
  MeshReadNotes lf_notes;
  ASSERT_TRUE(parse(coff, MeshFormat::kOff, &lf, &lf_notes).ok());
  EXPECT_EQ(lf.num_triangles(), 4);
  EXPECT_EQ(lf_notes.dropped_summary(),
            "1 polygons of 4 or more corners (fan-triangulated), 2 face colours (after the indices)");
  EXPECT_EQ(counts(lf_notes), "polygons=1 face_colors=2");
  ASSERT_EQ(lf.attributes.size(), 1u);
  EXPECT_EQ(attribute_label(lf.attributes[0]), "vertex_colors");
  for (const std::string end : {"\r\n", "\r"}) {
    Mesh mesh;
    MeshReadNotes notes;
    const Status s = parse(with_line_ends(coff, end), MeshFormat::kOff, &mesh, &notes);
    ASSERT_TRUE(s.ok()) << s.message();
    EXPECT_EQ(mesh.positions, lf.positions);
    EXPECT_EQ(mesh.triangles, lf.triangles);
    ASSERT_EQ(mesh.attributes.size(), 1u);
    EXPECT_EQ(mesh.attributes[0].values, lf.attributes[0].values);
    EXPECT_EQ(counts(notes), counts(lf_notes));
  }
  const std::string tri_faces = "3 0 1 2\n";
  struct Case {
    std::string keyword, vertex_extra, expected;
  };
  // The prefixes' data is carried, not named.
  for (const Case& c : {Case{"NOFF", " 0 0 1", "normals "}, Case{"STOFF", " 0.5 0.5", "texture_coordinates "},
                        Case{"CNOFF", " 0 0 1 0.1 0.2 0.3", "normals vertex_colors "},
                        Case{"STCNOFF", " 0 0 1 0.1 0.2 0.3 0 0", "normals vertex_colors texture_coordinates "}}) {
    const std::string text = c.keyword + "\n3 1 0\n0 0 0" + c.vertex_extra + "\n1 0 0" + c.vertex_extra + "\n0 1 0" +
                             c.vertex_extra + "\n" + tri_faces;
    Mesh mesh;
    MeshReadNotes notes;
    ASSERT_TRUE(parse(text, MeshFormat::kOff, &mesh, &notes).ok()) << c.keyword;
    EXPECT_TRUE(notes.empty()) << c.keyword << ": " << notes.dropped_summary();
    std::string labels;
    for (const MeshAttribute& a : mesh.attributes) labels += attribute_label(a) + " ";
    EXPECT_EQ(labels, c.expected) << c.keyword;
  }
  // Errors name the right line with CR line ends.
  Mesh mesh;
  EXPECT_EQ(parse("OFF\r3 1 0\r0 0 0\r1 0 0\r0 1 0\r3 0 1 3\r", MeshFormat::kOff, &mesh, nullptr).message(),
            "in:6: face 0: vertex index 3 out of range [0, 3)");
}

// A failed read leaves the caller's notes as they were.
TEST(MeshReadNotesTest, FailedReadLeavesNotesAlone) {
  Mesh mesh;
  MeshReadNotes notes;
  notes.drop("normals", "normals (vn)", 5);
  EXPECT_FALSE(parse("vn 0 0 1\nv 0 0 0\nf 1 2 3\n", MeshFormat::kObj, &mesh, &notes).ok());
  EXPECT_EQ(counts(notes), "normals=5");
}

// Debian's assimp-testmodels, when installed (CI installs it).
const char* const kAssimpModels = "/usr/share/assimp/models";

TEST(MeshReadNotesTest, AssimpTestModels) {
  if (!testing_util::exists(std::string(kAssimpModels) + "/OBJ/spider.obj")) {
    GTEST_SKIP() << "assimp-testmodels is not installed (" << kAssimpModels << "/OBJ/spider.obj)";
  }
  Mesh mesh;
  MeshReadNotes notes;
  ASSERT_TRUE(read_mesh(std::string(kAssimpModels) + "/OBJ/spider.obj", &mesh, &notes).ok());
  EXPECT_EQ(mesh.num_vertices(), 762);
  EXPECT_EQ(counts(notes), "groups=19 smoothing_groups=169 material_libraries=1 material_uses=19");
  // Refused before: "unknown header keyword 'Created'".
  const std::string wuson = std::string(kAssimpModels) + "/PLY/Wuson.ply";
  const Status s = read_mesh(wuson, &mesh, &notes);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(counts(notes), "");
  ASSERT_EQ(notes.warnings.size(), 1u);
  EXPECT_EQ(notes.warnings[0], wuson + ":3: unknown header line 'Created by Blender3D 247 - www.b...' skipped");
}

}  // namespace
}  // namespace gab
