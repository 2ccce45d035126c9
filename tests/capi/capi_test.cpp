// The C API (gab.h): the C99 scenarios' results (capi_scenarios.c) checked
// against the C++ API's, and every door's error codes and messages.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "capi/capi_scenarios.h"
#include "capi/capi_test_util.h"
#include "common/gab_files.h"
#include "common/scratch_files.h"
#include "common/test_meshes.h"
#include "gab/gab.h"
#include "gab/mesh/metrics.h"
#include "gab/sparse/cholesky.h"

namespace {

using gab::Mesh;
using gab::testing_util::bumpy_torus;

// A call's code and message, for the error-path tests.
struct Outcome {
  int code;
  std::string message;
};

Outcome compress_outcome(const double* positions, int32_t n, const int32_t* triangles, int32_t t, double target) {
  char message[256];
  unsigned char* file = nullptr;
  size_t size = 0;
  const int code = gab_compress(positions, n, triangles, t, target, &file, &size, message, sizeof message);
  gab_free(file);
  return {code, message};
}

Outcome decompress_outcome(const unsigned char* data, size_t size, int32_t max_anchors = -1) {
  char message[256];
  double* positions = nullptr;
  int32_t* triangles = nullptr;
  int32_t n = -1, t = -1;
  const int code = gab_decompress(data, size, max_anchors, &positions, &n, &triangles, &t, message, sizeof message);
  const bool cleared = positions == nullptr && triangles == nullptr && n == 0 && t == 0;
  gab_free(positions);
  gab_free(triangles);
  if (code != GAB_OK && code != GAB_W_TRUNCATED && !cleared) return {GAB_E_INTERNAL, "outputs not cleared on failure"};
  return {code, message};
}

Outcome create_outcome(int32_t n, const std::vector<int32_t>& colptr, const std::vector<int32_t>& rowind) {
  char message[256];
  gab_cholesky* c = reinterpret_cast<gab_cholesky*>(&message);  // must come back NULL
  const int code = gab_cholesky_create(n, colptr.data(), rowind.data(), nullptr, &c, message, sizeof message);
  if (code != GAB_OK && c != nullptr) return {GAB_E_INTERNAL, "handle not cleared on failure"};
  gab_cholesky_destroy(c);
  return {code, message};
}

TEST(CapiTest, VersionAndErrorNamesAgreeWithTheHeader) {
  EXPECT_EQ(capi_version_and_names(), 1);
  EXPECT_STREQ(gab_version(), GAB_VERSION_STRING);
}

// The C door reads the names the CLI reads ("natural" is gab factor's: the
// codec refuses it, gab_cholesky_create_ex takes it).
TEST(CapiTest, OrderingNamesAreTheCliVocabulary) {
  EXPECT_EQ(gab_ordering_from_name("auto"), GAB_ORDERING_AUTO);
  EXPECT_EQ(gab_ordering_from_name("amd"), GAB_ORDERING_AMD);
  EXPECT_EQ(gab_ordering_from_name("nd"), GAB_ORDERING_ND);
  EXPECT_EQ(gab_ordering_from_name("natural"), GAB_ORDERING_NATURAL);
  EXPECT_EQ(gab_ordering_from_name("given"), -1);  // the engine's, for a caller's own permutation: no name
  EXPECT_EQ(gab_ordering_from_name("AMD"), -1);
  EXPECT_EQ(gab_ordering_from_name(""), -1);
  EXPECT_EQ(gab_ordering_from_name(nullptr), -1);
  EXPECT_EQ(gab_solver_from_name("auto"), GAB_SOLVER_AUTO);
  EXPECT_EQ(gab_solver_from_name("global"), GAB_SOLVER_GLOBAL);
  EXPECT_EQ(gab_solver_from_name("iterative"), GAB_SOLVER_ITERATIVE);
  EXPECT_EQ(gab_solver_from_name("Global"), -1);
  EXPECT_EQ(gab_solver_from_name(nullptr), -1);
}

TEST(CapiTest, RoundTripMeetsTheTargetAndMatchesTheCppApi) {
  const Mesh mesh = bumpy_torus(40, 30);
  capi_round_trip r;
  capi_round_trip_run(mesh.positions.data(), mesh.num_vertices(), mesh.triangles.data(), mesh.num_triangles(), 1e-3,
                      20, &r);
  ASSERT_EQ(r.compress_code, GAB_OK) << r.message;
  ASSERT_EQ(r.decode_code, GAB_OK) << r.message;
  ASSERT_EQ(r.coarse_code, GAB_OK) << r.message;
  EXPECT_EQ(r.decoded.n, mesh.num_vertices());
  EXPECT_EQ(r.decoded.t, mesh.num_triangles());
  EXPECT_GT(r.rms_rel, 0.0);
  EXPECT_LE(r.rms_rel, 1e-3);
  EXPECT_EQ(gab_test::oriented_set(r.decoded.triangles, r.decoded.t),
            gab_test::oriented_set(mesh.triangles.data(), mesh.num_triangles()));
  // The first 20 anchors are a coarser level of the same mesh.
  EXPECT_EQ(r.coarse.n, mesh.num_vertices());
  EXPECT_GT(r.coarse_rms_rel, 2 * r.rms_rel);
  // The same bytes and the same decoded shape as the C++ API's, with the
  // numbering kept (gab_compress's contract; the C++ default drops it).
  gab::EncodeOptions options;
  options.target_rms_rel = 1e-3;
  options.reorder = false;
  gab::EncodeStats stats;
  const std::vector<uint8_t> file = gab::testing_util::encode_or_die(mesh, options, &stats);
  ASSERT_EQ(file.size(), r.size);
  EXPECT_EQ(std::memcmp(file.data(), r.file, r.size), 0);
  gab::DecodeStats decoded_stats;
  const Mesh decoded = gab::testing_util::decode_or_die(file, gab::DecodeOptions(), &decoded_stats);
  ASSERT_EQ(decoded.positions.size(), 3 * static_cast<size_t>(r.decoded.n));
  EXPECT_EQ(std::memcmp(decoded.positions.data(), r.decoded.positions, decoded.positions.size() * sizeof(double)), 0);
  capi_round_trip_free(&r);
}

TEST(CapiTest, AnchorPrefixesAreCoarserLevels) {
  const Mesh mesh = bumpy_torus(30, 20);
  unsigned char* file = nullptr;
  size_t size = 0;
  char message[256];
  ASSERT_EQ(capi_compress_anchors(mesh.positions.data(), mesh.num_vertices(), mesh.triangles.data(),
                                  mesh.num_triangles(), 150, 12, 1, &file, &size, message, sizeof message),
            GAB_OK)
      << message;
  gab::DecodeStats stats;
  gab::Mesh whole;
  ASSERT_TRUE(gab::decode_mesh(file, size, gab::DecodeOptions(), &whole, &stats).ok());
  EXPECT_EQ(stats.anchors, 150);
  double previous = HUGE_VAL;
  for (int32_t anchors : {10, 40, 150}) {
    double* positions = nullptr;
    int32_t* triangles = nullptr;
    int32_t n = 0, t = 0;
    ASSERT_EQ(gab_decompress(file, size, anchors, &positions, &n, &triangles, &t, message, sizeof message), GAB_OK)
        << message;
    Mesh level;
    level.positions.assign(positions, positions + 3 * static_cast<size_t>(n));
    level.triangles.assign(triangles, triangles + 3 * static_cast<size_t>(t));
    const double rms = gab::testing_util::relative_rms(mesh, level);
    EXPECT_LT(rms, previous) << anchors << " anchors";
    previous = rms;
    gab_free(positions);
    gab_free(triangles);
  }
  gab_free(file);
}

TEST(CapiTest, AFileCutShortIsAWarningWithTheMeshOfItsCompleteChunks) {
  const Mesh mesh = bumpy_torus(60, 40);
  gab::EncodeOptions options;
  options.target_rms_rel = 1e-3;
  options.reorder = true;
  gab::EncodeStats encoded;
  const std::vector<uint8_t> file = gab::testing_util::encode_or_die(mesh, options, &encoded);
  EXPECT_STREQ(gab_error_name(GAB_W_TRUNCATED), "GAB_W_TRUNCATED");
  int warned = 0;
  for (double share : {0.10, 0.50, 0.85, 0.99, 1.0}) {
    const size_t size = static_cast<size_t>(share * static_cast<double>(file.size()));
    // The C++ decoder says what the cut leaves.
    gab::Mesh expected;
    gab::DecodeStats stats;
    const gab::Status status = gab::decode_mesh(file.data(), size, gab::DecodeOptions(), &expected, &stats);
    char message[256];
    double* positions = nullptr;
    int32_t* triangles = nullptr;
    int32_t n = 0, t = 0;
    const int code = gab_decompress(file.data(), size, -1, &positions, &n, &triangles, &t, message, sizeof message);
    if (!status.ok()) {
      EXPECT_EQ(code, GAB_E_PARSE) << share << ": " << message;
    } else if (!stats.truncated) {
      EXPECT_EQ(code, GAB_OK) << share << ": " << message;
      EXPECT_STREQ(message, "");
    } else {
      ++warned;
      EXPECT_EQ(code, GAB_W_TRUNCATED) << share;
      EXPECT_EQ(std::string(message), "gab_decompress: the file is truncated: decoded " +
                                          std::to_string(stats.chunks) + " of " + std::to_string(stats.chunks_in_file) +
                                          " chunks (" + std::to_string(stats.anchors) + " of " +
                                          std::to_string(stats.anchors_in_file) + " anchors)");
      ASSERT_EQ(n, mesh.num_vertices());
      EXPECT_EQ(std::vector<double>(positions, positions + 3 * static_cast<size_t>(n)), expected.positions);
      EXPECT_LT(stats.anchors, encoded.anchors);
    }
    gab_free(positions);
    gab_free(triangles);
  }
  EXPECT_GE(warned, 2);  // 85% and 99% at least cut the geometry's chunks
  // A prefix of anchors that the cut leaves whole is no warning.
  const size_t size = file.size() - 1;
  gab::Mesh coarse;
  gab::DecodeStats stats;
  ASSERT_TRUE(gab::decode_mesh(file.data(), size, gab::DecodeOptions(), &coarse, &stats).ok());
  ASSERT_TRUE(stats.truncated);
  EXPECT_EQ(decompress_outcome(file.data(), size, stats.anchors).code, GAB_OK);
}

TEST(CapiTest, OptionsStructIsReadUpToItsSize) {
  const Mesh mesh = bumpy_torus(20, 12);
  const int32_t n = mesh.num_vertices(), t = mesh.num_triangles();
  auto compress = [&](const gab_compress_options* o, std::vector<uint8_t>* bytes) {
    char message[256];
    unsigned char* file = nullptr;
    size_t size = 0;
    const int code = gab_compress_ex(mesh.positions.data(), n, mesh.triangles.data(), t, o, &file, &size, message,
                                     sizeof message);
    if (bytes) bytes->assign(file, file + size);
    gab_free(file);
    return Outcome{code, message};
  };
  // NULL options are the defaults: the CLI's --error 0.001.
  std::vector<uint8_t> defaults, same;
  ASSERT_EQ(compress(nullptr, &defaults).code, GAB_OK);
  gab_compress_options o;
  gab_compress_options_init(&o, sizeof o);
  EXPECT_EQ(o.size, sizeof o);
  EXPECT_EQ(o.weight, 100.0);
  EXPECT_EQ(o.threads, 1);
  EXPECT_EQ(o.reorder, 1);
  ASSERT_EQ(compress(&o, &same).code, GAB_OK);
  EXPECT_EQ(defaults, same);
  // An older caller's struct (up to target_linf_rel): the weight it does not
  // know takes its default even if the bytes after its size say otherwise.
  struct {
    gab_compress_options o;
    unsigned char guard[8];
  } older;
  std::memset(&older, 0xAB, sizeof older);
  gab_compress_options_init(&older.o, offsetof(gab_compress_options, weight));
  EXPECT_EQ(older.o.size, offsetof(gab_compress_options, weight));
  EXPECT_EQ(reinterpret_cast<unsigned char*>(&older.o)[offsetof(gab_compress_options, weight)], 0xAB);  // not written
  older.o.target_rms_rel = 1e-3;
  ASSERT_EQ(compress(&older.o, &same).code, GAB_OK);
  EXPECT_EQ(defaults, same);
  // A newer caller's larger struct: zero tail accepted, a set byte refused.
  struct {
    gab_compress_options o;
    int64_t future[2];
  } newer;
  std::memset(&newer, 0, sizeof newer);
  gab_compress_options_init(&newer.o, sizeof newer.o);
  newer.o.size = sizeof newer;
  ASSERT_EQ(compress(&newer.o, &same).code, GAB_OK);
  EXPECT_EQ(defaults, same);
  newer.future[1] = 1;
  const Outcome refused = compress(&newer.o, nullptr);
  EXPECT_EQ(refused.code, GAB_E_UNSUPPORTED);
  EXPECT_EQ(refused.message, "gab_compress_ex: options->size is " + std::to_string(sizeof newer) + " and byte " +
                                 std::to_string(sizeof newer - 8) + " is set: gab " GAB_VERSION_STRING " knows " +
                                 std::to_string(sizeof o) + " bytes of options");
  // Values the door checks, and one the encoder checks.
  gab_compress_options_init(&o, sizeof o);
  o.threads = -1;
  EXPECT_EQ(compress(&o, nullptr).message, "gab_compress_ex: options->threads is -1: must be in 0..64 (0: every core)");
  gab_compress_options_init(&o, sizeof o);
  o.detail = 7;
  EXPECT_EQ(compress(&o, nullptr).message,
            "gab_compress_ex: options->detail is 7: must be GAB_DETAIL_AUTO, GAB_DETAIL_ON or GAB_DETAIL_OFF");
  gab_compress_options_init(&o, sizeof o);
  o.ordering = 4;
  EXPECT_EQ(compress(&o, nullptr).message,
            "gab_compress_ex: options->ordering is 4: must be GAB_ORDERING_AUTO, GAB_ORDERING_AMD or GAB_ORDERING_ND");
  o.ordering = GAB_ORDERING_NATURAL;  // a name of the engine's the codec does not factor with
  const Outcome natural = compress(&o, nullptr);
  EXPECT_EQ(natural.code, GAB_E_INVALID_ARGUMENT);
  EXPECT_EQ(natural.message,
            "gab_compress_ex: options->ordering is GAB_ORDERING_NATURAL: the codec's factorizations take "
            "GAB_ORDERING_AUTO, GAB_ORDERING_AMD or GAB_ORDERING_ND (natural is for gab_cholesky_create_ex)");
  gab_compress_options_init(&o, sizeof o);
  o.solver = 3;
  EXPECT_EQ(compress(&o, nullptr).message,
            "gab_compress_ex: options->solver is 3: must be GAB_SOLVER_AUTO, GAB_SOLVER_GLOBAL or GAB_SOLVER_ITERATIVE");
  // The solver is recorded in the file (header byte 12): the default is the
  // iterative one, the refinement picks the global one.
  for (int32_t solver : {GAB_SOLVER_AUTO, GAB_SOLVER_GLOBAL, GAB_SOLVER_ITERATIVE}) {
    for (int32_t refine : {0, 1}) {
      if (solver == GAB_SOLVER_ITERATIVE && refine) continue;
      gab_compress_options_init(&o, sizeof o);
      o.solver = solver;
      o.refine = refine;
      std::vector<uint8_t> file;
      ASSERT_EQ(compress(&o, &file).code, GAB_OK);
      ASSERT_GT(file.size(), 12u);
      EXPECT_EQ(file[12], solver == GAB_SOLVER_GLOBAL || refine ? gab::kGabReconstructionGlobal
                                                                 : gab::kGabReconstructionIterativeTuned);
    }
  }
  gab_compress_options_init(&o, sizeof o);
  o.solver = GAB_SOLVER_ITERATIVE;
  o.refine = 1;
  EXPECT_EQ(compress(&o, nullptr).message,
            "gab_compress_ex: the refinement chunk needs the global reconstruction operator");
  gab_compress_options_init(&o, sizeof o);
  o.bits = 30;
  const Outcome bits = compress(&o, nullptr);
  EXPECT_EQ(bits.code, GAB_E_INVALID_ARGUMENT);
  EXPECT_EQ(bits.message, "gab_compress_ex: bits must be in 2..24");
  gab_compress_options_init(&o, 4);  // not even the size field: nothing written
  o.size = 4;
  EXPECT_EQ(compress(&o, nullptr).message, "gab_compress_ex: options->size is 4: set it with gab_compress_options_init");
}

// The numbering's default (issue 34): gab_compress_ex and its options' init
// number the decoded mesh in the coder's order, the smallest file, as the
// C++ default and the CLI do; reorder = 0 and gab_compress (whose meaning is
// an ABI contract) keep the input's numbering vertex by vertex.
TEST(CapiTest, TheDefaultIsTheTraversalOrderAndGabCompressKeepsTheNumbering) {
  const Mesh mesh = bumpy_torus(30, 20);
  const int32_t n = mesh.num_vertices(), t = mesh.num_triangles();
  char message[256];
  auto compress_ex = [&](const gab_compress_options* o, gab_compress_report* r) {
    unsigned char* file = nullptr;
    size_t size = 0;
    const int code = gab_compress_with_report(mesh.positions.data(), n, mesh.triangles.data(), t, o, &file, &size, r,
                                              message, sizeof message);
    EXPECT_EQ(code, GAB_OK) << message;
    std::vector<uint8_t> bytes(file, file + size);
    gab_free(file);
    return bytes;
  };
  gab_compress_options o;
  gab_compress_options_init(&o, sizeof o);
  EXPECT_EQ(o.reorder, 1);
  gab_compress_report r;
  gab_compress_report_init(&r, sizeof r);
  const std::vector<uint8_t> by_default = compress_ex(nullptr, &r);
  ASSERT_GT(by_default.size(), 9u);
  EXPECT_EQ(by_default[9] & gab::kGabFlagReordered, gab::kGabFlagReordered);
  EXPECT_EQ(r.reordered, 1);
  EXPECT_EQ(r.order_bytes, 0u);
  ASSERT_NE(r.order, nullptr);
  std::vector<int32_t> order(r.order, r.order + n);
  gab_free(r.order);
  std::vector<int32_t> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  for (int32_t v = 0; v < n; ++v) ASSERT_EQ(sorted[v], v);  // a permutation
  gab_compress_report_init(&r, sizeof r);
  EXPECT_EQ(compress_ex(&o, &r), by_default);  // the init's options are the defaults
  gab_free(r.order);
  gab::EncodeOptions cpp;
  cpp.target_rms_rel = 1e-3;
  gab::EncodeStats cpp_stats;
  EXPECT_EQ(gab::testing_util::encode_or_die(mesh, cpp, &cpp_stats), by_default);  // the C++ default
  EXPECT_EQ(cpp_stats.new_index, order);

  // reorder = 0 and gab_compress: the same file, the numbering kept, priced.
  o.reorder = 0;
  gab_compress_report_init(&r, sizeof r);
  const std::vector<uint8_t> kept = compress_ex(&o, &r);
  EXPECT_EQ(kept[9] & gab::kGabFlagReordered, 0);
  EXPECT_EQ(r.reordered, 0);
  EXPECT_EQ(r.order, nullptr);
  EXPECT_GT(r.order_bytes, 0u);
  EXPECT_LT(by_default.size(), kept.size());
  unsigned char* plain = nullptr;
  size_t plain_size = 0;
  ASSERT_EQ(gab_compress(mesh.positions.data(), n, mesh.triangles.data(), t, 1e-3, &plain, &plain_size, message,
                         sizeof message),
            GAB_OK)
      << message;
  EXPECT_EQ(std::vector<uint8_t>(plain, plain + plain_size), kept);
  // Decoded vertex by vertex: vertex i of the output is input vertex i.
  double* positions = nullptr;
  int32_t* triangles = nullptr;
  int32_t dn = 0, dt = 0;
  ASSERT_EQ(gab_decompress(plain, plain_size, -1, &positions, &dn, &triangles, &dt, message, sizeof message), GAB_OK);
  ASSERT_EQ(dn, n);
  Mesh decoded;
  decoded.positions.assign(positions, positions + 3 * static_cast<size_t>(n));
  EXPECT_EQ(gab_test::oriented_set(triangles, dt), gab_test::oriented_set(mesh.triangles.data(), t));
  EXPECT_NEAR(gab::testing_util::relative_rms(mesh, decoded), r.rms_rel, 1e-12);
  EXPECT_LE(r.rms_rel, 1e-3);
  gab_free(positions);
  gab_free(triangles);
  gab_free(plain);
}

// gab_compress_with_report: the CLI's compress figures (EncodeStats, as
// `gab compress --json` prints them) and, with reorder, the map onto the
// decoded mesh's numbering.
TEST(CapiTest, CompressReportCarriesTheCliFiguresAndTheMap) {
  const Mesh mesh = bumpy_torus(40, 30);
  const int32_t n = mesh.num_vertices(), t = mesh.num_triangles();
  char message[256];
  auto compress = [&](const gab_compress_options* o, gab_compress_report* r, std::vector<uint8_t>* bytes) {
    unsigned char* file = nullptr;
    size_t size = 0;
    const int code = gab_compress_with_report(mesh.positions.data(), n, mesh.triangles.data(), t, o, &file, &size, r,
                                              message, sizeof message);
    if (bytes) bytes->assign(file, file + size);
    gab_free(file);
    return Outcome{code, message};
  };
  gab_compress_options o;
  gab_compress_options_init(&o, sizeof o);
  o.reorder = 1;
  gab_compress_report r;
  gab_compress_report_init(&r, sizeof r);
  EXPECT_EQ(r.size, sizeof r);
  EXPECT_EQ(r.order, nullptr);
  std::vector<uint8_t> file;
  ASSERT_EQ(compress(&o, &r, &file).code, GAB_OK) << message;
  // The C++ API's file and figures for the same options.
  gab::EncodeOptions options;
  options.target_rms_rel = 1e-3;
  options.reorder = true;
  gab::EncodeStats stats;
  EXPECT_EQ(gab::testing_util::encode_or_die(mesh, options, &stats), file);
  EXPECT_EQ(r.size, sizeof r);
  EXPECT_EQ(r.n, n);
  EXPECT_EQ(r.faces, t);
  EXPECT_EQ(r.anchors, stats.anchors);
  EXPECT_EQ(r.chunks, stats.chunks);
  EXPECT_EQ(r.bits, stats.bits);
  EXPECT_EQ(r.solver, GAB_SOLVER_ITERATIVE);
  EXPECT_EQ(r.ordering, GAB_ORDERING_AMD);
  EXPECT_EQ(r.target_met, 1);
  EXPECT_EQ(r.reordered, 1);
  EXPECT_EQ(r.levels, stats.levels ? 1 : 0);
  EXPECT_EQ(r.bytes, file.size());
  EXPECT_EQ(r.geometry_bytes, stats.geometry_bytes);
  EXPECT_EQ(r.connectivity_bytes, stats.connectivity_bytes);
  EXPECT_EQ(r.order_bytes, 0u);
  EXPECT_EQ(r.bytes, r.geometry_bytes + r.connectivity_bytes + r.order_bytes);
  EXPECT_EQ(r.rms_rel, stats.rms_rel);
  EXPECT_EQ(r.linf_rel, stats.linf_rel);
  EXPECT_EQ(r.anchor_rms_rel, stats.rms_rel);  // no detail layer at 1e-3 here
  EXPECT_EQ(r.detail, 0);
  EXPECT_EQ(r.detail_bytes, 0u);
  EXPECT_EQ(r.bpv_geometry, 8.0 * static_cast<double>(r.geometry_bytes) / n);
  EXPECT_EQ(r.weight, 100.0);
  EXPECT_GT(r.encode_s, 0.0);
  EXPECT_GT(r.rms_rel, 0.0);
  EXPECT_LE(r.rms_rel, 1e-3);
  // The map is --order-out's: order[i] is input vertex i's decoded index.
  ASSERT_NE(r.order, nullptr);
  ASSERT_EQ(std::vector<int32_t>(r.order, r.order + n), stats.new_index);
  gab::DecodeStats decoded_stats;
  const Mesh decoded = gab::testing_util::decode_or_die(file, gab::DecodeOptions(), &decoded_stats);
  Mesh mapped = decoded;
  for (int32_t v = 0; v < n; ++v) {
    for (int c = 0; c < 3; ++c) mapped.positions[3 * v + c] = decoded.positions[3 * r.order[v] + c];
  }
  EXPECT_NEAR(gab::testing_util::relative_rms(mesh, mapped), r.rms_rel, 1e-12);
  EXPECT_GT(gab::testing_util::relative_rms(mesh, decoded), 100 * r.rms_rel);  // unmapped: another numbering
  gab_free(r.order);
  // From C alone (capi_scenarios.c): the same map read by a C99 program.
  double mapped_rms = -1, reported_rms = -2;
  ASSERT_EQ(capi_compress_reordered(mesh.positions.data(), n, mesh.triangles.data(), t, 1e-3, &mapped_rms,
                                    &reported_rms, message, sizeof message),
            GAB_OK)
      << message;
  EXPECT_NEAR(mapped_rms, reported_rms, 1e-12);

  // reorder = 0: the numbering is kept, no map, the order block priced.
  gab_compress_options_init(&o, sizeof o);
  o.reorder = 0;
  gab_compress_report_init(&r, sizeof r);
  std::vector<uint8_t> kept, plain;
  ASSERT_EQ(compress(&o, &r, &kept).code, GAB_OK) << message;
  ASSERT_EQ(compress(&o, nullptr, &plain).code, GAB_OK) << message;  // no report: the same file
  EXPECT_EQ(kept, plain);
  EXPECT_EQ(r.reordered, 0);
  EXPECT_EQ(r.order, nullptr);
  EXPECT_GT(r.order_bytes, 0u);
  EXPECT_EQ(r.bytes, r.geometry_bytes + r.connectivity_bytes + r.order_bytes);
  // A detail layer and the global solver, as the JSON names them.
  gab_compress_options_init(&o, sizeof o);
  o.target_rms_rel = 1e-4;
  o.detail = GAB_DETAIL_ON;
  o.solver = GAB_SOLVER_GLOBAL;
  o.ordering = GAB_ORDERING_ND;
  o.weight = 50;
  ASSERT_EQ(compress(&o, &r, nullptr).code, GAB_OK) << message;
  EXPECT_EQ(r.detail, 1);
  EXPECT_GT(r.detail_bytes, 0u);
  EXPECT_LT(r.detail_bytes, r.geometry_bytes);
  EXPECT_GT(r.detail_step_rel, 0.0);
  EXPECT_GT(r.anchor_rms_rel, r.rms_rel);
  EXPECT_LE(r.rms_rel, 1e-4);
  EXPECT_EQ(r.solver, GAB_SOLVER_GLOBAL);
  EXPECT_EQ(r.ordering, GAB_ORDERING_ND);
  EXPECT_EQ(r.weight, 50.0);
  gab_free(r.order);  // reorder, the init's default: the report holds the map

  // An older caller's smaller report: only its bytes are written.
  struct {
    gab_compress_report r;
    unsigned char guard[8];
  } older;
  std::memset(&older, 0xAB, sizeof older);
  const size_t older_size = offsetof(gab_compress_report, bytes);
  gab_compress_report_init(&older.r, older_size);
  EXPECT_EQ(older.r.size, older_size);
  gab_compress_options_init(&o, sizeof o);
  o.reorder = 1;
  ASSERT_EQ(compress(&o, &older.r, nullptr).code, GAB_OK) << message;
  EXPECT_EQ(older.r.size, older_size);
  EXPECT_EQ(older.r.anchors, stats.anchors);
  EXPECT_EQ(reinterpret_cast<unsigned char*>(&older.r)[older_size], 0xAB);  // not written, and no map made
  EXPECT_EQ(older.guard[0], 0xAB);
  // A newer caller's larger report: this library's part written, `size` says how much.
  struct {
    gab_compress_report r;
    int64_t future[2];
  } newer;
  std::memset(&newer, 0, sizeof newer);
  gab_compress_report_init(&newer.r, sizeof newer);
  EXPECT_EQ(newer.r.size, sizeof newer.r);
  newer.r.size = sizeof newer;
  newer.future[1] = 7;
  ASSERT_EQ(compress(&o, &newer.r, nullptr).code, GAB_OK) << message;
  EXPECT_EQ(newer.r.size, sizeof newer.r);
  EXPECT_EQ(newer.future[1], 7);
  ASSERT_NE(newer.r.order, nullptr);
  gab_free(newer.r.order);

  // A failure leaves the report zero, its map NULL.
  gab_compress_report_init(&r, sizeof r);
  r.anchors = 99;
  r.order = reinterpret_cast<int32_t*>(&r);
  gab_compress_options_init(&o, sizeof o);
  o.bits = 30;
  const Outcome bits = compress(&o, &r, nullptr);
  EXPECT_EQ(bits.code, GAB_E_INVALID_ARGUMENT);
  EXPECT_EQ(bits.message, "gab_compress_with_report: bits must be in 2..24");
  EXPECT_EQ(r.anchors, 0);
  EXPECT_EQ(r.order, nullptr);
  EXPECT_EQ(r.size, sizeof r);
  r.size = 4;
  const Outcome unset = compress(nullptr, &r, nullptr);
  EXPECT_EQ(unset.code, GAB_E_INVALID_ARGUMENT);
  EXPECT_EQ(unset.message, "gab_compress_with_report: report->size is 4: set it with gab_compress_report_init");
}

TEST(CapiTest, DecompressOptionsBoundTheMemoryAndPickTheLevel) {
  const Mesh mesh = bumpy_torus(40, 20);
  char message[512];
  unsigned char* file = nullptr;
  size_t size = 0;
  ASSERT_EQ(gab_compress(mesh.positions.data(), mesh.num_vertices(), mesh.triangles.data(), mesh.num_triangles(),
                         1e-3, &file, &size, message, sizeof message),
            GAB_OK)
      << message;
  auto decode = [&](const gab_decompress_options* o, int32_t* n_out) {
    double* positions = nullptr;
    int32_t n = 0, t = 0;
    int32_t* triangles = nullptr;
    const int code = gab_decompress_ex(file, size, o, &positions, &n, &triangles, &t, message, sizeof message);
    gab_free(positions);
    gab_free(triangles);
    if (n_out != nullptr) *n_out = n;
    return Outcome{code, message};
  };
  int32_t n = 0;
  ASSERT_EQ(decode(nullptr, &n).code, GAB_OK) << message;
  EXPECT_EQ(n, mesh.num_vertices());
  gab_decompress_options o;
  gab_decompress_options_init(&o, sizeof o);
  EXPECT_EQ(o.size, sizeof o);
  EXPECT_EQ(o.max_memory, 0);
  EXPECT_EQ(o.max_anchors, -1);
  EXPECT_EQ(o.threads, 1);
  o.max_memory = 100000;  // under what even the mesh's arrays take
  const Outcome refused = decode(&o, nullptr);
  EXPECT_EQ(refused.code, GAB_E_RESOURCE_EXHAUSTED);
  EXPECT_EQ(refused.message.rfind("gab_decompress_ex: decoding needs about ", 0), 0u) << refused.message;
  EXPECT_NE(refused.message.find("over its memory limit of 1 MiB"), std::string::npos) << refused.message;
  o.max_memory = -1;  // no limit
  EXPECT_EQ(decode(&o, nullptr).code, GAB_OK);
  o.threads = 65;
  EXPECT_EQ(decode(&o, nullptr).message,
            "gab_decompress_ex: options->threads is 65: must be in 0..64 (0: every core)");
  gab_free(file);
}

// gab_decompress_options.ordering is the CLI's decompress --ordering: a
// global-solver file's factorizations take it (the shape the C++ decoder
// gives with that ordering, bit for bit); AUTO is the file's own. Another
// ordering rounds differently: the same anchors, the shape the same to
// 1e-11 of the diagonal (matrix_ordering.h).
TEST(CapiTest, DecompressOrderingReachesTheFactorizations) {
  const Mesh mesh = bumpy_torus(60, 30);
  gab::EncodeOptions options;
  options.solver = gab::Solver::kGlobal;
  options.ordering = gab::Ordering::kAmd;
  options.target_rms_rel = 2e-3;
  gab::EncodeStats encoded;
  const std::vector<uint8_t> file = gab::testing_util::encode_or_die(mesh, options, &encoded);
  const double diagonal = gab::bounding_box_diagonal(mesh);
  char message[256];
  auto decode = [&](int32_t ordering) {
    capi_mesh out{};
    const int code = capi_decompress_ordered(file.data(), file.size(), ordering, &out, message, sizeof message);
    EXPECT_EQ(code, GAB_OK) << ordering << ": " << message;
    std::vector<double> positions(out.positions, out.positions + 3 * static_cast<size_t>(out.n));
    capi_free_mesh(&out);
    return positions;
  };
  auto cpp_decode = [&](gab::Ordering ordering) {
    gab::DecodeOptions decode_options;
    decode_options.ordering = ordering;
    gab::DecodeStats stats;
    const Mesh decoded = gab::testing_util::decode_or_die(file, decode_options, &stats);
    EXPECT_EQ(stats.ordering, ordering == gab::Ordering::kAuto ? gab::Ordering::kAmd : ordering);
    return decoded.positions;
  };
  const std::vector<double> own = decode(GAB_ORDERING_AUTO), amd = decode(GAB_ORDERING_AMD),
                            nd = decode(GAB_ORDERING_ND);
  EXPECT_EQ(own, cpp_decode(gab::Ordering::kAuto));
  EXPECT_EQ(amd, own);  // the file's
  EXPECT_EQ(nd, cpp_decode(gab::Ordering::kNestedDissection));
  ASSERT_EQ(nd.size(), own.size());
  EXPECT_NE(nd, own) << "nested dissection should round differently: is the ordering passed on?";
  double largest = 0;
  for (size_t i = 0; i < own.size(); ++i) largest = std::max(largest, std::fabs(nd[i] - own[i]));
  EXPECT_LT(largest, 1e-11 * diagonal);

  // Checked as the other fields: the codec's orderings only, and the ABI rule.
  gab_decompress_options o;
  gab_decompress_options_init(&o, sizeof o);
  EXPECT_EQ(o.ordering, GAB_ORDERING_AUTO);
  auto outcome = [&](const gab_decompress_options* d) {
    double* positions = nullptr;
    int32_t* triangles = nullptr;
    int32_t n = 0, t = 0;
    const int code = gab_decompress_ex(file.data(), file.size(), d, &positions, &n, &triangles, &t, message,
                                       sizeof message);
    const std::vector<double> decoded(positions, positions + 3 * static_cast<size_t>(n));
    gab_free(positions);
    gab_free(triangles);
    return std::make_pair(Outcome{code, message}, decoded);
  };
  o.ordering = GAB_ORDERING_NATURAL;
  const Outcome natural = outcome(&o).first;
  EXPECT_EQ(natural.code, GAB_E_INVALID_ARGUMENT);
  EXPECT_EQ(natural.message,
            "gab_decompress_ex: options->ordering is GAB_ORDERING_NATURAL: the codec's factorizations take "
            "GAB_ORDERING_AUTO, GAB_ORDERING_AMD or GAB_ORDERING_ND (natural is for gab_cholesky_create_ex)");
  o.ordering = -1;
  EXPECT_EQ(outcome(&o).first.message,
            "gab_decompress_ex: options->ordering is -1: must be GAB_ORDERING_AUTO, GAB_ORDERING_AMD or "
            "GAB_ORDERING_ND");
  // An older caller's struct (up to threads): the ordering it does not know
  // is the file's, whatever the bytes after its size hold.
  struct {
    gab_decompress_options o;
    unsigned char guard[8];
  } older;
  std::memset(&older, 0xAB, sizeof older);
  gab_decompress_options_init(&older.o, offsetof(gab_decompress_options, ordering));
  EXPECT_EQ(older.o.size, offsetof(gab_decompress_options, ordering));
  const auto old_caller = outcome(&older.o);
  EXPECT_EQ(old_caller.first.code, GAB_OK) << old_caller.first.message;
  EXPECT_EQ(old_caller.second, own);
  // A newer caller's larger struct: a zero tail accepted, a set byte refused.
  struct {
    gab_decompress_options o;
    int64_t future[2];
  } newer;
  std::memset(&newer, 0, sizeof newer);
  gab_decompress_options_init(&newer.o, sizeof newer.o);
  newer.o.size = sizeof newer;
  newer.o.ordering = GAB_ORDERING_ND;
  const auto new_caller = outcome(&newer.o);
  EXPECT_EQ(new_caller.first.code, GAB_OK) << new_caller.first.message;
  EXPECT_EQ(new_caller.second, nd);
  newer.future[0] = 1;
  const Outcome refused = outcome(&newer.o).first;
  EXPECT_EQ(refused.code, GAB_E_UNSUPPORTED);
  EXPECT_EQ(refused.message, "gab_decompress_ex: options->size is " + std::to_string(sizeof newer) + " and byte " +
                                 std::to_string(sizeof newer.o) + " is set: gab " GAB_VERSION_STRING " knows " +
                                 std::to_string(sizeof o) + " bytes of options");
}

TEST(CapiTest, CompressRejectsBadArgumentsWithClearMessages) {
  const Mesh mesh = bumpy_torus(8, 6);
  const double* p = mesh.positions.data();
  const int32_t* f = mesh.triangles.data();
  const int32_t n = mesh.num_vertices(), t = mesh.num_triangles();
  EXPECT_EQ(capi_error_paths(), 1);
  const Outcome no_positions = compress_outcome(nullptr, n, f, t, 1e-3);
  EXPECT_EQ(no_positions.code, GAB_E_INVALID_ARGUMENT);
  EXPECT_EQ(no_positions.message, "gab_compress: positions is NULL");
  EXPECT_EQ(compress_outcome(p, n, nullptr, t, 1e-3).message, "gab_compress: triangles is NULL");
  EXPECT_EQ(compress_outcome(p, -4, f, t, 1e-3).message, "gab_compress: n = -4: a mesh needs at least one vertex");
  EXPECT_EQ(compress_outcome(p, n, f, 0, 1e-3).message, "gab_compress: t = 0: a mesh needs at least one triangle");
  // A triangle naming a vertex past n: the mesh layer's check, named.
  EXPECT_EQ(compress_outcome(p, 10, f, t, 1e-3).message,
            "gab_compress: mesh: triangle 6: vertex index 10 out of range [0, 10)");
  std::vector<double> nan_positions = mesh.positions;
  nan_positions[7] = std::nan("");
  EXPECT_EQ(compress_outcome(nan_positions.data(), n, f, t, 1e-3).message,
            "gab_compress: mesh: vertex 2: coordinate is not finite");
  EXPECT_EQ(compress_outcome(p, n, f, t, 0).message,
            "gab_compress: set a stopping rule: an anchor count, an RMS or an L-inf target");
  EXPECT_EQ(compress_outcome(p, n, f, t, -1).code, GAB_E_INVALID_ARGUMENT);
  char message[64];
  size_t size = 0;
  EXPECT_EQ(gab_compress(p, n, f, t, 1e-3, nullptr, &size, message, sizeof message), GAB_E_INVALID_ARGUMENT);
  EXPECT_STREQ(message, "gab_compress: out is NULL");
}

TEST(CapiTest, DecompressReportsHostileBytesAndNeverCrashes) {
  const Mesh mesh = bumpy_torus(12, 10);
  gab::EncodeOptions options;
  options.max_anchors = 30;
  gab::EncodeStats stats;
  const std::vector<uint8_t> file = gab::testing_util::encode_or_die(mesh, options, &stats);
  ASSERT_EQ(decompress_outcome(file.data(), file.size()).code, GAB_OK);
  const Outcome empty = decompress_outcome(nullptr, 0);
  EXPECT_EQ(empty.code, GAB_E_PARSE);
  EXPECT_EQ(empty.message.rfind("gab_decompress: ", 0), 0u) << empty.message;
  EXPECT_EQ(decompress_outcome(nullptr, 5).message, "gab_decompress: data is NULL");
  const std::string garbage = "this is not a .gab file, not at all";
  EXPECT_EQ(decompress_outcome(reinterpret_cast<const unsigned char*>(garbage.data()), garbage.size()).code,
            GAB_E_PARSE);
  char message[64];
  double* positions = nullptr;
  int32_t n = 0;
  EXPECT_EQ(gab_decompress(file.data(), file.size(), -1, &positions, &n, nullptr, nullptr, message, sizeof message),
            GAB_E_INVALID_ARGUMENT);
  EXPECT_STREQ(message, "gab_decompress: triangles is NULL");
  // Every cut and 300 random byte flips: a code and a message, never a crash
  // (ASan checks the reads).
  for (size_t cut = 0; cut < file.size(); cut += 1 + file.size() / 97) {
    const Outcome o = decompress_outcome(file.data(), cut);
    EXPECT_NE(o.code, GAB_E_INTERNAL) << cut << ": " << o.message;
    EXPECT_TRUE(o.code == GAB_OK || !o.message.empty()) << o.code;
  }
  std::mt19937 rng(7);
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<uint8_t> damaged = file;
    damaged[rng() % damaged.size()] ^= static_cast<uint8_t>(1 + rng() % 255);
    const Outcome o = decompress_outcome(damaged.data(), damaged.size(), trial % 3 == 0 ? 10 : -1);
    EXPECT_NE(o.code, GAB_E_INTERNAL) << trial << ": " << o.message;
    EXPECT_TRUE(o.code == GAB_OK || !o.message.empty()) << o.code;
  }
}

TEST(CapiTest, ReadMeshReadsAFileAndNamesWhatIsWrong) {
  const std::string path =
      gab_test::write_scratch_file("quad.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n3 0 2 1\n");
  capi_mesh mesh{};
  char message[256];
  ASSERT_EQ(capi_read_mesh(path.c_str(), &mesh, message, sizeof message), GAB_OK) << message;
  // The quad's arity is what the file held beyond triangles: said, the code still GAB_OK.
  EXPECT_EQ(std::string(message),
            "gab_read_mesh: " + path + ": not carried: 1 polygons of 4 or more corners (fan-triangulated)");
  EXPECT_EQ(mesh.n, 4);
  EXPECT_EQ(mesh.t, 3);  // the quad fan-triangulated, and the triangle
  EXPECT_EQ(mesh.positions[7], 1.0);
  EXPECT_EQ(std::vector<int32_t>(mesh.triangles, mesh.triangles + 9), (std::vector<int32_t>{0, 1, 2, 0, 2, 3, 0, 2, 1}));
  capi_free_mesh(&mesh);
  const std::string missing = gab_test::scratch_path("missing.off");
  EXPECT_EQ(capi_read_mesh(missing.c_str(), &mesh, message, sizeof message), GAB_E_IO);
  EXPECT_NE(std::string(message).find(missing), std::string::npos) << message;
  EXPECT_TRUE(mesh.positions == nullptr && mesh.n == 0);
  const std::string bad = gab_test::write_scratch_file("bad.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 5\n");
  EXPECT_EQ(capi_read_mesh(bad.c_str(), &mesh, message, sizeof message), GAB_E_PARSE) << message;
  EXPECT_EQ(capi_read_mesh(nullptr, &mesh, message, sizeof message), GAB_E_INVALID_ARGUMENT);
  EXPECT_STREQ(message, "gab_read_mesh: path is NULL");
  EXPECT_EQ(capi_read_mesh("mesh.stl", &mesh, message, sizeof message), GAB_E_INVALID_ARGUMENT);
}

// What a file held beyond positions and triangles is named in the message of
// a successful read: what gab does not carry (the CLI's warning) and the
// attributes gab reads that gab_read_mesh does not return (the readers keep
// them: gab_read_mesh_with_attributes returns them, its message naming
// neither); nothing is said of a plain file.
TEST(CapiTest, ReadMeshNamesWhatIsNotCarried) {
  const std::string obj = gab_test::write_scratch_file(
      "normals.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1/1 2/2/1 3/3/1\n");
  capi_mesh mesh{};
  char message[512];
  ASSERT_EQ(capi_read_mesh(obj.c_str(), &mesh, message, sizeof message), GAB_OK) << message;
  EXPECT_EQ(std::string(message), "gab_read_mesh: " + obj +
                                      ": not returned: 1 normals (per corner), 3 texture_coordinates (per corner); "
                                      "gab_read_mesh_with_attributes returns them");
  EXPECT_EQ(mesh.n, 3);
  EXPECT_EQ(mesh.t, 1);
  capi_free_mesh(&mesh);
  gab_attribute* attributes = nullptr;
  int32_t count = 0;
  ASSERT_EQ(capi_read_mesh_with_attributes(obj.c_str(), &mesh, &attributes, &count, message, sizeof message), GAB_OK)
      << message;
  EXPECT_STREQ(message, "");  // everything the file held is returned
  EXPECT_EQ(count, 2);
  gab_free(attributes);
  capi_free_mesh(&mesh);
  // Data gab does not carry, beside attributes it does: each named as what it is.
  const std::string grouped = gab_test::write_scratch_file(
      "grouped.obj", "mtllib a.mtl\ng part\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1\nl 1 2\n");
  ASSERT_EQ(capi_read_mesh(grouped.c_str(), &mesh, message, sizeof message), GAB_OK) << message;
  const std::string read = message;
  capi_free_mesh(&mesh);
  ASSERT_EQ(capi_read_mesh_with_attributes(grouped.c_str(), &mesh, &attributes, &count, message, sizeof message),
            GAB_OK);
  const std::string carried = std::string(message).substr(std::strlen("gab_read_mesh_with_attributes: "));
  EXPECT_EQ(carried.rfind(grouped + ": not carried: ", 0), 0u) << carried;
  EXPECT_NE(carried.find("groups (g)"), std::string::npos) << carried;
  EXPECT_EQ(carried.find("normals"), std::string::npos) << carried;  // returned: not named
  EXPECT_EQ(read, "gab_read_mesh: " + carried +
                      "; not returned: 1 normals (per corner); gab_read_mesh_with_attributes returns them");
  gab_free(attributes);
  capi_free_mesh(&mesh);
  const std::string plain = gab_test::write_scratch_file("plain.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  std::strcpy(message, "stale");
  ASSERT_EQ(capi_read_mesh(plain.c_str(), &mesh, message, sizeof message), GAB_OK) << message;
  EXPECT_STREQ(message, "");
  capi_free_mesh(&mesh);
}

TEST(CapiTest, CholeskySolvesAndUpdatesLikeAFreshFactorization) {
  const gab::CscMatrix a = gab_test::grid_laplacian(20, 0.05);
  const int32_t n = a.nrows, nrhs = 3, j = 137;
  const double w = 3.0;
  std::vector<double> b(static_cast<size_t>(n) * nrhs);
  for (size_t i = 0; i < b.size(); ++i) b[i] = std::sin(0.37 * static_cast<double>(i)) + 0.1;
  std::vector<double> x(b.size()), x_updated(b.size());
  int code[6];
  capi_cholesky_run(n, a.colptr.data(), a.rowind.data(), a.values.data(), b.data(), nrhs, j, w, x.data(),
                    x_updated.data(), code);
  for (int k = 0; k < 6; ++k) EXPECT_EQ(code[k], GAB_OK) << "call " << k;
  // A + w^2 e_j e_j^T, factored afresh through the C API.
  gab::CscMatrix updated = a;
  updated.values[updated.colptr[j]] += w * w;  // the diagonal leads its column
  for (int32_t r = 0; r < nrhs; ++r) {
    const size_t at = static_cast<size_t>(r) * n;
    EXPECT_LT(gab_test::relative_residual(a, &x[at], &b[at]), 1e-12);
    EXPECT_LT(gab_test::relative_residual(updated, &x_updated[at], &b[at]), 1e-12);
  }
  gab_cholesky* fresh = nullptr;
  char message[256];
  ASSERT_EQ(gab_cholesky_create(n, updated.colptr.data(), updated.rowind.data(), updated.values.data(), &fresh,
                                message, sizeof message),
            GAB_OK)
      << message;
  std::vector<double> x_fresh = b;
  ASSERT_EQ(gab_cholesky_solve(fresh, x_fresh.data(), nrhs), GAB_OK);
  for (size_t i = 0; i < b.size(); ++i) EXPECT_NEAR(x_updated[i], x_fresh[i], 1e-12 * (1 + std::fabs(x_fresh[i])));
  // Refactoring discards the update.
  ASSERT_EQ(gab_cholesky_factorize(fresh, a.values.data(), message, sizeof message), GAB_OK);
  std::vector<double> x_again = b;
  ASSERT_EQ(gab_cholesky_solve(fresh, x_again.data(), nrhs), GAB_OK);
  for (size_t i = 0; i < b.size(); ++i) EXPECT_NEAR(x_again[i], x[i], 1e-12 * (1 + std::fabs(x[i])));
  gab_cholesky_destroy(fresh);
}

// gab_cholesky_create_ex: every ordering of the engine (gab factor's
// --ordering) and its threads. Each solves A x = b; the orderings differ in
// the factor they make (natural's banded fill on a grid against AMD's),
// as the C++ engine's analysis with the same ordering says; the thread count
// changes nothing of the result.
TEST(CapiTest, CholeskyOptionsPickTheOrderingAndTheThreads) {
  const gab::CscMatrix a = gab_test::grid_laplacian(40, 0.05);
  const int32_t n = a.nrows, nrhs = 2;
  std::vector<double> b(static_cast<size_t>(n) * nrhs);
  for (size_t i = 0; i < b.size(); ++i) b[i] = std::cos(0.13 * static_cast<double>(i)) + 0.2;
  struct Case {
    int32_t code;
    gab::Ordering ordering;
  };
  const Case cases[] = {{GAB_ORDERING_AMD, gab::Ordering::kAmd},
                        {GAB_ORDERING_ND, gab::Ordering::kNestedDissection},
                        {GAB_ORDERING_NATURAL, gab::Ordering::kNatural},
                        {GAB_ORDERING_AUTO, gab::Ordering::kAmd}};  // AMD below 100,000 columns
  char message[256];
  std::vector<int64_t> entries;
  for (const Case& c : cases) {
    // The C++ engine's factor for this ordering: its size is what the handle reports.
    gab::Cholesky reference;
    gab::AnalyzeOptions analyze;
    analyze.ordering = c.ordering;
    ASSERT_TRUE(reference.analyze(a, analyze).ok());
    const int64_t expected = reference.symbolic().value_ptr.back();
    std::vector<double> one_thread;
    for (int32_t threads : {1, 2, 0}) {
      std::vector<double> x(b.size());
      int64_t stored = 0;
      ASSERT_EQ(capi_cholesky_ordered(n, a.colptr.data(), a.rowind.data(), a.values.data(), c.code, threads,
                                      b.data(), nrhs, x.data(), &stored, message, sizeof message),
                GAB_OK)
          << c.code << ", " << threads << " threads: " << message;
      EXPECT_EQ(stored, expected) << c.code;
      for (int32_t r = 0; r < nrhs; ++r) {
        const size_t at = static_cast<size_t>(r) * n;
        EXPECT_LT(gab_test::relative_residual(a, &x[at], &b[at]), 1e-12) << c.code << ", " << threads << " threads";
      }
      if (threads == 1) {
        one_thread = x;
      } else {
        EXPECT_EQ(x, one_thread) << c.code << ": " << threads << " threads";
      }
    }
    entries.push_back(expected);
  }
  // Natural order fills the grid's band (nnz(L) about n k, three times AMD's here).
  EXPECT_GT(entries[2], 3 * entries[0] / 2) << "natural order should fill a grid's band, AMD far less";
  EXPECT_GT(entries[2], 3 * entries[1] / 2) << "natural order should fill a grid's band, ND far less";
  EXPECT_EQ(entries[3], entries[0]);
  // NULL options and the initialized defaults are gab_cholesky_create.
  gab_cholesky* plain = nullptr;
  gab_cholesky* defaults = nullptr;
  gab_cholesky_options o;
  gab_cholesky_options_init(&o, sizeof o);
  EXPECT_EQ(o.size, sizeof o);
  EXPECT_EQ(o.ordering, GAB_ORDERING_AMD);
  EXPECT_EQ(o.threads, 1);
  ASSERT_EQ(gab_cholesky_create(n, a.colptr.data(), a.rowind.data(), nullptr, &plain, message, sizeof message),
            GAB_OK);
  ASSERT_EQ(gab_cholesky_create_ex(n, a.colptr.data(), a.rowind.data(), nullptr, nullptr, &defaults, message,
                                   sizeof message),
            GAB_OK);
  EXPECT_EQ(gab_cholesky_factor_entries(plain), entries[0]);
  EXPECT_EQ(gab_cholesky_factor_entries(defaults), entries[0]);
  gab_cholesky_destroy(plain);
  gab_cholesky_destroy(defaults);
}

TEST(CapiTest, CholeskyOptionsAreCheckedAsTheOtherOptions) {
  const std::vector<int32_t> colptr = {0, 2, 3, 4}, rowind = {0, 1, 1, 2};
  const double values[4] = {2, -1, 2, 1};
  char message[256];
  auto create = [&](const gab_cholesky_options* o) {
    gab_cholesky* c = reinterpret_cast<gab_cholesky*>(&message);  // must come back NULL on failure
    const int code = gab_cholesky_create_ex(3, colptr.data(), rowind.data(), values, o, &c, message, sizeof message);
    const bool cleared = code == GAB_OK || c == nullptr;
    if (code == GAB_OK) gab_cholesky_destroy(c);
    return cleared ? Outcome{code, message} : Outcome{GAB_E_INTERNAL, "handle not cleared on failure"};
  };
  gab_cholesky_options o;
  gab_cholesky_options_init(&o, sizeof o);
  EXPECT_EQ(create(&o).code, GAB_OK) << message;
  o.ordering = 7;
  const Outcome unknown = create(&o);
  EXPECT_EQ(unknown.code, GAB_E_INVALID_ARGUMENT);
  EXPECT_EQ(unknown.message,
            "gab_cholesky_create_ex: options->ordering is 7: must be GAB_ORDERING_AMD, GAB_ORDERING_ND, "
            "GAB_ORDERING_NATURAL or GAB_ORDERING_AUTO");
  gab_cholesky_options_init(&o, sizeof o);
  o.threads = -2;
  EXPECT_EQ(create(&o).message,
            "gab_cholesky_create_ex: options->threads is -2: must be in 0..64 (0: every core)");
  // An older caller's struct (up to ordering): the threads it does not know
  // take their default whatever the bytes after its size hold.
  struct {
    gab_cholesky_options o;
    unsigned char guard[8];
  } older;
  std::memset(&older, 0xAB, sizeof older);
  gab_cholesky_options_init(&older.o, offsetof(gab_cholesky_options, threads));
  EXPECT_EQ(older.o.size, offsetof(gab_cholesky_options, threads));
  EXPECT_EQ(older.o.ordering, GAB_ORDERING_AMD);
  older.o.ordering = GAB_ORDERING_NATURAL;
  EXPECT_EQ(create(&older.o).code, GAB_OK) << message;
  // A newer caller's larger struct: a zero tail accepted, a set byte refused.
  struct {
    gab_cholesky_options o;
    int64_t future[2];
  } newer;
  std::memset(&newer, 0, sizeof newer);
  gab_cholesky_options_init(&newer.o, sizeof newer.o);
  newer.o.size = sizeof newer;
  EXPECT_EQ(create(&newer.o).code, GAB_OK) << message;
  newer.future[1] = 1;
  const Outcome refused = create(&newer.o);
  EXPECT_EQ(refused.code, GAB_E_UNSUPPORTED);
  EXPECT_EQ(refused.message, "gab_cholesky_create_ex: options->size is " + std::to_string(sizeof newer) +
                                 " and byte " + std::to_string(sizeof newer - 8) + " is set: gab " GAB_VERSION_STRING
                                 " knows " + std::to_string(sizeof o) + " bytes of options");
  gab_cholesky_options_init(&o, 4);  // not even the size field: nothing written
  o.size = 4;
  EXPECT_EQ(create(&o).message,
            "gab_cholesky_create_ex: options->size is 4: set it with gab_cholesky_options_init");
  // A pattern error is named as gab_cholesky_create names it.
  gab_cholesky* c = nullptr;
  EXPECT_EQ(gab_cholesky_create_ex(3, colptr.data(), rowind.data(), nullptr, nullptr, nullptr, message,
                                   sizeof message),
            GAB_E_INVALID_ARGUMENT);
  EXPECT_STREQ(message, "gab_cholesky_create_ex: out is NULL");
  EXPECT_EQ(gab_cholesky_create_ex(0, colptr.data(), rowind.data(), nullptr, nullptr, &c, message, sizeof message),
            GAB_E_INVALID_ARGUMENT);
  EXPECT_STREQ(message, "gab_cholesky_create_ex: n = 0: must be positive");
  EXPECT_EQ(gab_cholesky_factor_entries(nullptr), -1);
}

TEST(CapiTest, CholeskyRejectsBadPatternsWithClearMessages) {
  // [2 -1; -1 2] and a third column, lower triangle.
  const std::vector<int32_t> colptr = {0, 2, 3, 4}, rowind = {0, 1, 1, 2};
  EXPECT_EQ(create_outcome(3, colptr, rowind).code, GAB_OK);
  const Outcome above = create_outcome(3, {0, 1, 3, 4}, {0, 0, 1, 2});
  EXPECT_EQ(above.code, GAB_E_INVALID_ARGUMENT);
  EXPECT_EQ(above.message, "gab_cholesky_create: column 1: row 0 is above the diagonal (give the lower triangle)");
  EXPECT_EQ(create_outcome(3, {0, 1, 2, 3}, {1, 1, 2}).message, "gab_cholesky_create: column 0 has no diagonal entry");
  EXPECT_EQ(create_outcome(3, {0, 2, 3, 4}, {1, 0, 1, 2}).message,
            "gab_cholesky_create: column 0 has an out-of-range or unsorted row index");
  EXPECT_EQ(create_outcome(3, {0, 2, 3, 4}, {0, 0, 1, 2}).message,  // a duplicate
            "gab_cholesky_create: column 0 has an out-of-range or unsorted row index");
  EXPECT_EQ(create_outcome(3, {0, 2, 3, 4}, {0, 3, 1, 2}).message,
            "gab_cholesky_create: column 0 has an out-of-range or unsorted row index");
  EXPECT_EQ(create_outcome(3, {1, 2, 3, 4}, rowind).message, "gab_cholesky_create: colptr[0] = 1: must be 0");
  EXPECT_EQ(create_outcome(3, {0, 2, 1, 4}, rowind).message, "gab_cholesky_create: colptr decreases at column 1");
  EXPECT_EQ(create_outcome(0, colptr, rowind).message, "gab_cholesky_create: n = 0: must be positive");
  char message[128];
  gab_cholesky* c = nullptr;
  EXPECT_EQ(gab_cholesky_create(3, nullptr, rowind.data(), nullptr, &c, message, sizeof message),
            GAB_E_INVALID_ARGUMENT);
  EXPECT_STREQ(message, "gab_cholesky_create: colptr is NULL");
  EXPECT_EQ(gab_cholesky_create(3, colptr.data(), rowind.data(), nullptr, nullptr, message, sizeof message),
            GAB_E_INVALID_ARGUMENT);
  EXPECT_STREQ(message, "gab_cholesky_create: out is NULL");
}

TEST(CapiTest, CholeskyCallsOutOfOrderOrOnBadValuesSaySo) {
  const std::vector<int32_t> colptr = {0, 2, 3, 4}, rowind = {0, 1, 1, 2};
  char message[128];
  gab_cholesky* c = nullptr;
  ASSERT_EQ(gab_cholesky_create(3, colptr.data(), rowind.data(), nullptr, &c, message, sizeof message), GAB_OK);
  double b[3] = {1, 2, 3};
  EXPECT_EQ(gab_cholesky_solve(c, b, 1), GAB_E_STATE);
  EXPECT_STREQ(gab_cholesky_message(c),
               "gab_cholesky_solve: no factorization: call gab_cholesky_factorize first (or it failed)");
  EXPECT_EQ(gab_cholesky_add_anchor(c, 0, 1.0), GAB_E_STATE);
  const double indefinite[4] = {1, 2, 1, 1};  // [1 2; 2 1] is indefinite
  EXPECT_EQ(gab_cholesky_factorize(c, indefinite, message, sizeof message), GAB_E_NOT_POSITIVE_DEFINITE);
  EXPECT_NE(std::string(message).find("column"), std::string::npos) << message;
  EXPECT_STREQ(gab_cholesky_message(c), message);
  EXPECT_EQ(gab_cholesky_solve(c, b, 1), GAB_E_STATE);  // the failed factorization left none
  const double not_finite[4] = {2, -1, 2, HUGE_VAL};
  EXPECT_EQ(gab_cholesky_factorize(c, not_finite, message, sizeof message), GAB_E_INVALID_ARGUMENT);
  EXPECT_STREQ(message, "gab_cholesky_factorize: values[3] is not finite");
  EXPECT_EQ(gab_cholesky_factorize(c, nullptr, message, sizeof message), GAB_E_INVALID_ARGUMENT);
  EXPECT_STREQ(message, "gab_cholesky_factorize: values is NULL");
  const double values[4] = {2, -1, 2, 1};
  ASSERT_EQ(gab_cholesky_factorize(c, values, message, sizeof message), GAB_OK);
  EXPECT_STREQ(gab_cholesky_message(c), "");
  EXPECT_EQ(gab_cholesky_solve(c, b, -1), GAB_E_INVALID_ARGUMENT);
  EXPECT_STREQ(gab_cholesky_message(c), "gab_cholesky_solve: nrhs = -1: must not be negative");
  EXPECT_EQ(gab_cholesky_solve(c, nullptr, 1), GAB_E_INVALID_ARGUMENT);
  EXPECT_STREQ(gab_cholesky_message(c), "gab_cholesky_solve: b is NULL");
  EXPECT_EQ(gab_cholesky_solve(c, nullptr, 0), GAB_OK);  // nothing to solve
  EXPECT_EQ(gab_cholesky_add_anchor(c, 3, 1.0), GAB_E_INVALID_ARGUMENT);
  EXPECT_STREQ(gab_cholesky_message(c), "gab_cholesky_add_anchor: j = 3 is out of range [0, 3)");
  EXPECT_EQ(gab_cholesky_add_anchor(c, 1, std::nan("")), GAB_E_INVALID_ARGUMENT);
  EXPECT_STREQ(gab_cholesky_message(c), "gab_cholesky_add_anchor: w is not finite");
  ASSERT_EQ(gab_cholesky_solve(c, b, 1), GAB_OK);
  EXPECT_STREQ(gab_cholesky_message(c), "");
  // [2 -1 0; -1 2 0; 0 0 1] x = (1 2 3): x = (4/3, 5/3, 3).
  EXPECT_NEAR(b[0], 4.0 / 3, 1e-14);
  EXPECT_NEAR(b[1], 5.0 / 3, 1e-14);
  EXPECT_NEAR(b[2], 3.0, 1e-14);
  gab_cholesky_destroy(c);
}

TEST(CapiTest, SharedMeshRoundTripKeepsTheNumbering) {
  const std::string path = std::string(GAB_SHARED_MESHES) + "/bunny-small.off";
  capi_mesh mesh{};
  char message[256];
  if (capi_read_mesh(path.c_str(), &mesh, message, sizeof message) == GAB_E_IO) {
    GTEST_SKIP() << "no shared meshes (" << path << "): " << message;
  }
  ASSERT_NE(mesh.positions, nullptr) << message;
  capi_round_trip r;
  capi_round_trip_run(mesh.positions, mesh.n, mesh.triangles, mesh.t, 1e-3, 50, &r);
  ASSERT_EQ(r.compress_code, GAB_OK) << r.message;
  ASSERT_EQ(r.decode_code, GAB_OK) << r.message;
  EXPECT_EQ(r.decoded.n, mesh.n);
  EXPECT_LE(r.rms_rel, 1e-3);
  EXPECT_GT(r.coarse_rms_rel, r.rms_rel);
  EXPECT_EQ(gab_test::oriented_set(r.decoded.triangles, r.decoded.t), gab_test::oriented_set(mesh.triangles, mesh.t));
  capi_round_trip_free(&r);
  capi_free_mesh(&mesh);
}

}  // namespace
