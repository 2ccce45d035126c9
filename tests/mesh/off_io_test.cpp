#include "gab/mesh/off_io.h"

#include <gtest/gtest.h>

#include <fstream>

namespace gab {
namespace {

TEST(OffTest, ParsesTrianglesAndFanTriangulatesPolygons) {
  Mesh m;
  const std::string text =
      "OFF\n# a comment\n5 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 2 2\n3 0 1 2\n4 0 1 2 3\n";
  ASSERT_TRUE(parse_off(text, "t.off", &m).ok());
  EXPECT_EQ(m.num_vertices(), 5);
  EXPECT_EQ(m.triangles, (std::vector<int32_t>{0, 1, 2, 0, 1, 2, 0, 2, 3}));
  EXPECT_EQ(m.positions[12], 2.0);
}

TEST(OffTest, ColouredVariantsKeepTheirColours) {
  Mesh m;
  ASSERT_TRUE(parse_off("COFF\n3 1 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 0 0 255 255\n3 0 1 2 9 9 9\n",
                        "c.off", &m).ok());
  EXPECT_EQ(m.num_triangles(), 1);
  EXPECT_EQ(m.positions[3], 1.0);
  ASSERT_EQ(m.attributes.size(), 1u);
  EXPECT_EQ(m.attributes[0].values, (std::vector<double>{255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255}));
}

struct BadCase {
  const char* text;
  const char* message;
};

TEST(OffTest, MalformedFilesNameTheLine) {
  const BadCase cases[] = {
      {"", "x.off:1: empty file, expected an OFF header"},
      {"PLY\n", "x.off:1: not an OFF file (header 'PLY')"},
      {"OFF\n3 1\n", "x.off:3: truncated header: expected vertex, face and edge counts"},
      {"OFF\n-3 1 0\n", "x.off:2: bad count '-3' in header"},
      {"OFF\n0 0 0\n", "x.off:2: mesh has no vertices"},
      {"OFF\n3 1 0\n0 0 0\n1 0 0\n", "x.off:5: truncated: file ends in vertex 2 of 3"},
      {"OFF\n3 1 0\n0 0 0\n1 zz 0\n0 1 0\n3 0 1 2\n", "x.off:4: vertex 1: bad coordinate 'zz'"},
      {"OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n", "x.off:4: vertex 1: coordinate is not finite"},
      {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", "x.off:6: face 0: vertex index 3 out of range [0, 3)"},
      {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n", "x.off:6: face 0: vertex index -1 out of range [0, 3)"},
      {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n", "x.off:6: face 0 has 2 vertices (need 3 or more)"},
      {"OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "x.off:7: truncated: file ends in face 1 of 2"},
      {"OFF\n3000000000 1 0\n0 0 0\n",
       "x.off:2: header claims 3000000000 vertices and 1 faces, more than the file's 25 bytes can hold"},
  };
  for (const BadCase& c : cases) {
    Mesh m;
    const Status s = parse_off(c.text, "x.off", &m);
    EXPECT_EQ(s.code(), StatusCode::kParseError) << c.text;
    EXPECT_EQ(s.message(), c.message);
  }
}

TEST(OffTest, MissingFileIsAnIoError) {
  Mesh m;
  const Status s = read_off("/nonexistent/dir/a.off", &m);
  EXPECT_EQ(s.code(), StatusCode::kIoError);
  EXPECT_EQ(s.message(), "/nonexistent/dir/a.off: cannot open: No such file or directory");
}

TEST(OffTest, ReadsTheSharedBunny) {
  const std::string path = std::string(GAB_SHARED_MESHES) + "/bunny-small.off";
  if (!std::ifstream(path)) GTEST_SKIP() << path << " not present";
  Mesh m;
  ASSERT_TRUE(read_off(path, &m).ok());
  EXPECT_EQ(m.num_vertices(), 3485);
  EXPECT_EQ(m.num_triangles(), 6966);
}

}  // namespace
}  // namespace gab

namespace gab {
namespace {

TEST(OffTest, HeaderVariants) {
  struct Case {
    const char* text;
    std::vector<double> positions;
  };
  const Case cases[] = {
      // Normals, texture coordinates and colours after x y z are attributes, not coordinates.
      {"NOFF\n3 1 0\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n", {0, 0, 0, 1, 0, 0, 0, 1, 0}},
      {"STCNOFF\n3 1 0\n0 0 0 1 2 3 .1 .2 .3 1 9 9\n1 0 0 1 2 3 .1 .2 .3 1 9 9\n0 1 0 1 2 3 .1 .2 .3 1 9 9\n3 0 1 2\n",
       {0, 0, 0, 1, 0, 0, 0, 1, 0}},
      // Homogeneous coordinates are divided by w.
      {"4OFF\n3 1 0\n2 4 6 2\n1 0 0 1\n0 3 0 3\n3 0 1 2\n", {1, 2, 3, 1, 0, 0, 0, 1, 0}},
      // nOFF with dimension 3, counts on the keyword's line, CRLF, BOM, comments anywhere.
      {"\xEF\xBB\xBFnOFF 3 # dim\r\n3 1 0\r\n0 0 0\r\n1 0 0 # x\r\n0 1 0\r\n3 0 1 2\r\n", {0, 0, 0, 1, 0, 0, 0, 1, 0}},
      // Free format: a record may span lines.
      {"OFF 3 1 0 0 0\n0 1 0 0 0\n1\n0 3 0\n1 2\n", {0, 0, 0, 1, 0, 0, 0, 1, 0}},
  };
  for (const Case& c : cases) {
    Mesh m;
    const Status s = parse_off(c.text, "v.off", &m);
    ASSERT_TRUE(s.ok()) << s.message() << " in " << c.text;
    EXPECT_EQ(m.positions, c.positions) << c.text;
    EXPECT_EQ(m.triangles, (std::vector<int32_t>{0, 1, 2})) << c.text;
  }
}

TEST(OffTest, RoundTripIsExact) {
  Mesh m;
  m.positions = {0.1, -2.5e-300, 1e300, 1.0 / 3.0, 123456789.123456789, -0.0, 5, 6, 7, 8, 9, 10};
  m.triangles = {0, 1, 2, 2, 1, 3, 3, 3, 0};  // a degenerate face is kept
  Mesh back;
  ASSERT_TRUE(parse_off(format_off(m), "r.off", &back).ok());
  EXPECT_EQ(back.positions, m.positions);
  EXPECT_EQ(back.triangles, m.triangles);
}

}  // namespace
}  // namespace gab
