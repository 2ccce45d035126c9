// `gab compress / decompress / info / demo` (the CLI contract), by running
// the gab binary.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "run_gab.h"

namespace {

using gab_test::CommandResult;
using gab_test::json_null;
using gab_test::json_number;
using gab_test::run_gab;
using gab_test::write_scratch_file;

// A bumpy torus as OFF text (n x m vertices).
std::string torus_off(int n, int m) {
  const double kPi = 3.14159265358979323846;
  std::ostringstream s;
  s.precision(17);
  s << "OFF\n" << n * m << " " << 2 * n * m << " 0\n";
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < m; ++j) {
      const double u = 2 * kPi * i / n, v = 2 * kPi * j / m;
      const double r = 0.3 * (1 + 0.2 * std::sin(3 * u + 1) * std::cos(2 * v));
      s << (1 + r * std::cos(v)) * std::cos(u) << " " << (1 + r * std::cos(v)) * std::sin(u) << " "
        << r * std::sin(v) << "\n";
    }
  }
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < m; ++j) {
      const int a = i * m + j, b = ((i + 1) % n) * m + j, c = ((i + 1) % n) * m + (j + 1) % m, d = i * m + (j + 1) % m;
      s << "3 " << a << " " << b << " " << c << "\n3 " << a << " " << c << " " << d << "\n";
    }
  }
  return s.str();
}

std::string read_all(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>());
}

bool is_one_json_line(const std::string& out) {
  return !out.empty() && out.front() == '{' && out.find('\n') == out.size() - 1 && out[out.size() - 2] == '}';
}

TEST(CodecCliTest, CompressWritesStdoutAndDevicesInPlace) {
  const std::string in = write_scratch_file("stdout.off", torus_off(20, 10));
  const std::string gab = write_scratch_file("stdout.gab", "");
  ASSERT_EQ(run_gab("compress -i " + in + " -o " + gab + " --anchors 30").exit_code, 0);
  // The file alone on stdout: the summary moves to stderr.
  const CommandResult piped = run_gab("compress -i " + in + " -o /dev/stdout --anchors 30");
  ASSERT_EQ(piped.exit_code, 0) << piped.err;
  EXPECT_EQ(piped.out, read_all(gab));
  EXPECT_NE(piped.err.find(" -> /dev/stdout: 200 vertices"), std::string::npos) << piped.err;
  EXPECT_EQ(run_gab("compress -i " + in + " -o /dev/null --anchors 30").exit_code, 0);
  const CommandResult full = run_gab("compress -i " + in + " -o /dev/full --anchors 30");
  EXPECT_EQ(full.exit_code, 1);
  EXPECT_EQ(full.err, "gab: error: /dev/full: cannot write: No space left on device\n");
}

TEST(CodecCliTest, CompressDecompressInfoRoundTrip) {
  const std::string in = write_scratch_file("rt.off", torus_off(40, 20));
  const std::string gab = write_scratch_file("rt.gab", "");
  const std::string out = write_scratch_file("rt-out.ply", "");
  const std::string map = write_scratch_file("rt.map", "");
  CommandResult c = run_gab("compress -i " + in + " -o " + gab + " --anchors 60 --order-out " + map + " --json");
  ASSERT_EQ(c.exit_code, 0) << c.err;
  ASSERT_TRUE(is_one_json_line(c.out)) << c.out;
  for (const char* key : {"n", "faces", "anchors", "bits", "bytes", "geometry_bytes", "connectivity_bytes",
                          "order_bytes", "bpv_geometry", "linf_rel", "rms_rel", "encode_s"}) {
    EXPECT_FALSE(std::isnan(json_number(c.out, key))) << key;
  }
  EXPECT_EQ(json_number(c.out, "n"), 800);
  EXPECT_EQ(json_number(c.out, "faces"), 1600);
  EXPECT_EQ(json_number(c.out, "anchors"), 60);
  EXPECT_EQ(json_number(c.out, "bytes"), static_cast<double>(read_all(gab).size()));
  EXPECT_EQ(json_number(c.out, "geometry_bytes") + json_number(c.out, "connectivity_bytes") +
                json_number(c.out, "order_bytes"),
            json_number(c.out, "bytes"));
  EXPECT_NEAR(json_number(c.out, "bpv_geometry"), 8 * json_number(c.out, "geometry_bytes") / 800, 1e-6);

  CommandResult d = run_gab("decompress -i " + gab + " -o " + out + " --json");
  ASSERT_EQ(d.exit_code, 0) << d.err;
  ASSERT_TRUE(is_one_json_line(d.out)) << d.out;
  for (const char* key : {"n", "anchors", "decode_s", "factor_s", "solve_s", "update_s"}) {
    EXPECT_FALSE(std::isnan(json_number(d.out, key))) << key;
  }
  EXPECT_EQ(json_number(d.out, "anchors"), 60);
  // The decoded mesh is what the encoder reported, in the traversal's
  // vertex order (the default) that the map pairs back.
  CommandResult diff = run_gab("diff " + in + " " + out + " --map " + map + " --json --samples 0");
  ASSERT_EQ(diff.exit_code, 0) << diff.err;
  EXPECT_NEAR(json_number(diff.out, "rms_rel"), json_number(c.out, "rms_rel"), 1e-9);
  EXPECT_NEAR(json_number(diff.out, "linf_rel"), json_number(c.out, "linf_rel"), 1e-9);

  // A file with its own connectivity: --connectivity is ignored, and said so.
  const CommandResult ignored = run_gab("decompress -i " + gab + " -o " + out + " --connectivity " + in);
  ASSERT_EQ(ignored.exit_code, 0) << ignored.err;
  EXPECT_EQ(ignored.err, "gab decompress: warning: --connectivity ignored: " + gab + " carries its own connectivity\n");

  CommandResult i = run_gab("info " + gab + " --json");
  ASSERT_EQ(i.exit_code, 0) << i.err;
  EXPECT_EQ(json_number(i.out, "anchors"), 60);
  EXPECT_EQ(json_number(i.out, "bytes"), json_number(c.out, "bytes"));
  EXPECT_EQ(json_number(i.out, "connectivity_bytes"), json_number(c.out, "connectivity_bytes"));
  EXPECT_EQ(json_number(i.out, "order_bytes"), json_number(c.out, "order_bytes"));
  EXPECT_EQ(json_number(i.out, "version"), 2);
  EXPECT_EQ(json_number(i.out, "reconstruction"), 3);  // the iterative operator, the default
  EXPECT_NE(i.out.find("\"solver\": \"iterative\""), std::string::npos) << i.out;
  EXPECT_EQ(json_number(i.out, "sections"), 0);
}

// `gab ARGS` on a pseudo-terminal (util-linux's script): what the terminal
// shows, stdout and stderr together.
std::string on_terminal(const std::string& args, int delay_ms) {
  const std::string cmd = "GAB_PROGRESS_DELAY_MS=" + std::to_string(delay_ms) + " script -qec '" +
                          std::string(GAB_BINARY) + " " + args + "' /dev/null";
  std::string shown;
  FILE* p = popen(cmd.c_str(), "r");
  if (p == nullptr) return shown;
  char buf[4096];
  size_t got;
  while ((got = fread(buf, 1, sizeof(buf), p)) > 0) shown.append(buf, got);
  pclose(p);
  return shown;
}

TEST(CodecCliTest, ProgressLineOnATerminalOnceTheWorkRunsLongAndQuietSilencesIt) {
  if (std::system("command -v script >/dev/null 2>&1") != 0) {
    GTEST_SKIP() << "util-linux's script (a pseudo-terminal) is not installed";
  }
  const std::string in = write_scratch_file("progress.off", torus_off(40, 20));
  const std::string gab = write_scratch_file("progress.gab", "");
  const std::string out = write_scratch_file("progress.ply", "");
  // No delay: the line shows (rewritten in place, ended by a newline).
  const std::string compress = "compress -i " + in + " -o " + gab;
  std::string shown = on_terminal(compress, 0);
  EXPECT_NE(shown.find("\rgab compress: "), std::string::npos) << shown;
  EXPECT_NE(shown.find(" of the diagonal"), std::string::npos) << shown;
  shown = on_terminal("decompress -i " + gab + " -o " + out, 0);
  EXPECT_NE(shown.find("\rgab decompress: chunk 1 of "), std::string::npos) << shown;
  // Work shorter than the delay, --quiet, or stderr not a terminal: none
  // (the terminal ends lines with \r\n: the progress texts are looked for).
  auto has_progress = [](const std::string& text) {
    return text.find("anchors, rms") != std::string::npos || text.find("decompress: chunk") != std::string::npos;
  };
  for (const std::string& args : {compress, "decompress -i " + gab + " -o " + out}) {
    shown = on_terminal(args, 600000);
    EXPECT_FALSE(has_progress(shown)) << shown;
    EXPECT_NE(shown.find(" -> "), std::string::npos) << shown;  // the result shows
    shown = on_terminal(args + " --quiet", 0);
    EXPECT_FALSE(has_progress(shown)) << shown;
    EXPECT_NE(shown.find(" -> "), std::string::npos) << shown;
    const CommandResult r = run_gab(args, "GAB_PROGRESS_DELAY_MS=0");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_FALSE(has_progress(r.err)) << r.err;
  }
}

// The numbering (a contract change, docs/cli.md): by default the decoded
// mesh is numbered in the coder's traversal order and the order block is
// gone; --reorder spells the default out; --keep-order keeps the input's
// numbering and pays for it.
TEST(CodecCliTest, TheDefaultDropsTheVertexOrderAndKeepOrderPaysForIt) {
  const std::string in = write_scratch_file("reorder.off", torus_off(40, 20));
  const std::string kept = write_scratch_file("kept.gab", ""), reordered = write_scratch_file("reordered.gab", "");
  const std::string spelled = write_scratch_file("reordered-spelled.gab", "");
  const std::string out = write_scratch_file("reordered-out.off", "");
  const CommandResult a = run_gab("compress -i " + in + " -o " + kept + " --keep-order --json");
  const CommandResult b = run_gab("compress -i " + in + " -o " + reordered + " --json");
  const CommandResult r = run_gab("compress -i " + in + " -o " + spelled + " --reorder --json");
  ASSERT_EQ(a.exit_code, 0) << a.err;
  ASSERT_EQ(b.exit_code, 0) << b.err;
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_all(spelled), read_all(reordered));  // --reorder: the default, spelled out
  EXPECT_NE(a.out.find("\"reordered\": false"), std::string::npos) << a.out;
  EXPECT_NE(b.out.find("\"reordered\": true"), std::string::npos) << b.out;
  EXPECT_EQ(json_number(b.out, "order_bytes"), 0);
  // The torus is numbered ring by ring: its order costs a small part of
  // log2(800!) / 8 = 822 bytes, the price of an arbitrary numbering.
  EXPECT_GT(json_number(a.out, "order_bytes"), 0);
  EXPECT_LT(json_number(a.out, "order_bytes"), 82);
  EXPECT_EQ(json_number(b.out, "connectivity_bytes"), json_number(a.out, "connectivity_bytes"));
  EXPECT_LT(json_number(b.out, "bytes"), json_number(a.out, "bytes"));
  // The human line names the order block either way (0 by default).
  const CommandResult human = run_gab("compress -i " + in + " -o " + reordered);
  ASSERT_EQ(human.exit_code, 0) << human.err;
  EXPECT_NE(human.out.find(", vertex order 0, attributes 0); "), std::string::npos) << human.out;
  const CommandResult d = run_gab("decompress -i " + reordered + " -o " + out + " --json");
  ASSERT_EQ(d.exit_code, 0) << d.err;
  EXPECT_NE(d.out.find("\"reordered\": true"), std::string::npos) << d.out;
  EXPECT_EQ(json_number(d.out, "n"), 800);
  EXPECT_GE(json_number(d.out, "connectivity_s"), 0);
  const CommandResult i = run_gab("info " + reordered);
  EXPECT_NE(i.out.find("(valence coded), vertices in traversal order"), std::string::npos) << i.out;
  const CommandResult k = run_gab("info " + kept);
  EXPECT_NE(k.out.find("(valence coded), vertex order " + std::to_string(static_cast<int>(json_number(a.out, "order_bytes")))),
            std::string::npos)
      << k.out;
  // --geometry-only keeps the numbering (no connectivity to traverse), with
  // or without --keep-order; --reorder asks for what it cannot do.
  const CommandResult geometry = run_gab("compress -i " + in + " -o " + kept + " --geometry-only --json");
  ASSERT_EQ(geometry.exit_code, 0) << geometry.err;
  EXPECT_NE(geometry.out.find("\"reordered\": false"), std::string::npos) << geometry.out;
  EXPECT_EQ(json_number(geometry.out, "order_bytes"), 0);
  const std::string geometry_file = read_all(kept);
  const CommandResult geometry_kept = run_gab("compress -i " + in + " -o " + kept + " --geometry-only --keep-order");
  ASSERT_EQ(geometry_kept.exit_code, 0) << geometry_kept.err;
  EXPECT_EQ(read_all(kept), geometry_file);
  const CommandResult both = run_gab("compress -i " + in + " -o " + kept + " --reorder --geometry-only");
  EXPECT_EQ(both.exit_code, 2);
  EXPECT_EQ(both.err.substr(0, both.err.find('\n')),
            "gab compress: --reorder codes the connectivity: it cannot go with --geometry-only");
  const CommandResult contradiction = run_gab("compress -i " + in + " -o " + kept + " --reorder --keep-order");
  EXPECT_EQ(contradiction.exit_code, 2);
  EXPECT_EQ(contradiction.err.substr(0, contradiction.err.find('\n')),
            "gab compress: give --reorder (the default) or --keep-order, not both");
}

// --keep-order: vertex i of the decoded mesh is input vertex i, within the
// error the encoder reports, for whoever keys data by vertex index.
TEST(CodecCliTest, KeepOrderDecodesVertexByVertexOntoTheInput) {
  const std::string in = write_scratch_file("keep-order.off", torus_off(36, 18));
  const std::string file = write_scratch_file("keep-order.gab", "");
  const std::string out = write_scratch_file("keep-order-out.off", "");
  const CommandResult c = run_gab("compress -i " + in + " -o " + file + " --keep-order --error 2e-3 --json");
  ASSERT_EQ(c.exit_code, 0) << c.err;
  ASSERT_EQ(run_gab("decompress -i " + file + " -o " + out).exit_code, 0);
  auto positions = [](const std::string& off) {
    std::istringstream s(read_all(off));
    std::string magic;
    int n = 0, t = 0, e = 0;
    s >> magic >> n >> t >> e;
    std::vector<double> p(3 * static_cast<size_t>(n));
    for (double& x : p) s >> x;
    return p;
  };
  const std::vector<double> a = positions(in), b = positions(out);
  ASSERT_EQ(a.size(), b.size());
  ASSERT_EQ(a.size(), 3u * 36 * 18);
  double lo[3] = {a[0], a[1], a[2]}, hi[3] = {a[0], a[1], a[2]};
  for (size_t i = 0; i < a.size(); ++i) {
    lo[i % 3] = std::min(lo[i % 3], a[i]);
    hi[i % 3] = std::max(hi[i % 3], a[i]);
  }
  const double diagonal = std::sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                                    (hi[2] - lo[2]) * (hi[2] - lo[2]));
  double sum2 = 0, max2 = 0;
  for (size_t v = 0; v < a.size() / 3; ++v) {
    double d2 = 0;
    for (size_t k = 0; k < 3; ++k) d2 += (a[3 * v + k] - b[3 * v + k]) * (a[3 * v + k] - b[3 * v + k]);
    sum2 += d2;
    max2 = std::max(max2, d2);
  }
  // The OFF text rounds each coordinate to 17 digits: the same to 1e-9.
  const double rms_rel = std::sqrt(sum2 / (a.size() / 3)) / diagonal, linf_rel = std::sqrt(max2) / diagonal;
  EXPECT_NEAR(rms_rel, json_number(c.out, "rms_rel"), 1e-9);
  EXPECT_NEAR(linf_rel, json_number(c.out, "linf_rel"), 1e-9);
  EXPECT_LE(rms_rel, 2e-3 + 1e-9);
  // So gab diff pairs them with no map.
  const CommandResult diff = run_gab("diff " + in + " " + out + " --json --samples 0");
  ASSERT_EQ(diff.exit_code, 0) << diff.err;
  EXPECT_NEAR(json_number(diff.out, "rms_rel"), json_number(c.out, "rms_rel"), 1e-9);
}

TEST(CodecCliTest, OrderOutWritesTheNumberingThatDiffMapPairsBack) {
  const std::string in = write_scratch_file("order-out.off", torus_off(40, 20));
  const std::string file = write_scratch_file("order-out.gab", ""), map = write_scratch_file("order-out.map", "");
  const std::string out = write_scratch_file("order-out-decoded.off", "");
  const CommandResult c = run_gab("compress -i " + in + " -o " + file + " --order-out " + map + " --json");
  ASSERT_EQ(c.exit_code, 0) << c.err;
  ASSERT_EQ(run_gab("decompress -i " + file + " -o " + out).exit_code, 0);
  // The map: line i the decoded index of input vertex i, a permutation
  // (--reorder, the default spelled out, writes the same).
  std::istringstream lines(read_all(map));
  std::vector<int> order;
  for (int v; lines >> v;) order.push_back(v);
  ASSERT_EQ(order.size(), 800u);
  std::vector<int> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  for (int v = 0; v < 800; ++v) ASSERT_EQ(sorted[v], v);
  EXPECT_NE(order, sorted);  // the traversal renumbers
  const std::string spelled_map = write_scratch_file("order-out-spelled.map", "");
  ASSERT_EQ(run_gab("compress -i " + in + " -o " + file + " --reorder --order-out " + spelled_map).exit_code, 0);
  EXPECT_EQ(read_all(spelled_map), read_all(map));
  // Numbered by the traversal, the decode pairs no vertex with its input
  // one; the map pairs them back to the encoder's own error.
  const CommandResult unpaired = run_gab("diff " + in + " " + out + " --json --samples 1000");
  ASSERT_EQ(unpaired.exit_code, 0) << unpaired.err;
  EXPECT_TRUE(json_null(unpaired.out, "rms_rel")) << unpaired.out;
  const CommandResult paired = run_gab("diff " + in + " " + out + " --map " + map + " --json --samples 1000");
  ASSERT_EQ(paired.exit_code, 0) << paired.err;
  EXPECT_EQ(paired.err, "");
  EXPECT_NEAR(json_number(paired.out, "rms_rel"), json_number(c.out, "rms_rel"), 1e-6);
  EXPECT_NEAR(json_number(paired.out, "linf_rel"), json_number(c.out, "linf_rel"), 1e-6);
  // Not with a kept numbering (no map to give), never over -o.
  const CommandResult kept = run_gab("compress -i " + in + " -o " + file + " --keep-order --order-out " + map);
  EXPECT_EQ(kept.exit_code, 2);
  EXPECT_EQ(kept.err.substr(0, kept.err.find('\n')),
            "gab compress: --order-out writes the map onto the traversal's numbering: --keep-order keeps the "
            "input's numbering");
  const CommandResult geometry = run_gab("compress -i " + in + " -o " + file + " --geometry-only --order-out " + map);
  EXPECT_EQ(geometry.exit_code, 2);
  EXPECT_EQ(geometry.err.substr(0, geometry.err.find('\n')),
            "gab compress: --order-out writes the map onto the traversal's numbering: --geometry-only keeps the "
            "input's numbering");
  EXPECT_EQ(run_gab("compress -i " + in + " -o " + file + " --reorder --order-out " + file).exit_code, 2);
  EXPECT_EQ(run_gab("compress -i " + in + " -o " + file + " --reorder --order-out " + in).exit_code, 2);
  // A file not made yet, named two ways: the map does not replace the .gab.
  const std::string fresh = gab_test::scratch_path("order-out-fresh.gab");
  std::remove(fresh.c_str());
  const std::string dir = fresh.substr(0, fresh.find_last_of('/'));
  const std::string other = dir + "/./order-out-fresh.gab";
  const CommandResult twice = run_gab("compress -i " + in + " -o " + fresh + " --reorder --order-out " + other);
  EXPECT_EQ(twice.exit_code, 2) << twice.err;
  EXPECT_NE(twice.err.find("is the input"), std::string::npos) << twice.err;
  const CommandResult info = run_gab("info " + fresh);
  EXPECT_EQ(info.exit_code, 0) << info.err;
}

TEST(CodecCliTest, RefineAddsALeastSquaresChunkThatDecompressApplies) {
  const std::string in = write_scratch_file("refine.off", torus_off(40, 20));
  const std::string plain = write_scratch_file("refine-plain.gab", ""), refined = write_scratch_file("refine.gab", "");
  const std::string out = write_scratch_file("refine-out.off", "");
  // The refinement needs the global solver, which --refine picks.
  CommandResult a = run_gab("compress -i " + in + " -o " + plain + " --anchors 60 --solver global --json");
  const std::string map = write_scratch_file("refine.map", "");
  CommandResult b =
      run_gab("compress -i " + in + " -o " + refined + " --anchors 60 --refine --order-out " + map + " --json");
  ASSERT_EQ(a.exit_code, 0) << a.err;
  ASSERT_EQ(b.exit_code, 0) << b.err;
  EXPECT_NE(a.out.find("\"refined\": false"), std::string::npos) << a.out;
  EXPECT_NE(b.out.find("\"refined\": true"), std::string::npos) << b.out;
  EXPECT_LT(json_number(b.out, "rms_rel"), json_number(a.out, "rms_rel"));
  EXPECT_EQ(json_number(b.out, "unrefined_rms_rel"), json_number(a.out, "rms_rel"));
  EXPECT_GT(json_number(b.out, "refinement_bytes"), 0);
  EXPECT_NE(b.out.find("\"solver\": \"global\""), std::string::npos) << b.out;
  CommandResult d = run_gab("decompress -i " + refined + " -o " + out + " --json");
  ASSERT_EQ(d.exit_code, 0) << d.err;
  EXPECT_NE(d.out.find("\"refined\": true"), std::string::npos) << d.out;
  CommandResult diff = run_gab("diff " + in + " " + out + " --map " + map + " --json --samples 0");
  EXPECT_NEAR(json_number(diff.out, "rms_rel"), json_number(b.out, "rms_rel"), 1e-9);
  CommandResult info = run_gab("info " + refined);
  ASSERT_EQ(info.exit_code, 0) << info.err;
  EXPECT_NE(info.out.find("least-squares refinement of all 60 anchors"), std::string::npos) << info.out;
  CommandResult json = run_gab("info " + refined + " --json");
  EXPECT_EQ(json_number(json.out, "refinement_bytes"), json_number(b.out, "refinement_bytes"));
}

TEST(CodecCliTest, LevelOfDetailFromOneFile) {
  const std::string in = write_scratch_file("lod.off", torus_off(40, 20));
  const std::string gab = write_scratch_file("lod.gab", ""), map = write_scratch_file("lod.map", "");
  ASSERT_EQ(run_gab("compress -i " + in + " -o " + gab + " --anchors 150 --order-out " + map).exit_code, 0);
  double previous = 1.0;
  for (int k : {20, 60, 150}) {
    const std::string out = write_scratch_file("lod-" + std::to_string(k) + ".off", "");
    CommandResult d = run_gab("decompress -i " + gab + " -o " + out + " --anchors " + std::to_string(k) + " --json");
    ASSERT_EQ(d.exit_code, 0) << d.err;
    EXPECT_EQ(json_number(d.out, "anchors"), k);
    CommandResult diff = run_gab("diff " + in + " " + out + " --map " + map + " --json --samples 0");
    const double rms = json_number(diff.out, "rms_rel");
    EXPECT_LT(rms, previous) << k;
    previous = rms;
  }
}

TEST(CodecCliTest, DecodingAtAnotherSimdLevelGivesTheSameAnchors) {
  // Predictions are rounded with a guard band, so a decoder whose floating
  // point differs (scalar kernels here) still decodes the same coefficients:
  // the shapes agree to rounding, not just to the quantization step.
  const std::string in = write_scratch_file("simd.off", torus_off(60, 30));
  const std::string gab = write_scratch_file("simd.gab", "");
  const std::string a = write_scratch_file("simd-a.off", ""), b = write_scratch_file("simd-b.off", "");
  ASSERT_EQ(run_gab("compress -i " + in + " -o " + gab + " --error 0.002").exit_code, 0);
  ASSERT_EQ(run_gab("decompress -i " + gab + " -o " + a).exit_code, 0);
  ASSERT_EQ(run_gab("decompress -i " + gab + " -o " + b, "GAB_SIMD=scalar").exit_code, 0);
  CommandResult diff = run_gab("diff " + a + " " + b + " --json --samples 0");
  ASSERT_EQ(diff.exit_code, 0) << diff.err;
  EXPECT_LT(json_number(diff.out, "linf_rel"), 1e-9);
}

TEST(CodecCliTest, DetailFilesDecodeToTheSameBitsAtEverySimdLevel) {
  // The detail layer rounds the anchors' shape with a guard band and builds
  // every prediction from what both sides hold exactly: a decoder with other
  // kernels outputs the very same coordinates, and gab diff against the input
  // gives the encoder's numbers.
  const std::string in = write_scratch_file("detail.off", torus_off(60, 30));
  const std::string gab = write_scratch_file("detail.gab", "");
  const std::string a = write_scratch_file("detail-a.off", ""), b = write_scratch_file("detail-b.off", "");
  const std::string map = write_scratch_file("detail.map", "");
  CommandResult c =
      run_gab("compress -i " + in + " -o " + gab + " --error 1e-4 --detail on --order-out " + map + " --json");
  ASSERT_EQ(c.exit_code, 0) << c.err;
  EXPECT_NE(c.out.find("\"detail\": true"), std::string::npos) << c.out;
  EXPECT_GT(json_number(c.out, "detail_bytes"), 0);
  EXPECT_GT(json_number(c.out, "anchor_rms_rel"), json_number(c.out, "rms_rel"));
  CommandResult d = run_gab("decompress -i " + gab + " -o " + a + " --json");
  ASSERT_EQ(d.exit_code, 0) << d.err;
  EXPECT_NE(d.out.find("\"detail\": true"), std::string::npos) << d.out;
  ASSERT_EQ(run_gab("decompress -i " + gab + " -o " + b, "GAB_SIMD=scalar").exit_code, 0);
  EXPECT_EQ(read_all(a), read_all(b));
  CommandResult diff = run_gab("diff " + in + " " + a + " --map " + map + " --json --samples 0");
  ASSERT_EQ(diff.exit_code, 0) << diff.err;
  EXPECT_NEAR(json_number(diff.out, "rms_rel"), json_number(c.out, "rms_rel"), 1e-12);
  EXPECT_LE(json_number(diff.out, "rms_rel"), 1e-4);
  CommandResult info = run_gab("info " + gab + " --json");
  EXPECT_NE(info.out.find("\"detail\": true"), std::string::npos) << info.out;
  EXPECT_EQ(json_number(info.out, "detail_bytes"), json_number(c.out, "detail_bytes"));
  info = run_gab("info " + gab);
  EXPECT_NE(info.out.find(": detail layer, every vertex's residual at step"), std::string::npos) << info.out;
}

TEST(CodecCliTest, ThreadCountChangesNeitherTheFileNorTheShape) {
  // --threads only spreads the factorizations; the bytes and the decoded
  // coordinates are the same (the encoder and decoder compute
  // bit-identical shapes), here also with the CLI's malloc settings
  // (malloc_tuning.h) overridden.
  const std::string in = write_scratch_file("thr.off", torus_off(80, 40));
  const std::string one = write_scratch_file("thr-1.gab", ""), three = write_scratch_file("thr-3.gab", "");
  const std::string a = write_scratch_file("thr-a.off", ""), b = write_scratch_file("thr-b.off", "");
  ASSERT_EQ(run_gab("compress -i " + in + " -o " + one + " --threads 1").exit_code, 0);
  ASSERT_EQ(run_gab("compress -i " + in + " -o " + three + " --threads 3").exit_code, 0);
  EXPECT_EQ(read_all(one), read_all(three));
  ASSERT_EQ(run_gab("decompress -i " + one + " -o " + a + " --threads 3").exit_code, 0);
  ASSERT_EQ(run_gab("decompress -i " + three + " -o " + b + " --threads 1",
                    "GLIBC_TUNABLES=glibc.malloc.hugetlb=0").exit_code, 0);
  EXPECT_EQ(read_all(a), read_all(b));
  // A malloc setting of the user's own is kept (malloc_tuning.h leaves it alone).
  ASSERT_EQ(run_gab("decompress -i " + one + " -o " + b, "GLIBC_TUNABLES=glibc.malloc.mmap_threshold=131072").exit_code,
            0);
  EXPECT_EQ(read_all(a), read_all(b));
  CommandResult r = run_gab("decompress -i " + one + " -o " + a + " --threads 0");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--threads"), std::string::npos) << r.err;
}

TEST(CodecCliTest, TruncatedFileDecodesItsCompleteChunksWithAWarning) {
  const std::string in = write_scratch_file("cut.off", torus_off(40, 20));
  const std::string gab = write_scratch_file("cut.gab", "");
  ASSERT_EQ(run_gab("compress -i " + in + " -o " + gab + " --anchors 100").exit_code, 0);
  const std::string bytes = read_all(gab);
  const std::string cut = write_scratch_file("cut-short.gab", bytes.substr(0, bytes.size() - 10));
  const std::string out = write_scratch_file("cut-out.off", "");
  CommandResult d = run_gab("decompress -i " + cut + " -o " + out + " --json");
  ASSERT_EQ(d.exit_code, 0) << d.err;
  EXPECT_LT(json_number(d.out, "anchors"), 100);
  EXPECT_NE(d.err.find("gab decompress: warning: " + cut + " is truncated: decoded "), std::string::npos) << d.err;
  CommandResult i = run_gab("info " + cut + " --json");
  EXPECT_EQ(i.exit_code, 0) << i.err;
  EXPECT_NE(i.out.find("\"truncated\": true"), std::string::npos);
}

TEST(CodecCliTest, GeometryOnlyFilesNeedTheirConnectivity) {
  const std::string in = write_scratch_file("geo.off", torus_off(30, 12));
  const std::string other = write_scratch_file("geo-other.off", torus_off(12, 30));
  const std::string gab = write_scratch_file("geo.gab", "");
  const std::string out = write_scratch_file("geo-out.obj", "");
  ASSERT_EQ(run_gab("compress -i " + in + " -o " + gab + " --anchors 30 --geometry-only").exit_code, 0);
  CommandResult d = run_gab("decompress -i " + gab + " -o " + out);
  EXPECT_EQ(d.exit_code, 1);
  EXPECT_EQ(d.err, "gab: error: " + gab +
                       ": this file holds geometry only: give the mesh it was made from (--connectivity MESH)\n");
  d = run_gab("decompress -i " + gab + " -o " + out + " --connectivity " + other);
  EXPECT_EQ(d.exit_code, 1);
  EXPECT_NE(d.err.find("the connectivity mesh is not the one this file was made from"), std::string::npos) << d.err;
  d = run_gab("decompress -i " + gab + " -o " + out + " --connectivity " + in);
  EXPECT_EQ(d.exit_code, 0) << d.err;
}

TEST(CodecCliTest, UsageAndInputErrors) {
  const std::string in = write_scratch_file("err.off", torus_off(10, 6));
  const std::string gab = write_scratch_file("err.gab", "");
  CommandResult r = run_gab("compress -i " + in + " -o " + gab + " --anchors 5 --error 0.01");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("give at most one of --anchors, --error, --linf"), std::string::npos);
  EXPECT_EQ(run_gab("compress -i " + in).exit_code, 2);
  EXPECT_EQ(run_gab("compress -i " + in + " -o " + gab + " --bits 40").exit_code, 2);
  EXPECT_EQ(run_gab("decompress -i " + gab + " -o x.txt").exit_code, 2);
  EXPECT_EQ(run_gab("info").exit_code, 2);
  // Bad input: exit 1, one line, and no output file left behind.
  const std::string missing = write_scratch_file("missing-out.gab", "");
  std::remove(missing.c_str());
  r = run_gab("compress -i /nonexistent/mesh.off -o " + missing);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err.rfind("gab: error: ", 0), 0u);
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1);
  EXPECT_FALSE(std::ifstream(missing).good());
  const std::string not_gab = write_scratch_file("not.gab", "hello, world, this is not a gab file at all........");
  r = run_gab("info " + not_gab);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_EQ(r.err, "gab: error: " + not_gab + ": not a .gab file (bad magic)\n");
}

TEST(CodecCliTest, SolverIsChosenRecordedAndChecked) {
  const std::string in = write_scratch_file("solver.off", torus_off(16, 8));
  const std::string gab = write_scratch_file("solver.gab", "");
  const std::string out = write_scratch_file("solver-out.off", "");
  for (const char* solver : {"global", "iterative"}) {
    CommandResult r = run_gab("compress -i " + in + " -o " + gab + " --solver " + solver + " --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find(std::string("\"solver\": \"") + solver + "\""), std::string::npos) << r.out;
    r = run_gab("decompress -i " + gab + " -o " + out + " --json");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    EXPECT_NE(r.out.find(std::string("\"solver\": \"") + solver + "\""), std::string::npos) << r.out;
    r = run_gab("info " + gab);
    EXPECT_NE(r.out.find(solver[0] == 'g'
                             ? "w = 100, ordered by AMD; global reconstruction\n"
                             : "w = 100, iterative reconstruction (start sweeps 4 per prediction, 8 final; final "
                               "steps 2 per anchor spacing, at most 64)\n"),
              std::string::npos)
        << r.out;
    r = run_gab("info " + gab + " --json");
    EXPECT_NE(r.out.find(solver[0] == 'g' ? "\"prediction_sweeps\": 0, \"final_sweeps\": 0"
                                          : "\"prediction_sweeps\": 4, \"final_sweeps\": 8"),
              std::string::npos)
        << r.out;
  }
  CommandResult r = run_gab("compress -i " + in + " -o " + gab + " --solver cholmod");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--solver must be auto, global or iterative, got 'cholmod'"), std::string::npos) << r.err;
  r = run_gab("compress -i " + in + " -o " + gab + " --solver iterative --refine");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--refine needs the global solver (--solver global or auto)"), std::string::npos) << r.err;
}

TEST(CodecCliTest, OrderingIsChosenRecordedAndOverridable) {
  const std::string in = write_scratch_file("ordering.off", torus_off(12, 6));
  const std::string gab = write_scratch_file("ordering.gab", "");
  const std::string out = write_scratch_file("ordering-out.off", "");
  // The global solver's factorizations are what an ordering is for.
  CommandResult r = run_gab("compress -i " + in + " -o " + gab + " --anchors 12 --solver global --json");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("\"ordering\": \"amd\""), std::string::npos) << r.out;  // auto, on a small mesh
  r = run_gab("compress -i " + in + " -o " + gab + " --anchors 12 --solver global --ordering nd --json");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("\"ordering\": \"nd\""), std::string::npos) << r.out;
  r = run_gab("info " + gab);
  EXPECT_NE(r.out.find("w = 100, ordered by nested dissection; global reconstruction\n"), std::string::npos) << r.out;
  r = run_gab("info " + gab + " --json");
  EXPECT_NE(r.out.find("\"ordering\": \"nd\""), std::string::npos) << r.out;
  r = run_gab("decompress -i " + gab + " -o " + out + " --json");
  EXPECT_NE(r.out.find("\"ordering\": \"nd\""), std::string::npos) << r.out;  // the file's
  r = run_gab("decompress -i " + gab + " -o " + out + " --ordering amd --json");
  EXPECT_NE(r.out.find("\"ordering\": \"amd\""), std::string::npos) << r.out;
  // An unknown name, and one of the engine's names the codec does not take
  // (natural: gab factor's and study's), are usage errors naming the three.
  for (const char* command : {"compress", "decompress"}) {
    for (const char* name : {"metis", "natural"}) {
      r = run_gab(std::string(command) + " -i " + (command[0] == 'c' ? in : gab) + " -o " +
                  (command[0] == 'c' ? gab : out) + " --ordering " + name);
      EXPECT_EQ(r.exit_code, 2);
      EXPECT_NE(r.err.find(std::string("--ordering must be auto, amd or nd, got '") + name + "'"), std::string::npos)
          << r.err;
    }
  }
}

// compress's greedy batch is a fraction (--batch-fraction), study's --batch a
// count: two names. The fraction's old spelling still works, with a note.
TEST(CodecCliTest, BatchFractionHasItsOwnNameAndTheOldOneStillWorks) {
  const std::string in = write_scratch_file("batch.off", torus_off(30, 16));
  const std::string a = write_scratch_file("batch-a.gab", ""), b = write_scratch_file("batch-b.gab", "");
  const std::string c = write_scratch_file("batch-c.gab", "");
  ASSERT_EQ(run_gab("compress -i " + in + " -o " + a + " --anchors 200 --batch-fraction 0.5").exit_code, 0);
  const CommandResult old = run_gab("compress -i " + in + " -o " + b + " --anchors 200 --batch 0.5");
  ASSERT_EQ(old.exit_code, 0) << old.err;
  EXPECT_NE(old.err.find("--batch is now --batch-fraction"), std::string::npos) << old.err;
  EXPECT_EQ(read_all(a), read_all(b));
  ASSERT_EQ(run_gab("compress -i " + in + " -o " + c + " --anchors 200 --batch-fraction 0.05").exit_code, 0);
  EXPECT_NE(read_all(a), read_all(c));  // the option reaches the encoder
  EXPECT_EQ(run_gab("compress -i " + in + " -o " + a + " --batch-fraction 2").exit_code, 2);
  EXPECT_EQ(run_gab("compress -i " + in + " -o " + a + " --batch 0.5 --batch-fraction 0.5").exit_code, 2);
}

TEST(CodecCliTest, UnreachableTargetWarnsAndStillWrites) {
  const std::string in = write_scratch_file("far.off", torus_off(12, 6));
  const std::string gab = write_scratch_file("far.gab", "");
  CommandResult r = run_gab("compress -i " + in + " -o " + gab + " --error 1e-9 --bits 6 --detail off --json");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(json_number(r.out, "anchors"), 72);  // every vertex
  EXPECT_NE(r.err.find("gab compress: warning: the error target is out of reach: every vertex is an anchor"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.out.find("\"target_met\": false"), std::string::npos);
  // With the detail layer the limit is its finest step (2^-24 of the box).
  r = run_gab("compress -i " + in + " -o " + gab + " --error 1e-9 --json");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("gab compress: warning: the error target is out of reach: the detail layer's finest step"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.out.find("\"detail\": true"), std::string::npos);
  EXPECT_NE(r.out.find("\"target_met\": false"), std::string::npos);
  r = run_gab("compress -i " + in + " -o " + gab + " --error 1e-3 --detail sometimes");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--detail must be auto, on or off, got 'sometimes'"), std::string::npos) << r.err;
  r = run_gab("compress -i " + in + " -o " + gab + " --anchors 10 --detail on");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--detail on needs an error target (--error or --linf), not --anchors"), std::string::npos)
      << r.err;
}

TEST(CodecCliTest, DemoRunsOnAGivenMeshAndWritesItsFiles) {
  const std::string dir = gab_test::scratch_path("demo");
  const std::string mesh = write_scratch_file("demo.off", torus_off(40, 20));
  CommandResult r = run_gab("demo", "mkdir -p " + dir + " && cd " + dir + " && GAB_DEMO_MESH=" + mesh);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("anchors"), std::string::npos);
  EXPECT_NE(r.out.find("800 vertices, 1600 triangles"), std::string::npos) << r.out;
  EXPECT_TRUE(std::ifstream(dir + "/gab-demo/original.off").good());
  EXPECT_TRUE(std::ifstream(dir + "/gab-demo/anchors-40.gab").good());
  EXPECT_TRUE(std::ifstream(dir + "/gab-demo/anchors-40.off").good());
}

}  // namespace
