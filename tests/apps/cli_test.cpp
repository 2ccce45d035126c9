// The CLI contract (docs/cli.md), by running the gab binary.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "run_gab.h"

namespace {

using gab_test::CommandResult;
using gab_test::run_gab;
using gab_test::write_scratch_file;

// A closed octahedron: 6 vertices, 8 faces.
const char* kOctahedron =
    "OFF\n6 8 0\n1 0 0\n-1 0 0\n0 1 0\n0 -1 0\n0 0 1\n0 0 -1\n"
    "3 0 2 4\n3 2 1 4\n3 1 3 4\n3 3 0 4\n3 2 0 5\n3 1 2 5\n3 3 1 5\n3 0 3 5\n";

TEST(CliTest, FactorJsonHasTheContractKeys) {
  const std::string path = write_scratch_file("octa.off", kOctahedron);
  const CommandResult r = run_gab("factor " + path + " --json --anchors 2 --repeat 2");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* key : {"\"n\": 6", "\"nnz_A\": 21", "\"nnz_L\":", "\"flops\":", "\"supernodes\":",
                          "\"etree_height\":", "\"order_s\":", "\"symbolic_s\":", "\"factor_s\":",
                          "\"solve_s\":", "\"gflops\":", "\"residual\":"}) {
    EXPECT_NE(r.out.find(key), std::string::npos) << key << " missing in " << r.out;
  }
  // Exactly one line: one JSON object and nothing else on stdout.
  EXPECT_EQ(r.out.front(), '{');
  EXPECT_EQ(r.out.find('\n'), r.out.size() - 1);
}

TEST(CliTest, FactorReportsItsThreadsAndTheSameResidualWithAny) {
  const std::string path = write_scratch_file("octa-t.off", kOctahedron);
  const CommandResult one = run_gab("factor " + path + " --json --anchors 2 --repeat 1");
  const CommandResult two = run_gab("factor " + path + " --json --anchors 2 --repeat 1 --threads 2");
  ASSERT_EQ(one.exit_code, 0) << one.err;
  ASSERT_EQ(two.exit_code, 0) << two.err;
  EXPECT_NE(one.out.find("\"threads\": 1"), std::string::npos) << one.out;
  EXPECT_NE(two.out.find("\"threads\": 2"), std::string::npos) << two.out;
  const std::string key = "\"residual\": ";
  const std::string r1 = one.out.substr(one.out.find(key)), r2 = two.out.substr(two.out.find(key));
  EXPECT_EQ(r1.substr(0, r1.find(',')), r2.substr(0, r2.find(',')));
  EXPECT_EQ(run_gab("factor " + path + " --threads 65").exit_code, 2);
}

TEST(CliTest, FactorMatrixMarketResidualIsTiny) {
  const std::string path = write_scratch_file(
      "spd.mtx", "%%MatrixMarket matrix coordinate real symmetric\n3 3 5\n1 1 4\n2 1 1\n2 2 4\n3 2 1\n3 3 4\n");
  const CommandResult r = run_gab("factor " + path + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const size_t at = r.out.find("\"residual\": ");
  ASSERT_NE(at, std::string::npos);
  EXPECT_LT(std::stod(r.out.substr(at + 12)), 1e-14);
}

TEST(CliTest, BadInputExitsOneWithOneLine) {
  const CommandResult r = run_gab("factor /nonexistent/x.off");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "gab: error: /nonexistent/x.off: cannot open: No such file or directory\n");
  EXPECT_EQ(r.out, "");
  const std::string bad = write_scratch_file("bad.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n");
  const CommandResult r2 = run_gab("factor " + bad + " --json");
  EXPECT_EQ(r2.exit_code, 1);
  EXPECT_EQ(r2.err, "gab: error: " + bad + ":6: face 0: vertex index 7 out of range [0, 3)\n");
}

TEST(CliTest, MemoryExhaustionExitsOneWithOneLine) {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
  GTEST_SKIP() << "a sanitizer's shadow memory does not start under an address-space cap";
#endif
  // /dev/zero never ends: reading it as a file runs out of a 200 MB address space.
  const CommandResult r = run_gab("info /dev/zero", "ulimit -v 200000 &&");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "gab: error: out of memory (info)\n");
}

TEST(CliTest, NotPositiveDefiniteIsAFailureNamingTheColumn) {
  const std::string path = write_scratch_file(
      "indef.mtx", "%%MatrixMarket matrix coordinate real symmetric\n2 2 2\n1 1 1\n2 2 -1\n");
  const CommandResult r = run_gab("factor " + path + " --ordering natural");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("not positive definite: pivot 1"), std::string::npos) << r.err;
}

TEST(CliTest, BadUsageExitsTwo) {
  EXPECT_EQ(run_gab("").exit_code, 2);
  EXPECT_EQ(run_gab("frobnicate").exit_code, 2);
  EXPECT_EQ(run_gab("factor").exit_code, 2);
  const CommandResult r = run_gab("factor a.off --ordering metis");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--ordering must be amd, nd or natural, got 'metis'"), std::string::npos);
  // auto is the codec's choice by size; factor and study measure a named ordering.
  for (const char* command : {"factor", "study"}) {
    const CommandResult a = run_gab(std::string(command) + " a.off --ordering auto");
    EXPECT_EQ(a.exit_code, 2) << command;
    EXPECT_NE(a.err.find("--ordering must be amd, nd or natural"), std::string::npos) << a.err;
  }
  EXPECT_EQ(run_gab("factor a.off --repeat 0").exit_code, 2);
  EXPECT_EQ(run_gab("factor a.off --bogus").exit_code, 2);
  EXPECT_EQ(run_gab("help").exit_code, 0);
}

TEST(CliTest, EveryCommandAnswersHelp) {
  // --help or -h anywhere after the command: its usage and summary on
  // stdout, exit 0, nothing run (no input read, no output written).
  for (const char* command :
       {"factor", "study", "diff", "subdivide", "compress", "decompress", "info", "demo", "version"}) {
    const CommandResult r = run_gab(std::string(command) + " --help");
    EXPECT_EQ(r.exit_code, 0) << command << ": " << r.err;
    EXPECT_EQ(r.out.rfind(std::string("usage: gab ") + command, 0), 0u) << r.out;
    EXPECT_NE(r.out.find("every command: gab help"), std::string::npos) << r.out;
    EXPECT_EQ(r.err, "") << command;
    EXPECT_EQ(run_gab(std::string(command) + " -h").out, r.out) << command;
  }
  const std::string out = write_scratch_file("help-not-written.gab", "untouched");
  const CommandResult r = run_gab("compress -i missing.off -o " + out + " --help");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  std::ifstream in(out);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), "untouched");
}

TEST(CliTest, OutputsAreCheckedBeforeTheWork) {
  // A new output in a folder that does not exist: refused before the input
  // is read (a missing input would be the error otherwise). An output that
  // is the input, by name or through a link: a usage error, the input
  // untouched. A directory: refused.
  const std::string mesh = write_scratch_file("outputs-in.off", kOctahedron);
  const std::string folder = mesh.substr(0, mesh.find_last_of('/'));
  CommandResult r = run_gab("compress -i missing.off -o " + folder + "/no-such-folder/out.gab");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "gab: error: " + folder + "/no-such-folder/out.gab: cannot write: the folder " + folder +
                       "/no-such-folder does not exist\n");
  r = run_gab("decompress -i missing.gab -o " + folder + "/no-such-folder/out.ply");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("does not exist"), std::string::npos) << r.err;
  const std::string link = folder + "/outputs-link.off";
  ::unlink(link.c_str());
  ASSERT_EQ(::symlink(mesh.c_str(), link.c_str()), 0);
  for (const std::string& command : {"compress -i " + mesh + " -o " + mesh, "compress -i " + mesh + " -o " + link,
                                     "subdivide " + mesh + " -o " + link,
                                     "decompress -i x.gab --connectivity " + mesh + " -o " + mesh}) {
    r = run_gab(command);
    EXPECT_EQ(r.exit_code, 2) << command;
    EXPECT_NE(r.err.find(": writing it would replace the input\nusage: gab "), std::string::npos) << r.err;
    std::ifstream in(mesh);
    EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), kOctahedron) << command;
  }
  r = run_gab("compress -i " + mesh + " -o " + folder);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "gab: error: " + folder + ": cannot write: Is a directory\n");
  ::unlink(link.c_str());
}

TEST(CliTest, UnsupportedExtensionIsBadInput) {
  const CommandResult r = run_gab("factor model.stl");
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "gab: error: model.stl: unsupported input type '.stl' (expected .obj, .off, .ply or .mtx)\n");
}

}  // namespace

namespace {

TEST(CliStudyTest, JsonCsvAndSvg) {
  const std::string path = write_scratch_file("octa_study.off", kOctahedron);
  const std::string csv = gab_test::scratch_path("study.csv");
  const std::string svg = gab_test::scratch_path("study.svg");
  const CommandResult r = run_gab("study " + path + " --anchors 1 --updates 4 --json --csv " + csv + " --svg " + svg);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* key : {"\"n\": 6", "\"nnz_L\":", "\"updates\": 4", "\"path_len_avg\":", "\"path_len_max\":",
                          "\"touched_avg\":", "\"touched_max\":", "\"update_s_avg\":", "\"update_s_median\":",
                          "\"update_s_max\":", "\"factor_s\":", "\"drift\":"}) {
    EXPECT_NE(r.out.find(key), std::string::npos) << key << " missing in " << r.out;
  }
  std::ifstream c(csv);
  std::string header, line;
  std::getline(c, header);
  // The original columns, then the ordering and the separator bound (empty: AMD has no separator tree).
  EXPECT_EQ(header,
            "input,update,vertex,anchors,path_columns,path_supernodes,touched,flops,seconds,ordering,separator_bound");
  std::getline(c, line);
  EXPECT_EQ(line.substr(line.size() - 5), ",amd,") << line;
  int rows = 1;
  while (std::getline(c, line)) ++rows;
  EXPECT_EQ(rows, 4);
  std::ifstream s(svg);
  std::string first;
  std::getline(s, first);
  EXPECT_EQ(first.rfind("<svg", 0), 0u);
}

// The value of a JSON number key in one-line output ("" when missing).
std::string json_value(const std::string& out, const std::string& key) {
  const size_t at = out.find("\"" + key + "\": ");
  if (at == std::string::npos) return "";
  const size_t begin = at + key.size() + 4;
  return out.substr(begin, out.find_first_of(",}", begin) - begin);
}

TEST(CliStudyTest, TwoThreadsGiveTheSameUpdatesAndDrift) {
  // A 7-point Laplacian on a 16^3 grid, whose top supernodes the two-thread
  // factorization and solves split.
  const int32_t g = 16, n = g * g * g;
  std::string mtx = "%%MatrixMarket matrix coordinate real symmetric\n";
  std::string entries;
  int64_t count = 0;
  for (int32_t v = 0; v < n; ++v) {
    const int32_t x = v % g, y = v / g % g, z = v / (g * g);
    entries += std::to_string(v + 1) + " " + std::to_string(v + 1) + " 6.5\n";
    ++count;
    for (int32_t d : {x + 1 < g ? 1 : 0, y + 1 < g ? g : 0, z + 1 < g ? g * g : 0}) {
      if (d == 0) continue;
      entries += std::to_string(v + d + 1) + " " + std::to_string(v + 1) + " -1\n";
      ++count;
    }
  }
  mtx += std::to_string(n) + " " + std::to_string(n) + " " + std::to_string(count) + "\n" + entries;
  const std::string path = write_scratch_file("grid3d_study.mtx", mtx);
  const CommandResult one = run_gab("study " + path + " --updates 60 --json");
  const CommandResult two = run_gab("study " + path + " --updates 60 --threads 2 --json");
  ASSERT_EQ(one.exit_code, 0) << one.err;
  ASSERT_EQ(two.exit_code, 0) << two.err;
  EXPECT_EQ(json_value(one.out, "threads"), "1");
  EXPECT_EQ(json_value(two.out, "threads"), "2");
  for (const char* key : {"touched_avg", "path_len_avg", "drift"}) {
    EXPECT_FALSE(json_value(one.out, key).empty()) << key;
    EXPECT_EQ(json_value(one.out, key), json_value(two.out, key)) << key;
  }
  EXPECT_EQ(json_value(one.out, "ordering"), "\"amd\"");

  // The nested-dissection ordering: the same updates on another factor.
  const CommandResult nd = run_gab("study " + path + " --updates 60 --ordering nd --json");
  ASSERT_EQ(nd.exit_code, 0) << nd.err;
  EXPECT_EQ(json_value(nd.out, "ordering"), "\"nd\"");
  EXPECT_LT(std::stod(json_value(nd.out, "drift")), 1e-9);
  EXPECT_NE(json_value(nd.out, "nnz_L"), json_value(one.out, "nnz_L"));
  const CommandResult factor = run_gab("factor " + path + " --ordering nd --repeat 1 --json");
  ASSERT_EQ(factor.exit_code, 0) << factor.err;
  EXPECT_EQ(json_value(factor.out, "ordering"), "\"nd\"");
  EXPECT_LT(std::stod(json_value(factor.out, "residual")), 1e-12);
}

// A triangulated k x k grid as OFF text.
std::string grid_off(int32_t k) {
  std::string off = "OFF\n" + std::to_string(k * k) + " " + std::to_string(2 * (k - 1) * (k - 1)) + " 0\n";
  for (int32_t y = 0; y < k; ++y) {
    for (int32_t x = 0; x < k; ++x) off += std::to_string(x) + " " + std::to_string(y) + " 0\n";
  }
  for (int32_t y = 0; y + 1 < k; ++y) {
    for (int32_t x = 0; x + 1 < k; ++x) {
      const int32_t v = y * k + x;
      off += "3 " + std::to_string(v) + " " + std::to_string(v + 1) + " " + std::to_string(v + k + 1) + "\n";
      off += "3 " + std::to_string(v) + " " + std::to_string(v + k + 1) + " " + std::to_string(v + k) + "\n";
    }
  }
  return off;
}

// The lines of a text.
std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  size_t begin = 0;
  while (begin < text.size()) {
    const size_t end = text.find('\n', begin);
    lines.push_back(text.substr(begin, end - begin));
    if (end == std::string::npos) break;
    begin = end + 1;
  }
  return lines;
}

TEST(CliStudyTest, OrderingListStudiesEachInputUnderEachOrdering) {
  const std::string small = write_scratch_file("grid40.off", grid_off(40));
  const std::string large = write_scratch_file("grid90.off", grid_off(90));
  const std::string svg = gab_test::scratch_path("orderings.svg");
  const CommandResult r =
      run_gab("study " + small + " " + large + " --ordering amd,nd --updates 40 --json --svg " + svg);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<std::string> lines = lines_of(r.out);
  ASSERT_EQ(lines.size(), 4u) << r.out;  // one object per input and ordering, inputs outermost
  const char* expected[] = {"\"amd\"", "\"nd\"", "\"amd\"", "\"nd\""};
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(json_value(lines[i], "ordering"), expected[i]) << lines[i];
    EXPECT_EQ(json_value(lines[i], "n"), i < 2 ? "1600" : "8100") << lines[i];
  }
  for (size_t i : {0u, 2u}) EXPECT_EQ(json_value(lines[i], "separator_bound_avg"), "null") << lines[i];
  for (size_t i : {1u, 3u}) {
    // The bound holds per update, so on average: it bounds the true path's entries.
    const double bound = std::stod(json_value(lines[i], "separator_bound_avg"));
    const double touched = std::stod(json_value(lines[i], "true_touched_avg"));
    EXPECT_GE(bound, touched) << lines[i];
    EXPECT_GT(touched, 0.0) << lines[i];
  }
  // The fitted growth exponent of each ordering: on stderr beside --json, and in the plot.
  for (const char* ordering : {"amd", "nd"}) {
    const std::string printed = std::string(ordering) + ": touched entries per update grow as n^";
    const size_t at = r.err.find(printed);
    ASSERT_NE(at, std::string::npos) << r.err;
    const double exponent = std::stod(r.err.substr(at + printed.size()));
    EXPECT_GT(exponent, 0.3) << ordering;  // grows with n, and no faster than n^2 (a dense factor)
    EXPECT_LT(exponent, 2.0) << ordering;
  }
  std::ifstream in(svg);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("amd: touched ~ n^"), std::string::npos);
  EXPECT_NE(text.find("nd: touched ~ n^"), std::string::npos);
  EXPECT_NE(text.find("separator bound"), std::string::npos);
}

TEST(CliStudyTest, UpdatesStopWhenEveryVertexIsAnchored) {
  const std::string path = write_scratch_file("octa_all.off", kOctahedron);
  const CommandResult r = run_gab("study " + path + " --anchors 2 --updates 100 --batch 3 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("\"updates\": 4"), std::string::npos) << r.out;  // 6 vertices, 2 anchored
}

TEST(CliStudyTest, BadUsage) {
  EXPECT_EQ(run_gab("study").exit_code, 2);
  EXPECT_EQ(run_gab("study a.off --batch 0").exit_code, 2);
  EXPECT_EQ(run_gab("study a.off --ordering metis").exit_code, 2);
  EXPECT_EQ(run_gab("study a.off --ordering amd,metis").exit_code, 2);
  EXPECT_EQ(run_gab("study a.off --ordering amd,").exit_code, 2);
  EXPECT_EQ(run_gab("study a.off --ordering nd,nd").exit_code, 2);
  EXPECT_EQ(run_gab("study a.off --threads 0").exit_code, 2);
  const CommandResult r = run_gab("study /nonexistent.off");
  EXPECT_EQ(r.exit_code, 1);
}

TEST(CliTest, SubdivideWritesTheFinerMesh) {
  // The octahedron: 6 vertices, 12 edges, 8 triangles. One level adds a
  // vertex per edge (18) and quadruples the triangles (32, with 48 edges);
  // the second gives 18 + 48 = 66 vertices and 128 triangles.
  const std::string in = write_scratch_file("octa-sub.off", kOctahedron);
  const std::string out = write_scratch_file("octa-sub2.obj", "");
  CommandResult r = run_gab("subdivide " + in + " -o " + out + " --levels 2");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("66 vertices, 128 triangles after 2 levels"), std::string::npos) << r.out;
  r = run_gab("factor " + out + " --json");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("\"n\": 66,"), std::string::npos) << r.out;
  r = run_gab("subdivide " + in + " -o " + out + " --levels 9");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--levels"), std::string::npos) << r.err;
}

}  // namespace
