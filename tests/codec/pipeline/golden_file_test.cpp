// Golden .gab files pin format version 2 by their whole bytes: the fuzzer
// seeds in tests/fuzz/corpus/gab (a leading options byte, then a file that
// tests/fuzz/make_gab_seeds.sh made with `gab compress` from
// gab_fuzz::seed_torus), one per variant the format has (each flag, both
// layouts, both orderings, every reconstruction operator, geometry only, the
// detail chunk, attribute sections of every kind, prefixes).
// Each seed must keep its bytes, keep decoding to its pinned shape, and be
// what the encoder writes today for its options (but operators 1 and 2's,
// which it no longer writes: earlier encoders', decoded as they are). A
// seed that no longer keeps its bytes or its shape is a format change:
// version 2 files exist, so it needs a new version or a new value in a
// reserved header field (docs/format.md), not new seeds. An encoder that
// chooses differently (other anchors, another detail step: the same
// variants, other bytes) regenerates the seeds it writes once the old ones
// pass here: each variant stays pinned by whole bytes.
#include <dirent.h>
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "codec/attributes/attribute_checks.h"
#include "common/gab_files.h"
#include "connectivity/valence_section.h"
#include "fuzz/gab_fuzz_mesh.h"
#include "gab/codec/decoder.h"
#include "gab/codec/encoder.h"
#include "gab/codec/gab_format.h"
#include "gab/mesh/file_io.h"
#include "gab/mesh/renumber.h"
#include "gab/mesh/triangle_set.h"

namespace gab {
namespace {

const std::string kCorpus = std::string(GAB_FUZZ_DIR) + "/corpus/gab";

// A seed's bytes: its options byte, then the file.
std::string seed_bytes(const std::string& name) {
  std::string bytes;
  EXPECT_TRUE(read_file(kCorpus + "/" + name, &bytes).ok()) << name;
  return bytes;
}

std::vector<uint8_t> seed(const std::string& name) {
  const std::string bytes = seed_bytes(name);
  return std::vector<uint8_t>(bytes.begin() + (bytes.empty() ? 0 : 1), bytes.end());
}

// FNV-1a 64 over bytes.
uint64_t fnv1a(const uint8_t* bytes, size_t size) {
  uint64_t h = 0xcbf29ce484222325ull;
  for (size_t i = 0; i < size; ++i) h = (h ^ bytes[i]) * 0x100000001b3ull;
  return h;
}

// A fingerprint of a shape: FNV-1a over the bytes of the coordinates.
uint64_t shape_fingerprint(const std::vector<double>& positions) {
  return fnv1a(reinterpret_cast<const uint8_t*>(positions.data()), positions.size() * sizeof(double));
}

// make_gab_seeds.sh's `gab compress` options for a seed, as EncodeOptions
// (the flags the script uses; the CLI maps them one to one, its default
// numbering the traversal's as the library's: --keep-order keeps the input's).
EncodeOptions options_of(const std::string& args) {
  EncodeOptions o;
  std::istringstream in(args);
  std::string flag, value;
  while (in >> flag) {
    if (flag == "--geometry-only") o.geometry_only = true;
    else if (flag == "--refine") o.refine = true;
    else if (flag == "--reorder") o.reorder = true;
    else if (flag == "--keep-order") o.reorder = false;
    else if (!(in >> value)) ADD_FAILURE() << flag << " needs a value";
    else if (flag == "--anchors") o.max_anchors = std::stoi(value);
    else if (flag == "--error") o.target_rms_rel = std::stod(value);
    else if (flag == "--bits") o.bits = std::stoi(value);
    else if (flag == "--chunk-growth") o.chunk_growth = std::stod(value);
    else if (flag == "--initial") o.initial_anchors = std::stoi(value);
    else if (flag == "--layout") o.layout = value == "levels" ? FileLayout::kLevels : FileLayout::kSelectionOrder;
    else if (flag == "--detail") o.detail = DetailMode::kOn;
    else if (flag == "--ordering") o.ordering = Ordering::kNestedDissection;
    else if (flag == "--solver") EXPECT_TRUE(parse_solver(value, &o.solver)) << value;
    else ADD_FAILURE() << "unknown option " << flag;
  }
  return o;
}

struct Golden {
  const char* name;
  uint64_t file_hash;  // FNV-1a of the seed file, options byte included
  uint8_t flags;       // header byte 9
  int bits, anchors, chunks;
  double rms_rel;       // of the decoded shape against seed_torus, in its numbering
  const char* options;  // make_gab_seeds.sh's for the file; null: an earlier operator's, not written today
  bool large = false;   // made from large_seed_torus, not seed_torus
  bool attributes = false;  // made from attributed_seed_torus (one attribute of each kind)
};

// Every variant, as make_gab_seeds.sh writes it. rms_rel: a shape the global
// solver makes may differ by rounding on another SIMD level, so it is
// pinned to 1e-7; the detail chunk's positions and the iterative solver's
// shapes are exact (pinned below).
const std::vector<Golden>& goldens() {
  constexpr uint8_t kGeo = kGabFlagGeometryOnly, kLevels = kGabFlagLevels;
  static const std::vector<Golden> all = {
      {"torus-full", 0x824442527a9b539full, 0, 12, 20, 8, 0.022588347,
       "--anchors 20 --chunk-growth 1.5 --layout selection --solver global --keep-order"},
      {"torus-geometry-only", 0xb374d63c1840c5d3ull, kGeo, 8, 12, 5, 0.035451577,
       "--anchors 12 --geometry-only --bits 8 --chunk-growth 2 --layout selection --solver global"},
      {"torus-coarse", 0x260b74b1b79fcd03ull, 0, 6, 37, 7, 0.009801301,
       "--error 0.01 --bits 6 --chunk-growth 2 --layout selection --solver global --keep-order"},
      {"torus-refined", 0x900fb22cd67100f4ull, kGabFlagRefined, 12, 16, 6, 0.024199612,
       "--anchors 16 --refine --chunk-growth 2 --layout selection --keep-order"},
      {"torus-levels", 0x598c0402f0050619ull, kLevels, 12, 40, 5, 0.008304911,
       "--anchors 40 --initial 4 --layout levels --chunk-growth 1.5 --solver global --keep-order"},
      {"torus-levels-refined", 0xd90bc57f331f69e1ull, kLevels | kGabFlagRefined, 12, 24, 5, 0.014869626,
       "--anchors 24 --initial 3 --layout levels --refine --keep-order"},
      {"torus-ordered", 0x2399a3f5c41efe5dull, kLevels, 12, 20, 4, 0.022588347,
       "--anchors 20 --chunk-growth 1.5 --solver global --keep-order"},
      {"torus-reordered", 0x83f61e3fc9dd1898ull, kLevels | kGabFlagReordered, 12, 20, 4, 0.022588347,
       "--anchors 20 --chunk-growth 1.5 --reorder --solver global"},
      {"torus-nd", 0x25ff4b3b24ba6282ull, kLevels, 12, 20, 4, 0.022588347,
       "--anchors 20 --chunk-growth 1.5 --ordering nd --solver global --keep-order"},
      {"torus-detail", 0xb454c0aa3cc55725ull, kGabFlagDetail, 6, 15, 4, 0.000099702,
       "--error 1e-4 --detail on --solver global --keep-order"},
      {"torus-detail-geometry-only", 0xdb991622f7b0d688ull, kGeo | kGabFlagDetail, 6, 15, 4, 0.000099905,
       "--error 1e-4 --detail on --geometry-only --solver global"},
      {"torus-iterative", 0x31abc4769bb00cdaull, kLevels, 12, 20, 4, 0.022223650,
       "--anchors 20 --chunk-growth 1.5 --solver iterative --keep-order"},
      {"torus-iterative-selection", 0x0f1687500b9564edull, 0, 12, 20, 7, 0.022223650,
       "--anchors 20 --chunk-growth 1.5 --layout selection --solver iterative --keep-order"},
      {"torus-iterative-detail", 0x7423022b8aa47d82ull, kGabFlagDetail, 6, 15, 4, 0.000099257,
       "--error 1e-4 --detail on --solver iterative --keep-order"},
      {"torus-iterative-large", 0x76bca00e9404d250ull, kLevels, 12, 300, 3, 0.006329242,
       "--anchors 300 --solver iterative --keep-order", true},
      // Attribute sections: normals from the decoded surface, byte colours, a
      // float property, per-corner texture coordinates with seams.
      {"torus-attributes", 0xc1ce0d2cb559042cull, kLevels | kGabFlagReordered, 12, 20, 4, 0.022186366,
       "--anchors 20 --chunk-growth 1.5",
       false, true},
      {"torus-attributes-detail", 0x2d68ba0cc961fe39ull, kGabFlagDetail | kGabFlagReordered, 6, 15, 4, 0.000095796,
       "--error 1e-4 --detail on", false, true},
      // Operator 2, made by an earlier encoder with torus-iterative*'s options
      // (and another greedy loop: other anchors than torus-iterative*'s).
      {"torus-operator2", 0xc1212b18592d3d6cull, kLevels, 12, 20, 4, 0.020931225, nullptr},
      {"torus-operator2-selection", 0x9bec0fe97beac200ull, 0, 12, 20, 8, 0.020931225, nullptr},
      {"torus-operator2-detail", 0x4547a313ea78c562ull, kGabFlagDetail, 6, 15, 4, 0.000098065, nullptr},
      {"torus-operator2-large", 0x2b94270f1256cd4aull, kLevels, 12, 300, 3, 0.009721790, nullptr, true},
      // Operator 1, made by an earlier encoder with torus-iterative*'s options.
      {"torus-operator1", 0xa177618616521ad2ull, kLevels, 12, 20, 4, 0.021768607, nullptr},
      {"torus-operator1-selection", 0xd5c603d01d806202ull, 0, 12, 20, 8, 0.021768607, nullptr},
      {"torus-operator1-detail", 0x15d5fec3c8931bd1ull, kGabFlagDetail, 6, 15, 4, 0.000098065, nullptr},
  };
  return all;
}

// The torus as a file's decoder numbers it.
Mesh expected_mesh(const Golden& g) {
  const Mesh torus = g.large        ? gab_fuzz::large_seed_torus()
                     : g.attributes ? gab_fuzz::attributed_seed_torus()
                                    : gab_fuzz::seed_torus();
  if ((g.flags & kGabFlagReordered) == 0) return torus;
  return renumber_vertices(torus, encode_valence_section(torus.num_vertices(), torus.triangles).new_index);
}

TEST(GoldenFiles, EverySeedKeepsItsBytes) {
  for (const Golden& g : goldens()) {
    const std::string bytes = seed_bytes(g.name);
    EXPECT_EQ(fnv1a(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size()), g.file_hash)
        << g.name << std::hex << " 0x" << fnv1a(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
  }
}

TEST(GoldenFiles, EverySeedDecodesToItsPinnedShape) {
  const Mesh torus = gab_fuzz::seed_torus();
  for (const Golden& g : goldens()) {
    const std::vector<uint8_t> file = seed(g.name);
    ASSERT_GE(file.size(), kGabMinHeaderBytes) << g.name;
    EXPECT_TRUE(std::equal(kGabMagic, kGabMagic + 8, file.begin())) << g.name;
    EXPECT_EQ(file[8], kGabVersion) << g.name;
    EXPECT_EQ(file[9], g.flags) << g.name;
    DecodeOptions options;
    options.connectivity = (g.flags & kGabFlagGeometryOnly) ? &torus : nullptr;
    Mesh out;
    DecodeStats ds;
    const Status s = decode_mesh(file.data(), file.size(), options, &out, &ds);
    ASSERT_TRUE(s.ok()) << g.name << ": " << s.message();
    const Mesh expected = expected_mesh(g);
    EXPECT_EQ(oriented_triangle_set(out.triangles), oriented_triangle_set(expected.triangles)) << g.name;
    EXPECT_EQ(ds.bits, g.bits) << g.name;
    EXPECT_EQ(ds.anchors, g.anchors) << g.name;
    EXPECT_EQ(ds.chunks, g.chunks) << g.name;
    EXPECT_NEAR(testing_util::relative_rms(expected, out), g.rms_rel, 1e-7) << g.name;
    // Every attribute within its quantization: normals within the 8-bit
    // lattice's reach, colours exact, the rest within half a step.
    ASSERT_EQ(out.attributes.size(), expected.attributes.size()) << g.name;
    const double bounds[4] = {0.6, 0.5 / 1023 * (1 + 1e-9), 0.0, 0.5 * 11.25 / 65535 * (1 + 1e-9)};
    for (size_t i = 0; i < out.attributes.size(); ++i) {
      EXPECT_LE(testing_util::largest_attribute_error(expected, out, {}, i), bounds[i]) << g.name << " " << i;
    }
  }
}

TEST(GoldenFiles, TheEncoderWritesEverySeed) {
  const Mesh torus = gab_fuzz::seed_torus(), large = gab_fuzz::large_seed_torus();
  const Mesh attributed = gab_fuzz::attributed_seed_torus();
  for (const Golden& g : goldens()) {
    if (!g.options) continue;
    EncodeStats es;
    EXPECT_EQ(testing_util::encode_or_die(g.large ? large : g.attributes ? attributed : torus, options_of(g.options), &es),
              seed(g.name))
        << g.name;
  }
}

TEST(GoldenFiles, DetailSeedsDecodeToTheirPinnedBits) {
  // The detail chunk's decoded coordinates do not depend on the machine or
  // SIMD level (detail_chunk.h), so they are pinned bit for bit.
  const Mesh torus = gab_fuzz::seed_torus();
  struct Seed {
    const char* name;
    bool geometry_only;
    uint64_t fingerprint;
  };
  for (const Seed& g : {Seed{"torus-detail", false, 0xce594d0d6d6a2636ull},
                        Seed{"torus-detail-geometry-only", true, 0xeaaf70d2f9f2840full}}) {
    const std::vector<uint8_t> golden = seed(g.name);
    DecodeOptions decode;
    decode.connectivity = g.geometry_only ? &torus : nullptr;
    Mesh out;
    DecodeStats ds;
    const Status status = decode_mesh(golden.data(), golden.size(), decode, &out, &ds);
    ASSERT_TRUE(status.ok()) << g.name << ": " << status.message();
    EXPECT_TRUE(ds.detail) << g.name;
    EXPECT_LE(testing_util::relative_rms(torus, out), 1e-4) << g.name;
    EXPECT_EQ(shape_fingerprint(out.positions), g.fingerprint) << g.name << std::hex << " 0x"
                                                                << shape_fingerprint(out.positions);
  }
}

TEST(GoldenFiles, IterativeSeedsDecodeToTheirPinnedBits) {
  // The iterative operators fix every operation (docs/format.md 5.2.1 to
  // 5.2.3): their shapes, whole or a prefix, are the same bits on any
  // machine, SIMD level and thread count, so they are pinned bit for bit.
  struct Seed {
    const char* name;
    int32_t max_anchors;
    uint64_t fingerprint;
  };
  // (Both layouts code the same anchors, whose shape depends on them alone.)
  for (const Seed& g : {Seed{"torus-iterative", -1, 0x60ec70ce634b5936ull},
                        Seed{"torus-iterative", 10, 0xa28c5cae9ed75bafull},
                        Seed{"torus-iterative-selection", -1, 0x60ec70ce634b5936ull},
                        Seed{"torus-iterative-detail", -1, 0xd048e99ab77b9fcbull},
                        Seed{"torus-iterative-large", -1, 0xc34c3adb71f66e1bull},
                        Seed{"torus-iterative-large", 100, 0x7cf27e2c14b4642cull},
                        Seed{"torus-operator2", -1, 0xc306299c072e51efull},
                        Seed{"torus-operator2", 10, 0x6798242a3a1f823dull},
                        Seed{"torus-operator2-selection", -1, 0xc306299c072e51efull},
                        Seed{"torus-operator2-detail", -1, 0xd91e627a6525b252ull},
                        Seed{"torus-operator2-large", -1, 0x0041af6f9dc57a05ull},
                        Seed{"torus-operator2-large", 100, 0xa84f37c9b1745f4eull},
                        Seed{"torus-operator1", -1, 0x0276aba1b3f1ff13ull},
                        Seed{"torus-operator1", 10, 0xbd475e0a4716f1fcull},
                        Seed{"torus-operator1-selection", -1, 0x0276aba1b3f1ff13ull},
                        Seed{"torus-operator1-detail", -1, 0xd91e627a6525b252ull}}) {
    const std::vector<uint8_t> golden = seed(g.name);
    for (int32_t threads : {1, 2}) {
      DecodeOptions decode;
      decode.max_anchors = g.max_anchors;
      decode.threads = threads;
      Mesh out;
      DecodeStats ds;
      const Status status = decode_mesh(golden.data(), golden.size(), decode, &out, &ds);
      ASSERT_TRUE(status.ok()) << g.name << ": " << status.message();
      EXPECT_EQ(ds.solver, Solver::kIterative) << g.name;
      EXPECT_EQ(shape_fingerprint(out.positions), g.fingerprint)
          << g.name << " " << g.max_anchors << std::hex << " 0x" << shape_fingerprint(out.positions);
    }
  }
}

TEST(GoldenFiles, NestedDissectionSeedDecodesWithEitherOrdering) {
  // torus-nd: torus-ordered's options with --ordering nd (header byte 11 =
  // 1). The same anchors, hence the same chunks; the shape solved from them
  // is the same up to rounding whichever ordering decodes it.
  const Mesh torus = gab_fuzz::seed_torus();
  const std::vector<uint8_t> golden = seed("torus-nd");
  GabFileInfo info;
  ASSERT_TRUE(read_gab_info(golden.data(), golden.size(), &info).ok());
  EXPECT_EQ(golden[11], kGabOrderingNestedDissection);
  const std::vector<uint8_t> amd = seed("torus-ordered");
  ASSERT_EQ(golden.size(), amd.size());
  EXPECT_EQ(std::vector<uint8_t>(golden.begin() + info.header_bytes, golden.end()),
            std::vector<uint8_t>(amd.begin() + info.header_bytes, amd.end()));
  for (Ordering ordering : {Ordering::kAuto, Ordering::kAmd}) {
    DecodeOptions options;
    options.ordering = ordering;
    Mesh out;
    DecodeStats ds;
    const Status status = decode_mesh(golden.data(), golden.size(), options, &out, &ds);
    ASSERT_TRUE(status.ok()) << status.message();
    EXPECT_EQ(ds.ordering,
              ordering == Ordering::kAuto ? Ordering::kNestedDissection : Ordering::kAmd);
    EXPECT_EQ(ds.anchors, 20);
    EXPECT_EQ(oriented_triangle_set(out.triangles), oriented_triangle_set(torus.triangles));
  }
}

TEST(GoldenFiles, PrefixSeedsDecodeTheirFirstAnchors) {
  // torus-levels-prefix-10: chunk 0 (4) and 6 of level 1's 8 anchors;
  // torus-prefix-5: the first 5 anchors of torus-full, in its first 4 chunks.
  struct Prefix {
    const char* name;
    const char* whole;
    int anchors, chunks;
  };
  for (const Prefix& p : {Prefix{"torus-levels-prefix-10", "torus-levels", 10, 2},
                          Prefix{"torus-prefix-5", "torus-full", 5, 4}}) {
    const std::string bytes = seed_bytes(p.name);
    ASSERT_EQ(static_cast<uint8_t>(bytes[0]) >> 2, p.anchors) << p.name;
    const std::vector<uint8_t> file(bytes.begin() + 1, bytes.end());
    EXPECT_EQ(file, seed(p.whole)) << p.name;
    DecodeOptions options;
    options.max_anchors = p.anchors;
    Mesh out;
    DecodeStats ds;
    ASSERT_TRUE(decode_mesh(file.data(), file.size(), options, &out, &ds).ok()) << p.name;
    EXPECT_EQ(ds.anchors, p.anchors) << p.name;
    EXPECT_EQ(ds.chunks, p.chunks) << p.name;
    EXPECT_FALSE(ds.truncated) << p.name;
  }
}

// Every seed, with and without each option bit, through the fuzzer's checks.
TEST(GoldenFiles, SeedsPassTheFuzzersChecks) {
  const Mesh torus = gab_fuzz::seed_torus();
  DIR* d = opendir(kCorpus.c_str());
  ASSERT_NE(d, nullptr);
  int seen = 0;
  while (dirent* e = readdir(d)) {
    if (e->d_name[0] == '.') continue;
    ++seen;
    std::string bytes;
    ASSERT_TRUE(read_file(kCorpus + "/" + e->d_name, &bytes).ok());
    const std::vector<uint8_t> file(bytes.begin() + 1, bytes.end());
    DecodeOptions options;
    options.connectivity = (bytes[0] & 1) ? &torus : nullptr;
    options.max_anchors = (bytes[0] & 2) ? static_cast<uint8_t>(bytes[0]) >> 2 : -1;
    Mesh out;
    DecodeStats ds;
    const Status s = decode_mesh(file.data(), file.size(), options, &out, &ds);
    ASSERT_TRUE(s.ok()) << e->d_name << ": " << s.message();
    for (double x : out.positions) ASSERT_TRUE(std::isfinite(x)) << e->d_name;
  }
  closedir(d);
  EXPECT_EQ(seen, static_cast<int>(goldens().size()) + 6);  // and the six prefixes
}

}  // namespace
}  // namespace gab
