// Golden .gab files pin the format: the fuzzer seeds in tests/fuzz/corpus/gab
// (a leading options byte, then a version-1 file made by `gab compress` from
// gab_fuzz::seed_torus) must keep decoding to the same shapes, and a fresh
// encoding must keep writing the same header. A deliberate format change
// bumps kGabVersion and regenerates the seeds (tests/fuzz/make_gab_seeds.sh);
// a new flag adds seeds beside the old ones (bit 1: torus-refined; bit 2,
// the level layout: torus-levels*; bit 3: torus-reordered; bit 4:
// torus-*ordered-vK for each valence coder version K; bit 5, the detail
// chunk: torus-detail*, each version of the chunk; header byte 11, the
// ordering: torus-nd).
#include <dirent.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

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

const std::string kCorpus = [] {
  const std::string here = __FILE__;  // .../tests/codec/pipeline/golden_file_test.cpp
  return here.substr(0, here.rfind("/codec/")) + "/fuzz/corpus/gab";
}();

std::vector<uint8_t> seed(const std::string& name) {
  std::string bytes;
  EXPECT_TRUE(read_file(kCorpus + "/" + name, &bytes).ok()) << name;
  return std::vector<uint8_t>(bytes.begin() + (bytes.empty() ? 0 : 1), bytes.end());
}

struct Golden {
  const char* name;
  bool geometry_only;
  int bits, anchors, chunks;
  double rms_rel;  // of the decoded shape against seed_torus
};

TEST(GoldenFiles, SeedsDecodeToTheirPinnedShapes) {
  const Mesh torus = gab_fuzz::seed_torus();
  const Golden goldens[] = {
      {"torus-full", false, 12, 20, 8, 0.0226},
      {"torus-geometry-only", true, 8, 12, 5, 0.0355},
      {"torus-coarse", false, 6, 37, 7, 0.00989},
      {"torus-refined", false, 12, 16, 6, 0.0242},  // flag bit 1: the refinement applied
      {"torus-levels", false, 12, 40, 5, 0.00830},  // flag bit 2: chunk 0 and 4 levels of 8, 8, 10, 10
      {"torus-levels-refined", false, 12, 24, 5, 0.01487},  // bits 1 and 2
  };
  for (const Golden& g : goldens) {
    const std::vector<uint8_t> file = seed(g.name);
    ASSERT_GE(file.size(), kGabHeaderBytes) << g.name;
    EXPECT_TRUE(std::equal(kGabMagic, kGabMagic + 8, file.begin())) << g.name;
    EXPECT_EQ(file[8], 1) << g.name << ": format version";
    const bool levels = std::string(g.name).find("levels") != std::string::npos;
    EXPECT_EQ((file[9] & kGabFlagLevels) != 0, levels) << g.name;
    DecodeOptions options;
    options.connectivity = g.geometry_only ? &torus : nullptr;
    Mesh out;
    DecodeStats ds;
    const Status s = decode_mesh(file.data(), file.size(), options, &out, &ds);
    ASSERT_TRUE(s.ok()) << g.name << ": " << s.message();
    EXPECT_EQ(out.triangles, torus.triangles) << g.name;
    EXPECT_EQ(ds.bits, g.bits) << g.name;
    EXPECT_EQ(ds.anchors, g.anchors) << g.name;
    EXPECT_EQ(ds.chunks, g.chunks) << g.name;
    EXPECT_NEAR(testing_util::relative_rms(torus, out), g.rms_rel, 5e-5) << g.name;
  }
}

// A fresh encoding's header against a seed's, byte for byte but for the
// flags, where the fresh one has `added` too (and so the header's checksum).
void expect_same_header(const std::vector<uint8_t>& fresh, const std::vector<uint8_t>& golden, uint8_t added) {
  ASSERT_GE(fresh.size(), kGabHeaderBytes);
  ASSERT_GE(golden.size(), kGabHeaderBytes);
  std::vector<uint8_t> expected(golden.begin(), golden.begin() + kGabHeaderBytes - 4);
  expected[9] |= added;
  EXPECT_EQ(std::vector<uint8_t>(fresh.begin(), fresh.begin() + kGabHeaderBytes - 4), expected);
}

TEST(GoldenFiles, ValenceSeedsDecodeToTheTorusInTheirNumbering) {
  // torus-reordered: flag bit 3 alone, the first --reorder (valence section
  // version 1, no version byte). torus-reordered-vK: bit 4, the versioned
  // valence section at version K, without the vertex order block (bit 3);
  // torus-ordered-v2 with it. A reordered file is numbered as its version's
  // traversal numbers the torus.
  const Mesh torus = gab_fuzz::seed_torus();
  struct Seed {
    const char* name;
    uint8_t flags;
    int version;  // 0: kept order, no traversal numbering to check against
    double rms_rel;
  };
  const uint8_t reordered = kGabFlagReordered | kGabFlagLevels, versioned = kGabFlagVersionedValence | kGabFlagLevels;
  for (const Seed& s : {Seed{"torus-reordered", reordered, 1, 0.0225855},
                        Seed{"torus-reordered-v1", reordered | versioned, 1, 0.0225855},
                        Seed{"torus-ordered-v2", versioned, 0, 0.0225855},
                        Seed{"torus-reordered-v2", reordered | versioned, 2, 0.0225883}}) {
    const std::vector<uint8_t> golden = seed(s.name);
    ASSERT_GE(golden.size(), kGabHeaderBytes) << s.name;
    EXPECT_EQ(golden[9], s.flags) << s.name;
    Mesh out;
    DecodeStats ds;
    const Status status = decode_mesh(golden.data(), golden.size(), DecodeOptions(), &out, &ds);
    ASSERT_TRUE(status.ok()) << s.name << ": " << status.message();
    EXPECT_EQ(ds.reordered, s.version > 0) << s.name;
    const Mesh expected =
        s.version > 0
            ? renumber_vertices(torus, encode_valence_section(torus.num_vertices(), torus.triangles, s.version).new_index)
            : torus;
    EXPECT_EQ(oriented_triangle_set(out.triangles), oriented_triangle_set(expected.triangles)) << s.name;
    EXPECT_NEAR(testing_util::relative_rms(expected, out), s.rms_rel, 5e-6) << s.name;
  }
}

TEST(GoldenFiles, TheLatestValenceSeedsAreWhatTheEncoderWrites) {
  EncodeOptions options;
  options.max_anchors = 20;
  options.chunk_growth = 1.5;
  EncodeStats es;
  EXPECT_EQ(testing_util::encode_or_die(gab_fuzz::seed_torus(), options, &es), seed("torus-ordered-v2"));
  options.reorder = true;
  EXPECT_EQ(testing_util::encode_or_die(gab_fuzz::seed_torus(), options, &es), seed("torus-reordered-v2"));
}

TEST(GoldenFiles, NestedDissectionSeedDecodesWithEitherOrdering) {
  // torus-nd: torus-ordered-v2's options with --ordering nd (header byte
  // 11 = 1). The same anchors, hence the same chunks; the shape solved from
  // them is the same up to rounding whichever ordering decodes it.
  const Mesh torus = gab_fuzz::seed_torus();
  const std::vector<uint8_t> golden = seed("torus-nd");
  ASSERT_GE(golden.size(), kGabHeaderBytes);
  EXPECT_EQ(golden[11], kGabOrderingNestedDissection);
  const std::vector<uint8_t> amd = seed("torus-ordered-v2");
  EXPECT_EQ(std::vector<uint8_t>(golden.begin() + kGabHeaderBytes, golden.end()),
            std::vector<uint8_t>(amd.begin() + kGabHeaderBytes, amd.end()));
  for (MatrixOrdering ordering : {MatrixOrdering::kAuto, MatrixOrdering::kAmd}) {
    DecodeOptions options;
    options.ordering = ordering;
    Mesh out;
    DecodeStats ds;
    const Status status = decode_mesh(golden.data(), golden.size(), options, &out, &ds);
    ASSERT_TRUE(status.ok()) << status.message();
    EXPECT_EQ(ds.ordering,
              ordering == MatrixOrdering::kAuto ? MatrixOrdering::kNestedDissection : MatrixOrdering::kAmd);
    EXPECT_EQ(ds.anchors, 20);
    EXPECT_EQ(ds.chunks, 4);
    EXPECT_EQ(oriented_triangle_set(out.triangles), oriented_triangle_set(torus.triangles));
    EXPECT_NEAR(testing_util::relative_rms(torus, out), 0.0225883, 5e-8);
  }
}

// FNV-1a over the bytes of the coordinates: a fingerprint of a shape.
uint64_t shape_fingerprint(const std::vector<double>& positions) {
  uint64_t h = 0xcbf29ce484222325ull;
  const uint8_t* bytes = reinterpret_cast<const uint8_t*>(positions.data());
  for (size_t i = 0; i < positions.size() * sizeof(double); ++i) h = (h ^ bytes[i]) * 0x100000001b3ull;
  return h;
}

TEST(GoldenFiles, DetailSeedsDecodeToTheirPinnedBits) {
  // The detail chunk, version 1. Its decoded coordinates do not depend on
  // the machine or SIMD level (detail_chunk.h), so they are pinned bit for
  // bit: a change of the predictions or the coding that a version-1 decoder
  // would misread fails here, and needs a new kDetailVersion with new seeds
  // beside these. A fresh encoding (whose search may improve) must decode
  // and meet the target.
  const Mesh torus = gab_fuzz::seed_torus();
  struct Seed {
    const char* name;
    bool geometry_only;
    uint64_t fingerprint;
  };
  for (const Seed& g : {Seed{"torus-detail", false, 0x2540888d23fdcf32ull},
                        Seed{"torus-detail-geometry-only", true, 0xeaaf70d2f9f2840full}}) {
    const std::vector<uint8_t> golden = seed(g.name);
    ASSERT_GE(golden.size(), kGabHeaderBytes) << g.name;
    EXPECT_NE(golden[9] & kGabFlagDetail, 0) << g.name;
    DecodeOptions decode;
    decode.connectivity = g.geometry_only ? &torus : nullptr;
    Mesh out;
    DecodeStats ds;
    const Status status = decode_mesh(golden.data(), golden.size(), decode, &out, &ds);
    ASSERT_TRUE(status.ok()) << g.name << ": " << status.message();
    EXPECT_TRUE(ds.detail) << g.name;
    EXPECT_EQ(oriented_triangle_set(out.triangles), oriented_triangle_set(torus.triangles)) << g.name;
    EXPECT_LE(testing_util::relative_rms(torus, out), 1e-4) << g.name;
    EXPECT_EQ(shape_fingerprint(out.positions), g.fingerprint) << g.name << std::hex << " 0x"
                                                                << shape_fingerprint(out.positions);
    EncodeOptions options;
    options.target_rms_rel = 1e-4;
    options.detail = DetailMode::kOn;
    options.geometry_only = g.geometry_only;
    EncodeStats es;
    const std::vector<uint8_t> fresh = testing_util::encode_or_die(torus, options, &es);
    ASSERT_TRUE(decode_mesh(fresh.data(), fresh.size(), decode, &out, &ds).ok()) << g.name;
    EXPECT_LE(testing_util::relative_rms(torus, out), 1e-4) << g.name;
  }
}

TEST(GoldenFiles, EncoderWritesThePinnedHeader) {
  EncodeOptions options;
  options.max_anchors = 20;
  options.chunk_growth = 1.5;
  options.layout = FileLayout::kSelectionOrder;  // what torus-full was written in
  EncodeStats es;
  const std::vector<uint8_t> fresh = testing_util::encode_or_die(gab_fuzz::seed_torus(), options, &es);
  const std::vector<uint8_t> golden = seed("torus-full");
  expect_same_header(fresh, golden, kGabFlagVersionedValence);
}

TEST(GoldenFiles, EncoderWritesThePinnedLevelHeader) {
  // torus-levels' options in make_gab_seeds.sh; the levels' sizes follow
  // from the counts alone.
  EncodeOptions options;
  options.max_anchors = 40;
  options.initial_anchors = 4;
  options.chunk_growth = 1.5;
  options.layout = FileLayout::kLevels;
  EncodeStats es;
  const std::vector<uint8_t> fresh = testing_util::encode_or_die(gab_fuzz::seed_torus(), options, &es);
  EXPECT_EQ(es.chunk_anchors, (std::vector<int32_t>{4, 8, 8, 10, 10}));
  const std::vector<uint8_t> golden = seed("torus-levels");
  expect_same_header(fresh, golden, kGabFlagVersionedValence);
}

TEST(GoldenFiles, LevelPrefixSeedDecodesItsFirstLevel) {
  std::string bytes;
  ASSERT_TRUE(read_file(kCorpus + "/torus-levels-prefix-10", &bytes).ok());
  ASSERT_EQ(static_cast<uint8_t>(bytes[0]) >> 2, 10);
  const std::vector<uint8_t> file(bytes.begin() + 1, bytes.end());
  DecodeOptions options;
  options.max_anchors = 10;  // chunk 0 (4) and 6 of level 1's 8
  Mesh out;
  DecodeStats ds;
  ASSERT_TRUE(decode_mesh(file.data(), file.size(), options, &out, &ds).ok());
  EXPECT_EQ(ds.anchors, 10);
  EXPECT_EQ(ds.chunks, 2);
  EXPECT_FALSE(ds.truncated);
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
  EXPECT_GE(seen, 4);
}

}  // namespace
}  // namespace gab
