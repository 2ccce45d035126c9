// Attributes through the gab binary: compress's flags, its JSON and summary,
// info's section list, and what decompress says when the output's format
// cannot hold per-corner data as decoded.
#include <gtest/gtest.h>

#include <string>

#include "common/scratch_files.h"
#include "run_gab.h"

namespace {

using gab_test::CommandResult;
using gab_test::json_number;
using gab_test::run_gab;
using gab_test::write_scratch_file;

// A cube with a normal per side (per corner: every vertex has three) and a
// per-vertex colour: Draco's cube_att.obj in kind.
std::string faceted_cube() {
  std::string text;
  for (int i = 0; i < 8; ++i) {
    text += "v " + std::to_string(i & 1) + " " + std::to_string((i >> 1) & 1) + " " + std::to_string(i >> 2) + " 0." +
            std::to_string(i + 1) + " 0.5 0.25\n";
  }
  text += "vn 0 0 -1\nvn 0 0 1\nvn 0 -1 0\nvn 0 1 0\nvn -1 0 0\nvn 1 0 0\n";
  const int sides[6][4] = {{1, 3, 4, 2}, {5, 6, 8, 7}, {1, 2, 6, 5}, {3, 7, 8, 4}, {1, 5, 7, 3}, {2, 4, 8, 6}};
  for (int s = 0; s < 6; ++s) {
    const int* q = sides[s];
    const std::string n = std::to_string(s + 1);
    auto corner = [&n](int v) { return " " + std::to_string(v) + "//" + n; };
    text += "f" + corner(q[0]) + corner(q[1]) + corner(q[2]) + "\nf" + corner(q[0]) + corner(q[2]) + corner(q[3]) + "\n";
  }
  return text;
}

TEST(AttributesCliTest, CompressReportsEachAttributeAndItsBits) {
  const std::string in = write_scratch_file("faceted.obj", faceted_cube());
  const std::string out = gab_test::scratch_path("faceted.gab");
  CommandResult r = run_gab("compress -i " + in + " -o " + out + " --json --normal-bits 10 --color-bits 6");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");  // everything the file holds is carried
  EXPECT_GT(json_number(r.out, "attribute_bytes"), 0);
  EXPECT_EQ(json_number(r.out, "bytes"), json_number(r.out, "geometry_bytes") + json_number(r.out, "connectivity_bytes") +
                                             json_number(r.out, "order_bytes") + json_number(r.out, "attribute_bytes"));
  EXPECT_NE(r.out.find("\"label\": \"normals\", \"bits\": 10, \"per_corner\": true, \"elements\": 24"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("\"label\": \"vertex_colors\", \"bits\": 6, \"per_corner\": false, \"elements\": 8"),
            std::string::npos)
      << r.out;
  r = run_gab("info " + out);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("  section 0: normals, 24 values shared by corners, 10 bits"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("  section 1: vertex_colors, 8 per vertex, 6 bits"), std::string::npos) << r.out;
  r = run_gab("compress -i " + in + " -o " + out + " --normal-bits 17");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--normal-bits"), std::string::npos) << r.err;
}

TEST(AttributesCliTest, DecompressSaysWhereTheFormatSplitsVertices) {
  const std::string in = write_scratch_file("faceted_split.obj", faceted_cube());
  const std::string gab = gab_test::scratch_path("faceted_split.gab");
  ASSERT_EQ(run_gab("compress -i " + in + " -o " + gab).exit_code, 0);
  // OBJ holds the normals per corner: nothing to say.
  CommandResult r = run_gab("decompress -i " + gab + " -o " + gab_test::scratch_path("back.obj") + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_EQ(json_number(r.out, "attributes"), 2);
  EXPECT_EQ(json_number(r.out, "split_vertices"), 0);
  // PLY holds them per vertex: each corner of the cube becomes three vertices.
  const std::string ply = gab_test::scratch_path("back.ply");
  r = run_gab("decompress -i " + gab + " -o " + ply + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(json_number(r.out, "split_vertices"), 16);
  EXPECT_EQ(r.err, "gab decompress: warning: " + ply +
                       ": 16 vertices added where per-corner data has seams (the format holds it per vertex; OBJ "
                       "keeps the mesh's vertices)\n");
}

}  // namespace
