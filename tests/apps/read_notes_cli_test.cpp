// What the mesh readers did not keep, as the commands say it: one warning
// line per input on stderr (also with --quiet), and compress --json's
// "dropped" object. By running the gab binary.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "run_gab.h"

namespace {

using gab_test::CommandResult;
using gab_test::json_number;
using gab_test::run_gab;
using gab_test::write_scratch_file;

// Draco's cube_att.obj in kind (8 v, 6 vn, 4 vt, 12 faces v/vt/vn: carried,
// not named), with a group, a material and a line (not carried).
std::string cube_with_attributes() {
  std::string text;
  for (int i = 0; i < 8; ++i) {
    text += "v " + std::to_string(i & 1) + " " + std::to_string((i >> 1) & 1) + " " + std::to_string(i >> 2) + "\n";
  }
  text += "vn 0 0 1\nvn 0 0 -1\nvn 0 1 0\nvn 0 -1 0\nvn 1 0 0\nvn -1 0 0\nvt 0 0\nvt 0 1\nvt 1 0\nvt 1 1\n";
  // Two triangles per side of the cube: corners (v, vt, vn), 1-based.
  text += "g cube\nusemtl red\nl 1 2\n";
  const int sides[6][4] = {{1, 3, 4, 2}, {5, 6, 8, 7}, {1, 2, 6, 5}, {3, 7, 8, 4}, {1, 5, 7, 3}, {2, 4, 8, 6}};
  for (int s = 0; s < 6; ++s) {
    const int* q = sides[s];
    const std::string n = std::to_string(s + 1);
    auto corner = [&n](int v, int t) { return " " + std::to_string(v) + "/" + std::to_string(t) + "/" + n; };
    text += "f" + corner(q[0], 1) + corner(q[1], 2) + corner(q[2], 4) + "\n";
    text += "f" + corner(q[0], 1) + corner(q[2], 4) + corner(q[3], 3) + "\n";
  }
  return text;
}

const std::string kCubeWarning =
    ": not carried: 1 lines (l), 1 groups (g), 1 material uses (usemtl); gab keeps positions, triangles, normals, texture coordinates, colours and vertex properties\n";

TEST(ReadNotesCliTest, CompressWarnsOnceAndJsonHasDropped) {
  const std::string in = write_scratch_file("cube_att.obj", cube_with_attributes());
  const std::string out = gab_test::scratch_path("cube_att.gab");
  const CommandResult r = run_gab("compress -i " + in + " -o " + out + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "gab: warning: " + in + kCubeWarning);
  EXPECT_NE(r.out.find("\"dropped\": {\"lines\": 1, \"groups\": 1, \"material_uses\": 1}"),
            std::string::npos)
      << r.out;
  // The keys that were there stay.
  EXPECT_EQ(json_number(r.out, "n"), 8);
  EXPECT_EQ(json_number(r.out, "faces"), 12);
  EXPECT_FALSE(std::isnan(json_number(r.out, "bytes")));
}

TEST(ReadNotesCliTest, QuietDoesNotSilenceTheWarning) {
  const std::string in = write_scratch_file("cube_quiet.obj", cube_with_attributes());
  const CommandResult r = run_gab("compress -i " + in + " -o " + gab_test::scratch_path("cube_quiet.gab") + " --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "gab: warning: " + in + kCubeWarning);
}

TEST(ReadNotesCliTest, NothingDroppedNoWarningAndAnEmptyObject) {
  const std::string in = write_scratch_file("plain.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n");
  const CommandResult r = run_gab("compress -i " + in + " -o " + gab_test::scratch_path("plain.gab") + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_NE(r.out.find("\"dropped\": {}"), std::string::npos) << r.out;
}

// --strict: the warning, then the failure naming the same data, before any
// output is written; an input with nothing dropped (a forgiven CRLF line end
// is not data) compresses as without it.
TEST(ReadNotesCliTest, StrictFailsOnDroppedDataOnly) {
  const std::string in = write_scratch_file("cube_strict.obj", cube_with_attributes());
  const std::string out = gab_test::scratch_path("cube_strict.gab");
  std::remove(out.c_str());
  const CommandResult r = run_gab("compress -i " + in + " -o " + out + " --strict");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(r.err, "gab: warning: " + in + kCubeWarning + "gab: error: " + in +
                       ": --strict: not carried: 1 lines (l), 1 groups (g), 1 material uses (usemtl)\n");
  EXPECT_NE(access(out.c_str(), F_OK), 0) << "--strict wrote " << out;

  const std::string plain =
      write_scratch_file("plain_strict.off", "OFF\r\n4 2 0\r\n0 0 0\r\n1 0 0\r\n1 1 0\r\n0 1 0\r\n3 0 1 2\r\n3 0 2 3\r\n");
  const CommandResult ok = run_gab("compress -i " + plain + " -o " + gab_test::scratch_path("plain_strict.gab") +
                                   " --strict --json");
  ASSERT_EQ(ok.exit_code, 0) << ok.err;
  EXPECT_EQ(ok.err, "");
  EXPECT_NE(ok.out.find("\"dropped\": {}"), std::string::npos) << ok.out;
}

// assimp's Wuson.ply in kind: a "Created by" header line, normals, UVs (carried,
// not named), and a quad.
const std::string kCreatedByPly =
    "ply\r\nformat ascii 1.0\r\nCreated by Blender3D 247 - www.blender3d.com\r\nelement vertex 4\r\n"
    "property float x\r\nproperty float y\r\nproperty float z\r\nproperty float nx\r\nproperty float ny\r\n"
    "property float nz\r\nproperty float s\r\nproperty float t\r\nelement face 1\r\n"
    "property list uchar uint vertex_indices\r\nend_header\r\n"
    "0 0 0 0 0 1 0 0\r\n1 0 0 0 0 1 1 0\r\n1 1 0 0 0 1 1 1\r\n0 1 0 0 0 1 0 1\r\n4 0 1 2 3\r\n";

TEST(ReadNotesCliTest, UnknownPlyHeaderLineIsAWarningNotAnError) {
  const std::string in = write_scratch_file("created_by.ply", kCreatedByPly);
  const CommandResult r = run_gab("compress -i " + in + " -o " + gab_test::scratch_path("created_by.gab"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "gab: warning: " + in + ":3: unknown header line 'Created by Blender3D 247 - www.b...' skipped\n"
                   "gab: warning: " + in + ": not carried: 1 polygons of 4 or more corners (fan-triangulated); gab "
                   "keeps positions, triangles, normals, texture coordinates, colours and vertex properties\n");
}

TEST(ReadNotesCliTest, EveryCommandThatReadsAMeshWarnsPerInput) {
  const std::string cube = write_scratch_file("cube_every.obj", cube_with_attributes());
  const std::string quad = write_scratch_file("quad_every.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n");
  const std::string quad_warning = "gab: warning: " + quad +
                                   ": not carried: 1 polygons of 4 or more corners (fan-triangulated); gab keeps "
                                   "positions, triangles, normals, texture coordinates, colours and vertex properties\n";
  CommandResult r = run_gab("diff " + cube + " " + quad + " --json --samples 10");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err.substr(0, r.err.find('\n') + 1), "gab: warning: " + cube + kCubeWarning);
  EXPECT_NE(r.err.find(quad_warning), std::string::npos) << r.err;

  // Subdividing keeps positions and triangles: the normals and texture
  // coordinates the reader carried are named too.
  const std::string fine = gab_test::scratch_path("cube_fine.obj");
  r = run_gab("subdivide " + cube + " -o " + fine);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "gab: warning: " + cube + kCubeWarning + "gab subdivide: warning: " + cube +
                       ": not subdivided, left out of " + fine + ": normals, texture_coordinates\n");

  r = run_gab("factor " + cube + " --anchors 2 --repeat 1 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "gab: warning: " + cube + kCubeWarning);

  // Once per input, not once per ordering.
  r = run_gab("study " + cube + " --anchors 2 --updates 2 --ordering amd,natural --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "gab: warning: " + cube + kCubeWarning);
}

// A Rhino export's header: lines end with a lone CR (Draco's Box.ply and
// delim_test.ply), read by every command.
TEST(ReadNotesCliTest, CrLinePlyIsRead) {
  std::string text =
      "ply\rformat ascii 1.0\relement vertex 3\rproperty float x\rproperty float y\rproperty float z\r"
      "element face 1\rproperty list uchar int vertex_index\rend_header\r0 0 0\r1 0 0\r0 1 0\r3 0 1 2\r";
  const std::string in = write_scratch_file("rhino.ply", text);
  const CommandResult r = run_gab("compress -i " + in + " -o " + gab_test::scratch_path("rhino.gab") + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_EQ(json_number(r.out, "n"), 3);
}

// Bad input stays refused with its own message, and nothing is warned.
TEST(ReadNotesCliTest, RefusedInputGetsTheErrorAlone) {
  const std::string in = write_scratch_file("bad_index.obj", "vn 0 0 1\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n");
  const CommandResult r = run_gab("compress -i " + in + " -o " + gab_test::scratch_path("bad_index.gab"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "gab: error: " + in + ":5: face 0: vertex index 4 out of range [1, 3]\n");
}

}  // namespace
