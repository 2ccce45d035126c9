// OBJ reader (tinyobjloader + line scan) and writer.
#include "gab/mesh/obj_io.h"

#include <gtest/gtest.h>

#include <cmath>

#include "mesh_test_util.h"

namespace gab {
namespace {

TEST(ObjTest, ReadsTriplesPolygonsRelativeAndForwardIndices) {
  const std::string text =
      "# comment\nmtllib none.mtl\no thing\ng part\nv 0 0 0\nv 1 0 0 1.0\r\nv 1 1 0 0.5 0.5 0.5\n"
      "vt 0 0\nvn 0 0 1\nusemtl red\ns 1\n"
      "f 1/1/1 2/1/1 3/1/1\n"
      "f -3//1 -1//1 4//1\n"  // relative to the 3 vertices so far; 4 is defined below
      "\tf  1 2 3 4 \n"        // a quad, fanned
      "l 1 2\np 3\n"
      "v 0 1 0\r";
  Mesh m;
  const Status s = parse_obj(text, "t.obj", &m);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(m.positions, (std::vector<double>{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0}));
  EXPECT_EQ(m.triangles, (std::vector<int32_t>{0, 1, 2, 0, 2, 3, 0, 1, 2, 0, 2, 3}));
}

TEST(ObjTest, RoundTripWithinTinyobjloadersRounding) {
  Mesh m = testing_util::torus(10, 7, 123.456, 0.001);
  Mesh back;
  ASSERT_TRUE(parse_obj(format_obj(m), "r.obj", &back).ok());
  EXPECT_EQ(back.triangles, m.triangles);
  ASSERT_EQ(back.positions.size(), m.positions.size());
  for (size_t i = 0; i < m.positions.size(); ++i) {
    EXPECT_NEAR(back.positions[i], m.positions[i], 1e-14 * std::fabs(m.positions[i])) << i;
  }
}

TEST(ObjTest, WritesOneBasedFaces) {
  const std::string text = format_obj(testing_util::grid(1, 1));
  EXPECT_EQ(text, "# written by gab\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 4\nf 1 4 3\n");
}

}  // namespace
}  // namespace gab
