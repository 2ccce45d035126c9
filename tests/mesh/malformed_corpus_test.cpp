// A corpus of malformed and hostile files, generated here: every one must be
// refused with its own clear message naming the file and the line (text) or
// the element (binary), and must leave the output mesh untouched.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstring>
#include <set>
#include <string>

#include "gab/mesh/mesh_io.h"
#include "gab/mesh/obj_io.h"
#include "gab/mesh/off_io.h"
#include "mesh_test_util.h"

namespace gab {
namespace {

struct Hostile {
  MeshFormat format;
  std::string bytes;
  std::string message;  // exact, after the file name
};

std::string ply_header(const std::string& format, const std::string& body) {
  return "ply\nformat " + format + " 1.0\n" + body;
}
const std::string kVertexXyz = "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n";
const std::string kFaceList = "element face 1\nproperty list uchar int vertex_indices\n";
const std::string kAsciiTriangle = ply_header("ascii", kVertexXyz + kFaceList + "end_header\n");

std::string le32(uint32_t v) {
  std::string s(4, '\0');
  for (int i = 0; i < 4; ++i) s[i] = static_cast<char>((v >> (8 * i)) & 0xff);
  return s;
}
std::string le_float(float f) {
  uint32_t u;
  std::memcpy(&u, &f, 4);
  return le32(u);
}
// Three vertices (0 0 0), (1 0 0), (0 1 0) in binary little-endian floats.
std::string binary_vertices(float y1 = 0.0f) {
  std::string s;
  for (float c : {0.0f, 0.0f, 0.0f, 1.0f, y1, 0.0f, 0.0f, 1.0f, 0.0f}) s += le_float(c);
  return s;
}
const std::string kBinaryTriangle = ply_header("binary_little_endian", kVertexXyz + kFaceList + "end_header\n");

std::vector<Hostile> corpus() {
  const MeshFormat OFF = MeshFormat::kOff, PLY = MeshFormat::kPly, OBJ = MeshFormat::kObj;
  const std::string tri = "0 0 0\n1 0 0\n0 1 0\n";
  const std::string v3 = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  return {
      // ---- OFF ----
      {OFF, "", ":1: empty file, expected an OFF header"},
      {OFF, "   \n# only a comment\n", ":3: empty file, expected an OFF header"},
      {OFF, "OFF", ":1: truncated header: expected vertex, face and edge counts"},
      {OFF, "OFF BINARY\n\x01\x02", ":1: binary OFF is not supported"},
      {OFF, "nOFF 4\n3 1 0\n", ":1: nOFF dimension '4' is not supported (only 3)"},
      {OFF, "OFF\n3 x 0\n", ":2: bad count 'x' in header"},
      {OFF, "OFF\n99999999999999999999 1 0\n", ":2: bad count '99999999999999999999' in header"},
      {OFF, "OFF\n1000000 1 0\n0 0 0\n",
       ":2: header claims 1000000 vertices and 1 faces, more than the file's 22 bytes can hold"},
      {OFF, "OFF\n3 0 0\n" + tri, ":2: mesh has no faces"},
      {OFF, "OFF\n3 1 0\n0 0 0\n1 0 inf\n0 1 0\n3 0 1 2\n", ":4: vertex 1: coordinate is not finite"},
      {OFF, "OFF\n3 1 0\n0 0 0\n1 0 1e999\n0 1 0\n3 0 1 2\n", ":4: vertex 1: coordinate is not finite"},
      {OFF, "OFF\n3 1 0\n0 0 0\n1 0 0x1F\n0 1 0\n3 0 1 2\n", ":4: vertex 1: bad coordinate '0x1F'"},
      {OFF, "4OFF\n3 1 0\n0 0 0 1\n1 0 0 0\n0 1 0 1\n3 0 1 2\n", ":4: vertex 1: homogeneous coordinate w is 0"},
      {OFF, "OFF\n3 1 0\n" + tri + "3 0 1.5 2\n", ":6: face 0: bad vertex index '1.5'"},
      {OFF, "OFF\n3 1 0\n" + tri + "-3 0 1 2\n", ":6: face 0: bad vertex count '-3'"},
      {OFF, "OFF\n3 1 0\n" + tri + "0\n", ":6: face 0 has 0 vertices (need 3 or more)"},
      {OFF, "OFF\n3 1 0\n" + tri + "4000000000 0 1 2\n",
       ":6: face 0: vertex count 4000000000 is more than the rest of the file can hold"},
      {OFF, "OFF\n3 1 0\n" + tri + "3 0 1", ":6: truncated: file ends in face 0 of 1"},
      {OFF, "OFF\n3 1 0\n" + tri + "3 0 1 -2147483649\n", ":6: face 0: vertex index -2147483649 out of range [0, 3)"},
      {OFF, std::string("\x7f" "ELF\x02\x01\x01\0\0", 9), ": not an OFF file (it looks like binary data)"},
      {OFF, kAsciiTriangle, ": not an OFF file (it looks like PLY)"},
      // ---- PLY: header ----
      {PLY, "", ":1: empty file, expected a PLY header"},
      {PLY, "OFF\n3 1 0\n", ": not a PLY file (it looks like OFF)"},
      {PLY, "ply\n", ":2: truncated header: no end_header line"},
      {PLY, "ply\nformat ascii 2.0\n", ":2: unsupported PLY version '2.0'"},
      {PLY, "ply\nformat binary_middle_endian 1.0\n", ":2: unknown PLY format 'binary_middle_endian'"},
      {PLY, "ply\nformat ascii 1.0\nformat ascii 1.0\n", ":3: second format line"},
      {PLY, "ply\nformat ascii 1.0\nproperty float x\n", ":3: property before any element"},
      {PLY, "ply\nformat ascii 1.0\nelement vertex 3\nproperty flot x\n", ":4: unknown property type 'flot'"},
      {PLY, "ply\nformat ascii 1.0\nelement face 1\nproperty list float int vertex_indices\n",
       ":4: list count type 'float' is not an integer type"},
      {PLY, "ply\nformat ascii 1.0\nelement vertex -1\n", ":3: bad count '-1' for element 'vertex'"},
      // An unknown header line is skipped with a warning (exporters write "Created by ...").
      {PLY, "ply\nformat ascii 1.0\nelephant 3\n", ":4: truncated header: no end_header line"},
      {PLY, "ply\nformat ascii 1.0\nelement vertex 1\nelement vertex 1\n", ":4: element 'vertex' declared twice"},
      {PLY, "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty double x\n",
       ":5: property 'x' declared twice in element 'vertex'"},
      {PLY, "ply\nelement vertex 1\nend_header\n", ":3: end_header before any format line"},
      {PLY, ply_header("ascii", kFaceList + "end_header\n3 0 1 2\n"), ": no 'vertex' element"},
      {PLY, ply_header("ascii", "element vertex 3\nproperty float x\nproperty float y\n" + kFaceList + "end_header\n"),
       ":3: element 'vertex' has no property 'z'"},
      {PLY, ply_header("ascii", kVertexXyz + "end_header\n" + tri), ": no 'face' or 'tristrips' element (mesh has no faces)"},
      {PLY, ply_header("ascii", kVertexXyz + "element face 1\nproperty list uchar int corners\nend_header\n"),
       ":7: element 'face' has no vertex_indices list"},
      {PLY, ply_header("ascii", kVertexXyz + "element face 1\nproperty list uchar float vertex_indices\nend_header\n"),
       ":7: element 'face': vertex indices are not an integer type"},
      {PLY, ply_header("binary_little_endian", "element vertex 1000000000\nproperty float x\nproperty float y\n"
                                               "property float z\n" + kFaceList + "end_header\n" + binary_vertices()),
       ":3: element 'vertex' claims 1000000000 entries, more than the 36 bytes after the header can hold"},
      {PLY, ply_header("ascii", "element vertex 0\nproperty float x\nproperty float y\nproperty float z\n" + kFaceList +
                                    "end_header\n3 0 1 2\n"),
       ":3: mesh has no vertices"},
      // ---- PLY: ASCII body ----
      {PLY, kAsciiTriangle + tri + "3 0 1 3\n", ":13: face 0: vertex index 3 out of range [0, 3)"},
      {PLY, kAsciiTriangle + tri + "3 0 -1 2\n", ":13: face 0: vertex index -1 out of range [0, 3)"},
      {PLY, kAsciiTriangle + "0 0 0\n1 abc 0\n0 1 0\n3 0 1 2\n", ":11: vertex 1: bad value 'abc' for property 'y'"},
      {PLY, kAsciiTriangle + "0 0 0\n1 0 nan\n0 1 0\n3 0 1 2\n", ":11: vertex 1: coordinate is not finite"},
      {PLY, kAsciiTriangle + tri + "2 0 1\n", ":13: face 0 has 2 vertices (need 3 or more)"},
      {PLY, kAsciiTriangle + tri + "3 0 1\n", ":14: truncated: file ends in face 0 of 1"},
      {PLY, kAsciiTriangle + tri + "200 0 1 2\n", ":13: face 0: list length 200 is more than the rest of the file can hold"},
      // ---- PLY: binary body ----
      {PLY, kBinaryTriangle + binary_vertices() + "\x03" + le32(0) + le32(1), ": truncated: file ends in face 0 of 1"},
      {PLY, kBinaryTriangle + binary_vertices().substr(0, 30) + "\x03",
       ":3: element 'vertex' claims 3 entries, more than the 31 bytes after the header can hold"},
      {PLY, kBinaryTriangle + binary_vertices() + "\x03" + le32(0) + le32(7) + le32(1),
       ": face 0: vertex index 7 out of range [0, 3)"},
      {PLY, kBinaryTriangle + binary_vertices() + "\x03" + le32(0) + le32(0xffffffffu) + le32(1),
       ": face 0: vertex index -1 out of range [0, 3)"},
      {PLY, kBinaryTriangle + binary_vertices(1.0f / 0.0f) + "\x03" + le32(0) + le32(1) + le32(2),
       ": vertex 1: coordinate is not finite"},
      {PLY, kBinaryTriangle + binary_vertices() + "\x02" + le32(0) + le32(1) + le32(2),
       ": face 0 has 2 vertices (need 3 or more)"},
      {PLY, ply_header("binary_little_endian", kVertexXyz + "element face 1\nproperty list char int vertex_indices\n"
                                               "end_header\n") + binary_vertices() + "\xff" + le32(0),
       ": face 0: negative list length -1"},
      {PLY, ply_header("binary_little_endian", kVertexXyz + "element face 1\nproperty list uint int vertex_indices\n"
                                               "end_header\n") + binary_vertices() + le32(0xffffffffu) + le32(0),
       ": face 0: list length 4294967295 is more than the rest of the file can hold"},
      {PLY, ply_header("binary_little_endian", kVertexXyz + "element tristrips 1\nproperty list int int vertex_indices\n"
                                               "end_header\n") + binary_vertices() + le32(5) + le32(0) + le32(1) +
                 le32(2) + le32(0xffffffffu) + le32(9),
       ": tristrips 0: entry 4: vertex index 9 out of range [0, 3)"},
      {PLY, ply_header("binary_little_endian", kVertexXyz + "element tristrips 1\nproperty list int int vertex_indices\n"
                                               "end_header\n") + binary_vertices() + le32(5) + le32(0) + le32(1) +
                 le32(0xffffffffu) + le32(1) + le32(2),
       ": mesh has no faces"},
      // ---- OBJ ----
      {OBJ, "", ": mesh has no vertices"},
      {OBJ, "# nothing but\n# comments\n", ": mesh has no vertices"},
      {OBJ, v3, ": mesh has no faces"},
      {OBJ, "v 1 2\n", ":1: vertex 0: needs 3 coordinates, has 2"},
      {OBJ, "v 0 0 0\nv 1 nan 0\n", ":2: vertex 1: coordinate is not finite"},
      {OBJ, "v 0 0 0\r\nv 1 abc 0\r\n", ":2: vertex 1: bad coordinate 'abc'"},
      {OBJ, "v 0 0 0\rv 1 0 0\rv 0 1e400 0\r", ":3: vertex 2: coordinate is not finite"},
      {OBJ, "v 0 0 0\nv 1.7976931348623157e308 0 0\nv 0 1 0\nf 1 2 3\n",
       ":2: vertex 1: coordinate overflows tinyobjloader's number parser"},
      {OBJ, v3 + "f 1 2\n", ":4: face 0 has 2 vertices (need 3 or more)"},
      {OBJ, v3 + "f 1 2 0\n", ":4: face 0: vertex index 0 (OBJ indices start at 1)"},
      {OBJ, v3 + "f 1 2 3\nf 1 2 9\n", ":5: face 1: vertex index 9 out of range [1, 3]"},
      {OBJ, v3 + "f -1 -2 -5\n", ":4: face 0: relative vertex index -5 reaches before the first vertex (3 defined so far)"},
      {OBJ, v3 + "f 1 2 99999999999\n", ":4: face 0: bad vertex index '99999999999'"},
      {OBJ, v3 + "f 1/2/3/4 2 3\n", ":4: face 0: bad vertex index '1/2/3/4'"},
      {OBJ, v3 + "f 1 2 three\n", ":4: face 0: bad vertex index 'three'"},
      {OBJ, std::string("v 0 0 0\0\x01\x02", 10), ": not an OBJ file (it looks like binary data)"},
      {OBJ, "solid cube\nfacet normal 0 0 1\n", ": not an OBJ file (it looks like ASCII STL)"},
      {OBJ, kAsciiTriangle + tri + "3 0 1 2\n", ": not an OBJ file (it looks like PLY)"},
      {OBJ, "OFF\n3 1 0\n" + tri + "3 0 1 2\n", ": not an OBJ file (it looks like OFF)"},
  };
}

TEST(MalformedCorpusTest, EveryFileGetsItsOwnClearMessage) {
  const std::vector<Hostile> files = corpus();
  EXPECT_GE(files.size(), 40u);
  std::set<std::string> messages;
  int index = 0;
  for (const Hostile& h : files) {
    const std::string name = "bad" + std::to_string(index++) +
                             (h.format == MeshFormat::kObj ? ".obj" : h.format == MeshFormat::kOff ? ".off" : ".ply");
    Mesh mesh = testing_util::grid(1, 1);
    const Mesh before = mesh;
    const Status s = parse_mesh(h.bytes, h.format, name, &mesh);
    EXPECT_FALSE(s.ok()) << name;
    EXPECT_EQ(s.message(), name + h.message) << "file " << name;
    EXPECT_NE(s.code(), StatusCode::kOk);
    EXPECT_EQ(mesh.positions, before.positions) << name << ": a failed read must not touch the output";
    EXPECT_EQ(mesh.triangles, before.triangles) << name;
    messages.insert(h.message);
  }
  // Distinct problems, distinct messages (a few share one on purpose:
  // e.g. inf and 1e999 are both "not finite").
  EXPECT_GE(messages.size(), 70u);
}

TEST(MalformedCorpusTest, ReadMeshNamesPathAndExtensionProblems) {
  Mesh m;
  EXPECT_EQ(read_mesh("model.stl", &m).message(), "model.stl: unsupported mesh type '.stl' (expected .obj, .off or .ply)");
  EXPECT_EQ(read_mesh("dir.v2/model", &m).message(),
            "dir.v2/model: unsupported mesh type '(no extension)' (expected .obj, .off or .ply)");
  EXPECT_EQ(read_mesh("/nonexistent/a.PLY", &m).message(), "/nonexistent/a.PLY: cannot open: No such file or directory");
  const std::string dir = gab_test::scratch_path("dir.obj");
  ASSERT_EQ(::mkdir(dir.c_str(), 0700), 0);
  EXPECT_EQ(read_mesh(dir, &m).message(), dir + ": cannot open: Is a directory");
  ::rmdir(dir.c_str());
}

TEST(MalformedCorpusTest, TruncatingAValidFileAnywhereIsAnErrorNeverACrash) {
  // Every prefix of a binary and an ASCII PLY, an OFF and an OBJ file.
  const Mesh m = testing_util::torus(5, 4);
  PlyWriteOptions ascii;
  ascii.encoding = PlyEncoding::kAscii;
  struct Whole {
    MeshFormat format;
    std::string bytes;
  };
  Mesh tmp;
  for (const Whole& w : {Whole{MeshFormat::kPly, format_ply(m)}, Whole{MeshFormat::kPly, format_ply(m, ascii)},
                         Whole{MeshFormat::kOff, format_off(m)}, Whole{MeshFormat::kObj, format_obj(m)}}) {
    ASSERT_TRUE(parse_mesh(w.bytes, w.format, "whole", &tmp).ok());
    // Binary: every cut is refused. OFF and ASCII PLY: every cut before the
    // last line is refused (within it, dropping the final newline or a
    // final digit can leave a valid, different file). OBJ has no counts: a
    // cut between lines is a smaller valid mesh; only the messages count.
    const bool binary = w.bytes.find("binary_little_endian") != std::string::npos;
    const size_t last_line = w.bytes.rfind('\n', w.bytes.size() - 2) + 1;
    for (size_t cut = 0; cut < w.bytes.size(); ++cut) {
      const Status s = parse_mesh(std::string_view(w.bytes).substr(0, cut), w.format, "cut", &tmp);
      if (!s.ok()) {
        EXPECT_EQ(s.message().rfind("cut", 0), 0u);
      } else if (binary || (w.format != MeshFormat::kObj && cut < last_line)) {
        ADD_FAILURE() << "a cut at byte " << cut << " of " << w.bytes.size() << " was accepted";
      }
    }
  }
}

}  // namespace
}  // namespace gab
