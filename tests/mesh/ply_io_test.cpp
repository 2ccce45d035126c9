// PLY reader and writer: encodings, property types, tristrips, skipping,
// round trips.
#include "gab/mesh/ply_io.h"

#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "mesh_test_util.h"

namespace gab {
namespace {

// Appends `value` as a PLY binary scalar of the named type.
void pack(std::string* out, const std::string& type, double value, bool big) {
  char b[8];
  int n = 0;
  if (type == "char" || type == "uchar") {
    const int8_t v = static_cast<int8_t>(static_cast<int64_t>(value));
    std::memcpy(b, &v, n = 1);
  } else if (type == "short" || type == "ushort") {
    const int16_t v = static_cast<int16_t>(static_cast<int64_t>(value));
    std::memcpy(b, &v, n = 2);
  } else if (type == "int" || type == "uint") {
    const int32_t v = static_cast<int32_t>(static_cast<int64_t>(value));
    std::memcpy(b, &v, n = 4);
  } else if (type == "float") {
    const float v = static_cast<float>(value);
    std::memcpy(b, &v, n = 4);
  } else {
    std::memcpy(b, &value, n = 8);
  }
  if (big) {
    for (int i = 0; i < n / 2; ++i) std::swap(b[i], b[n - 1 - i]);
  }
  out->append(b, static_cast<size_t>(n));
}

// A square (4 vertices) as one quad face plus one triangle, in a binary
// PLY with the given coordinate, list count and index types.
std::string binary_square(bool big, const std::string& coord, const std::string& count, const std::string& index) {
  std::string s = std::string("ply\nformat ") + (big ? "binary_big_endian" : "binary_little_endian") +
                  " 1.0\nelement vertex 4\nproperty " + coord + " x\nproperty " + coord + " y\nproperty " + coord +
                  " z\nproperty uchar red\nelement face 2\nproperty list " + count + " " + index +
                  " vertex_indices\nproperty float quality\nend_header\n";
  const double xyz[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  for (const auto& v : xyz) {
    for (double c : v) pack(&s, coord, c, big);
    pack(&s, "uchar", 7, big);
  }
  pack(&s, count, 4, big);
  for (int v : {0, 1, 2, 3}) pack(&s, index, v, big);
  pack(&s, "float", 0.5, big);
  pack(&s, count, 3, big);
  for (int v : {3, 2, 1}) pack(&s, index, v, big);
  pack(&s, "float", 0.5, big);
  return s;
}

TEST(PlyTest, BinaryEveryByteOrderAndTypeGivesTheSameMesh) {
  const std::vector<int32_t> expect_tris = {0, 1, 2, 0, 2, 3, 3, 2, 1};
  const std::vector<double> expect_pos = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0};
  int cases = 0;
  for (bool big : {false, true}) {
    for (const char* coord : {"float", "double", "short", "int", "uchar"}) {
      for (const char* count : {"uchar", "char", "ushort", "short", "uint", "int"}) {
        for (const char* index : {"int", "uint", "short", "ushort", "char", "uchar"}) {
          Mesh m;
          const Status s = parse_ply(binary_square(big, coord, count, index), "b.ply", &m);
          ASSERT_TRUE(s.ok()) << s.message() << " " << coord << " " << count << " " << index;
          EXPECT_EQ(m.triangles, expect_tris);
          EXPECT_EQ(m.positions, expect_pos);
          ++cases;
        }
      }
    }
  }
  EXPECT_EQ(cases, 360);
}

TEST(PlyTest, BinaryBytesBeyondTheHeadersElementsAreAnError) {
  const std::string square = binary_square(false, "float", "uchar", "int");
  Mesh m;
  // A line end after the body, as some exporters write, is fine.
  ASSERT_TRUE(parse_ply(square + "\r\n", "b.ply", &m).ok());
  const Status s = parse_ply(square + "garbage", "b.ply", &m);
  EXPECT_EQ(s.code(), StatusCode::kParseError);
  EXPECT_EQ(s.message(), "b.ply: 7 bytes after the last element the header declares");
}

TEST(PlyTest, AsciiSkipsExtraPropertiesAndElements) {
  const std::string text =
      "ply\r\nformat ascii 1.0\r\ncomment made by hand\r\nobj_info none\r\nelement material 1\r\n"
      "property list uchar float diffuse\r\nproperty int id\r\nelement vertex 4\r\nproperty double nx\r\n"
      "property float z\r\nproperty float y\r\nproperty float x\r\nproperty list uchar int neighbours\r\n"
      "element face 2\r\nproperty list int uint vertex_index\r\nproperty uchar red\r\nelement edge 1\r\n"
      "property int vertex1\r\nproperty int vertex2\r\nend_header\r\n"
      "3 0.1 0.2 0.3 9\r\n"
      "0.5 3 2 1 2 1 2\r\n0.5 6 5 4 0\r\n0.5 9 8 7 1 0\r\n0.5 1 1 1 0\r\n"
      "3 0 1 2 255\r\n5 0 1 2 3 1 0\r\n0 1\r\n";
  Mesh m;
  const Status s = parse_ply(text, "a.ply", &m);
  ASSERT_TRUE(s.ok()) << s.message();
  // x y z are found by name whatever their order in the element.
  EXPECT_EQ(m.positions, (std::vector<double>{1, 2, 3, 4, 5, 6, 7, 8, 9, 1, 1, 1}));
  // The pentagon (0 1 2 3 1) is fanned from its first vertex; its last
  // triangle (0 3 1) repeats nothing, (0 1 2) is a duplicate: both legal.
  EXPECT_EQ(m.triangles, (std::vector<int32_t>{0, 1, 2, 0, 1, 2, 0, 2, 3, 0, 3, 1}));
}

TEST(PlyTest, FacesMayComeBeforeVertices) {
  const std::string text =
      "ply\nformat ascii 1.0\nelement face 1\nproperty list uchar int vertex_indices\nelement vertex 3\n"
      "property float x\nproperty float y\nproperty float z\nend_header\n3 2 1 0\n0 0 0\n1 0 0\n0 1 0\n";
  Mesh m;
  ASSERT_TRUE(parse_ply(text, "f.ply", &m).ok());
  EXPECT_EQ(m.triangles, (std::vector<int32_t>{2, 1, 0}));
}

TEST(PlyTest, TristripsAlternateOrientationRestartAndDropStitching) {
  // Strip 0 1 2 3 4: (0 1 2), (2 1 3), (2 3 4). Restart. Strip 5 6 6 7 8:
  // (5 6 6) and (6 6 7) repeat a vertex (a strip's stitch): dropped;
  // then (j = 2, even) (6 7 8). A strip of two vertices gives nothing.
  const std::string text =
      "ply\nformat ascii 1.0\nelement vertex 9\nproperty float x\nproperty float y\nproperty float z\n"
      "element tristrips 2\nproperty list int int vertex_indices\nend_header\n"
      "0 0 0\n1 0 0\n0 1 0\n1 1 0\n0 2 0\n5 0 0\n6 0 0\n5 1 0\n6 1 0\n"
      "11 0 1 2 3 4 -1 5 6 6 7 8\n3 0 1 -1\n";
  Mesh m;
  const Status s = parse_ply(text, "s.ply", &m);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(m.triangles, (std::vector<int32_t>{0, 1, 2, 2, 1, 3, 2, 3, 4, 6, 7, 8}));
}

TEST(PlyTest, StripsOfAGridKeepOneOrientation) {
  // A 4 x 3 grid as strips row by row (binary big-endian): every triangle
  // must have the normal +z, like the grid's own triangles.
  const Mesh g = testing_util::grid(4, 3);
  std::string s = "ply\nformat binary_big_endian 1.0\nelement vertex " + std::to_string(g.num_vertices()) +
                  "\nproperty double x\nproperty double y\nproperty double z\nelement tristrips 1\n"
                  "property list int int vertex_indices\nend_header\n";
  for (double c : g.positions) pack(&s, "double", c, true);
  std::vector<int> strip;
  for (int row = 0; row < 3; ++row) {
    if (row > 0) strip.push_back(-1);
    for (int i = 0; i <= 4; ++i) {
      strip.push_back(i + (row + 1) * 5);  // upper, then lower: counter-clockwise start
      strip.push_back(i + row * 5);
    }
  }
  pack(&s, "int", static_cast<double>(strip.size()), true);
  for (int v : strip) pack(&s, "int", v, true);
  Mesh m;
  const Status st = parse_ply(s, "grid.ply", &m);
  ASSERT_TRUE(st.ok()) << st.message();
  ASSERT_EQ(m.num_triangles(), 24);
  for (int t = 0; t < m.num_triangles(); ++t) {
    const double* a = &m.positions[3 * m.triangles[3 * t]];
    const double* b = &m.positions[3 * m.triangles[3 * t + 1]];
    const double* c = &m.positions[3 * m.triangles[3 * t + 2]];
    const double nz = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    EXPECT_GT(nz, 0) << "triangle " << t;
  }
}

TEST(PlyTest, RoundTripsEveryEncodingExactly) {
  Mesh m = testing_util::torus(12, 8);
  m.positions[0] = 0.1 + 1e-17;  // not representable as float: double keeps it
  for (PlyEncoding e : {PlyEncoding::kAscii, PlyEncoding::kBinaryLittleEndian, PlyEncoding::kBinaryBigEndian}) {
    PlyWriteOptions o;
    o.encoding = e;
    Mesh back;
    ASSERT_TRUE(parse_ply(format_ply(m, o), "r.ply", &back).ok());
    EXPECT_EQ(back.positions, m.positions);
    EXPECT_EQ(back.triangles, m.triangles);
    o.float32 = true;
    ASSERT_TRUE(parse_ply(format_ply(m, o), "r.ply", &back).ok());
    ASSERT_EQ(back.positions.size(), m.positions.size());
    for (size_t i = 0; i < m.positions.size(); ++i) {
      EXPECT_EQ(back.positions[i], static_cast<double>(static_cast<float>(m.positions[i])));
    }
  }
}

TEST(PlyTest, WriterRefusesInvalidMeshesAndLeavesNoFile) {
  Mesh m = testing_util::grid(1, 1);
  m.triangles[2] = 9;
  const std::string path = testing_util::temp_path("invalid.ply");
  const Status s = write_ply(path, m);
  EXPECT_EQ(s.code(), StatusCode::kInvalidArgument);
  EXPECT_EQ(s.message(), path + ": triangle 0: vertex index 9 out of range [0, 4)");
  EXPECT_FALSE(testing_util::exists(path));
  m = testing_util::grid(1, 1);
  m.positions[7] = 1e300;
  PlyWriteOptions o;
  o.float32 = true;
  EXPECT_EQ(write_ply(path, m, o).message(), path + ": vertex 2: coordinate does not fit a float");
  EXPECT_FALSE(testing_util::exists(path));
  o.float32 = false;
  EXPECT_TRUE(write_ply(path, m, o).ok());
  std::remove(path.c_str());
}

}  // namespace
}  // namespace gab
