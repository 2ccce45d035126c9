// `gab diff`, by running the gab binary.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include "run_gab.h"

namespace {

using gab_test::CommandResult;
using gab_test::json_null;
using gab_test::json_number;
using gab_test::run_gab;
using gab_test::write_scratch_file;

// The unit square (two triangles) at height z, as OFF; and as OBJ.
std::string square_off(double z) {
  const std::string h = std::to_string(z);
  return "OFF\n4 2 0\n0 0 " + h + "\n1 0 " + h + "\n1 1 " + h + "\n0 1 " + h + "\n3 0 1 2\n3 0 2 3\n";
}

TEST(DiffCliTest, JsonHasTheContractKeysAndKnownValues) {
  const std::string a = write_scratch_file("a.off", square_off(0));
  const std::string b = write_scratch_file("b.obj", "v 0 0 0.25\nv 1 0 0.25\nv 1 1 0.25\nv 0 1 0.25\nf 1 2 3\nf 1 3 4\n");
  const CommandResult r = run_gab("diff " + a + " " + b + " --json --samples 5000");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // Exactly one JSON object on one line, nothing else on stdout.
  ASSERT_FALSE(r.out.empty());
  EXPECT_EQ(r.out.front(), '{');
  EXPECT_EQ(r.out.find('\n'), r.out.size() - 1);
  EXPECT_EQ(r.out[r.out.size() - 2], '}');
  const double diag = std::sqrt(2.0);
  EXPECT_EQ(json_number(r.out, "n"), 4);
  EXPECT_DOUBLE_EQ(json_number(r.out, "linf"), 0.25);
  EXPECT_DOUBLE_EQ(json_number(r.out, "rms"), 0.25);
  EXPECT_NEAR(json_number(r.out, "linf_rel"), 0.25 / diag, 1e-8);
  EXPECT_NEAR(json_number(r.out, "rms_rel"), 0.25 / diag, 1e-8);
  EXPECT_NEAR(json_number(r.out, "metro_mean_rel"), 0.25 / diag, 1e-8);
  EXPECT_NEAR(json_number(r.out, "metro_rms_rel"), 0.25 / diag, 1e-8);
  EXPECT_NEAR(json_number(r.out, "hausdorff_rel"), 0.25 / diag, 1e-8);
  EXPECT_EQ(json_number(r.out, "samples"), 5000);
  EXPECT_EQ(r.err, "");
}

TEST(DiffCliTest, DifferentVertexCountsGiveNullVertexMetrics) {
  const std::string a = write_scratch_file("a2.off", square_off(0));
  // The same square as four triangles around a centre vertex, in ASCII PLY.
  const std::string b = write_scratch_file(
      "b2.ply",
      "ply\nformat ascii 1.0\nelement vertex 5\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 4\nproperty list uchar int vertex_indices\nend_header\n"
      "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0.5 0.5 0\n3 0 1 4\n3 1 2 4\n3 2 3 4\n3 3 0 4\n");
  const CommandResult r = run_gab("diff " + a + " " + b + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* key : {"linf", "rms", "linf_rel", "rms_rel"}) EXPECT_TRUE(json_null(r.out, key)) << key;
  EXPECT_EQ(r.err, "gab diff: no per-vertex distances: the vertex counts differ (4 and 5)\n");
  // Same surface, different tessellation: zero up to rounding.
  EXPECT_LT(json_number(r.out, "hausdorff_rel"), 1e-12);
  EXPECT_LT(json_number(r.out, "metro_mean_rel"), 1e-12);
  EXPECT_EQ(json_number(r.out, "n"), 4);
  EXPECT_EQ(json_number(r.out, "n_b"), 5);
}

TEST(DiffCliTest, ARenumberedMeshGetsVertexFiguresOnlyThroughAMap) {
  const std::string a = write_scratch_file("a6.off", square_off(0));
  // The square 0.25 above, its vertices numbered backwards (B's vertex 3 - i
  // is A's i): the same counts, other triangles by index.
  const std::string b = write_scratch_file(
      "b6.off", "OFF\n4 2 0\n0 1 0.25\n1 1 0.25\n1 0 0.25\n0 0 0.25\n3 3 2 1\n3 3 1 0\n");
  const CommandResult plain = run_gab("diff " + a + " " + b + " --json");
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  for (const char* key : {"linf", "rms", "linf_rel", "rms_rel"}) EXPECT_TRUE(json_null(plain.out, key)) << key;
  EXPECT_EQ(plain.err,
            "gab diff: no per-vertex distances: the triangles differ by vertex index: the numberings do not "
            "correspond (a renumbered mesh, such as a decode in traversal order, gab compress's default; --map FILE "
            "pairs them: compress --order-out writes it)\n");
  EXPECT_NEAR(json_number(plain.out, "metro_mean_rel"), 0.25 / std::sqrt(2.0), 1e-8);  // the surfaces still compare
  const CommandResult text = run_gab("diff " + a + " " + b);
  EXPECT_NE(text.out.find("vertex distance: n/a: the triangles differ by vertex index"), std::string::npos)
      << text.out;
  EXPECT_EQ(text.err, "");
  const std::string map = write_scratch_file("b6.map", "3\n2\n 1 \n0\n\n");
  const CommandResult mapped = run_gab("diff " + a + " " + b + " --map " + map + " --json");
  ASSERT_EQ(mapped.exit_code, 0) << mapped.err;
  EXPECT_DOUBLE_EQ(json_number(mapped.out, "rms"), 0.25);
  EXPECT_DOUBLE_EQ(json_number(mapped.out, "linf"), 0.25);
  EXPECT_EQ(mapped.err, "");
  // A map that pairs the wrong vertices: the triangles tell.
  const std::string wrong = write_scratch_file("b6-wrong.map", "0\n1\n2\n3\n");
  const CommandResult w = run_gab("diff " + a + " " + b + " --map " + wrong + " --json");
  ASSERT_EQ(w.exit_code, 0) << w.err;
  EXPECT_TRUE(json_null(w.out, "rms"));
  EXPECT_EQ(w.err, "gab diff: no per-vertex distances: the triangles differ by vertex index under --map " + wrong +
                       "\n");
}

TEST(DiffCliTest, AMapThatIsNotAPermutationIsAnErrorNamingItsLine) {
  const std::string a = write_scratch_file("a7.off", square_off(0));
  const std::string b = write_scratch_file("b7.off", square_off(1));
  struct Case {
    const char* name;
    const char* text;
    std::string message;
  };
  for (const Case& c : {Case{"m1.map", "0\n1\nx\n3\n", ": line 3: 'x' is not a vertex index"},
                        Case{"m2.map", "0\n1\n4\n3\n", ": line 3: index 4 is outside 0..3"},
                        Case{"m3.map", "0\n1\n-1\n3\n", ": line 3: index -1 is outside 0..3"},
                        Case{"m4.map", "0\n1\n1\n3\n", ": line 3: index 1 is given twice"},
                        Case{"m5.map", "0\n1\n2\n3\n0\n", ": line 5: more indices than A's 4 vertices"},
                        Case{"m6.map", "0\n1\n2\n", ": 3 indices for A's 4 vertices"}}) {
    const std::string map = write_scratch_file(c.name, c.text);
    const CommandResult r = run_gab("diff " + a + " " + b + " --map " + map);
    EXPECT_EQ(r.exit_code, 1) << c.name;
    EXPECT_EQ(r.err, "gab: error: " + map + c.message + "\n") << c.name;
    EXPECT_EQ(r.out, "") << c.name;
  }
}

TEST(DiffCliTest, NoSamplesLeavesOnlyTheVertexHausdorff) {
  const std::string a = write_scratch_file("a5.off", square_off(0));
  const std::string b = write_scratch_file("b5.off", square_off(2));
  const CommandResult r = run_gab("diff " + a + " " + b + " --samples 0 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(json_null(r.out, "metro_mean_rel"));
  EXPECT_TRUE(json_null(r.out, "metro_rms_rel"));
  EXPECT_NEAR(json_number(r.out, "hausdorff_rel"), 2 / std::sqrt(2.0), 1e-8);
}

TEST(DiffCliTest, HumanReadableOutput) {
  const std::string a = write_scratch_file("a3.off", square_off(0));
  const std::string b = write_scratch_file("b3.off", square_off(0.5));
  const CommandResult r = run_gab("diff " + a + " " + b + " --samples 100");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("vertex distance: max 0.5"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Hausdorff 0.5"), std::string::npos) << r.out;
}

TEST(DiffCliTest, ABoxOfNoSizeHasNoRelativeDistances) {
  const std::string p = write_scratch_file("point.off", "OFF\n3 1 0\n1 1 1\n1 1 1\n1 1 1\n3 0 1 2\n");
  const CommandResult r = run_gab("diff " + p + " " + p + " --samples 10");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("bounding-box diagonal 0 (no size: no relative distances)"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("vertex distance: max 0 (n/a of the diagonal), rms 0 (n/a)"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("nan"), std::string::npos) << r.out;
}

TEST(DiffCliTest, BadInputExitsOneWithOneLine) {
  const std::string a = write_scratch_file("a4.off", square_off(0));
  const std::string bad = write_scratch_file("bad.ply", square_off(0));
  CommandResult r = run_gab("diff " + a + " " + bad + " --json");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.out, "");
  EXPECT_EQ(r.err, "gab: error: " + bad + ": not a PLY file (it looks like OFF)\n");
  r = run_gab("diff /nonexistent/a.obj " + a);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "gab: error: /nonexistent/a.obj: cannot open: No such file or directory\n");
  const std::string hostile = write_scratch_file("hostile.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 9\n");
  r = run_gab("diff " + hostile + " " + a);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "gab: error: " + hostile + ":6: face 0: vertex index 9 out of range [0, 3)\n");
  r = run_gab("diff " + a + " model.stl");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "gab: error: model.stl: unsupported mesh type '.stl' (expected .obj, .off or .ply)\n");
}

TEST(DiffCliTest, BadUsageExitsTwo) {
  EXPECT_EQ(run_gab("diff").exit_code, 2);
  EXPECT_EQ(run_gab("diff a.off").exit_code, 2);
  EXPECT_EQ(run_gab("diff a.off b.off c.off").exit_code, 2);
  const CommandResult r = run_gab("diff a.off b.off --samples lots");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--samples must be an integer in [0, 1000000000], got 'lots'"), std::string::npos) << r.err;
  EXPECT_EQ(run_gab("diff a.off b.off --samples -5").exit_code, 2);
  EXPECT_EQ(run_gab("diff a.off b.off --frobnicate").exit_code, 2);
}

TEST(DiffCliTest, FactorReadsEveryMeshFormat) {
  const std::string obj = write_scratch_file("sq.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
  const std::string ply = write_scratch_file(
      "sq.ply",
      "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n");
  for (const std::string& path : {obj, ply}) {
    const CommandResult r = run_gab("factor " + path + " --json --anchors 1 --repeat 1");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(json_number(r.out, "n"), 4) << path;
    EXPECT_LT(json_number(r.out, "residual"), 1e-12) << path;
  }
}

}  // namespace
