// The valence section: any triangle list (non-manifold, degenerate,
// duplicate, isolated vertices, several components) decodes to the same
// oriented triangles after the reported renumbering; counts that disagree
// with the stream and damaged streams are errors.
#include "connectivity/valence_section.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include "common/test_meshes.h"
#include "connectivity/valence_coder.h"
#include "entropy/int_coder.h"
#include "gab/mesh/triangle_set.h"

namespace gab {
namespace {

void expect_round_trip(int32_t n, const std::vector<int32_t>& triangles) {
  const ValenceSection section = encode_valence_section(n, triangles);
  ASSERT_EQ(section.new_index.size(), static_cast<size_t>(n));
  std::vector<int32_t> sorted = section.new_index;
  std::sort(sorted.begin(), sorted.end());
  for (int32_t i = 0; i < n; ++i) ASSERT_EQ(sorted[i], i) << "new_index is not a permutation";
  std::vector<int32_t> decoded;
  const int32_t t = static_cast<int32_t>(triangles.size() / 3);
  const Status s = decode_valence_section(section.bytes.data(), section.bytes.size(), n, t, &decoded);
  ASSERT_TRUE(s.ok()) << s.message();
  std::vector<int32_t> renamed;
  for (int32_t v : triangles) renamed.push_back(section.new_index[v]);
  EXPECT_EQ(oriented_triangle_set(decoded), oriented_triangle_set(renamed));
}

TEST(ValenceSectionTest, MeshesOfEveryKindRoundTrip) {
  const Mesh torus = testing_util::torus(9, 7);
  expect_round_trip(torus.num_vertices(), torus.triangles);
  const Mesh grid = testing_util::grid(5, 4);
  expect_round_trip(grid.num_vertices(), grid.triangles);
  const Mesh bumpy = testing_util::bumpy_torus(30, 20);
  expect_round_trip(bumpy.num_vertices(), bumpy.triangles);
  // Two components, an isolated vertex (7), a degenerate and a duplicate
  // triangle, a pinched vertex.
  expect_round_trip(9, {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 8, 0, 5, 4, 1, 1, 2, 0, 1, 2});
  expect_round_trip(3, {0, 0, 0});  // only a degenerate triangle
}

TEST(ValenceSectionTest, RandomSoupsRoundTrip) {
  std::mt19937 rng(3);
  for (int trial = 0; trial < 300; ++trial) {
    int32_t n = 0;
    const std::vector<int32_t> t = testing_util::random_soup(&rng, 1, 20, 40, false, &n);
    expect_round_trip(n, t);
    if (HasFailure()) {
      ADD_FAILURE() << "trial " << trial;
      return;
    }
  }
}

TEST(ValenceSectionTest, WrongCountsAndDamageAreErrors) {
  const Mesh torus = testing_util::torus(9, 7);
  const ValenceSection section = encode_valence_section(torus.num_vertices(), torus.triangles);
  const int32_t n = torus.num_vertices(), t = torus.num_triangles();
  std::vector<int32_t> out;
  EXPECT_EQ(decode_valence_section(section.bytes.data(), section.bytes.size(), n, t + 1, &out).message(),
            "connectivity: triangle count disagrees with the header");
  EXPECT_EQ(decode_valence_section(section.bytes.data(), section.bytes.size(), n - 1, t, &out).message(),
            "connectivity: more vertices than the header says");
  EXPECT_FALSE(decode_valence_section(section.bytes.data(), section.bytes.size() - 1, n, t, &out).ok());
  std::vector<uint8_t> longer = section.bytes;
  longer.push_back(0);
  EXPECT_EQ(decode_valence_section(longer.data(), longer.size(), n, t, &out).message(),
            "connectivity: trailing bytes");
  // Every single-byte change decodes to an error or to some valid mesh.
  for (size_t i = 0; i < section.bytes.size(); ++i) {
    std::vector<uint8_t> bad = section.bytes;
    bad[i] ^= 0x5A;
    if (decode_valence_section(bad.data(), bad.size(), n, t, &out).ok()) {
      for (int32_t v : out) ASSERT_TRUE(v >= 0 && v < n);
      EXPECT_EQ(out.size(), 3u * t);
    }
  }
}

TEST(ValenceSectionTest, DamagedIrregularStreamsNeverCrash) {
  // Soups cut into many pieces exercise SPLIT, MERGE, dummies and stitches;
  // every byte flipped must decode to an error or to some valid mesh.
  std::mt19937 rng(21);
  for (int trial = 0; trial < 20; ++trial) {
    int32_t n = 0;
    const std::vector<int32_t> soup = testing_util::random_soup(&rng, 10, 60, 120, trial % 2 == 0, &n);
    const int32_t t = static_cast<int32_t>(soup.size() / 3);
    const ValenceSection section = encode_valence_section(n, soup);
    std::vector<int32_t> out;
    for (size_t i = 0; i < section.bytes.size(); ++i) {
      for (uint8_t flip : {0x01, 0x80, 0xFF}) {
        std::vector<uint8_t> bad = section.bytes;
        bad[i] ^= flip;
        const Status s = decode_valence_section(bad.data(), bad.size(), n, t, &out);
        if (s.ok()) {
          for (int32_t v : out) ASSERT_TRUE(v >= 0 && v < n);
          ASSERT_EQ(out.size(), 3u * t);
        } else {
          ASSERT_EQ(s.code(), StatusCode::kParseError) << s.message();
        }
      }
    }
  }
}

// The fingerprint of the sections over a fixed set of meshes: their total
// size and the FNV-1a hash of their concatenated bytes.
struct Fingerprint {
  size_t total = 0;
  uint64_t hash = 1469598103934665603ull;
};

Fingerprint fingerprint() {
  Fingerprint f;
  auto eat = [&](const std::vector<uint8_t>& bytes) {
    f.total += bytes.size();
    for (uint8_t b : bytes) f.hash = (f.hash ^ b) * 1099511628211ull;
  };
  const Mesh torus = testing_util::torus(12, 8);
  eat(encode_valence_section(torus.num_vertices(), torus.triangles).bytes);
  const Mesh grid = testing_util::grid(7, 5);
  eat(encode_valence_section(grid.num_vertices(), grid.triangles).bytes);
  std::mt19937 rng(11);
  for (int i = 0; i < 50; ++i) {
    int32_t n = 0;
    const std::vector<int32_t> t = testing_util::random_soup(&rng, 4, 30, 60, i % 2 == 0, &n);
    eat(encode_valence_section(n, t).bytes);
  }
  return f;
}

// The coder's bytes are what version-2 files hold: a change to them is a
// new format version (or a new connectivity coder in a reserved header byte).
TEST(ValenceSectionTest, TheBytesAreFrozen) {
  const Fingerprint f = fingerprint();
  EXPECT_EQ(f.total, 5543u);
  EXPECT_EQ(f.hash, 0xb049cecb260a0bdcull);
}

// A forged count is refused before anything is looped over: the header's
// triangles against the block's size, the degenerate triangles against the
// bytes left after the valences.
TEST(ValenceSectionTest, CountsBeyondTheBytesAreRefusedAtOnce) {
  const Mesh torus = testing_util::torus(9, 7);
  const ValenceSection section = encode_valence_section(torus.num_vertices(), torus.triangles);
  const size_t size = section.bytes.size();
  std::vector<int32_t> out;
  const int32_t too_many = static_cast<int32_t>(6 * max_decisions(size) + 1);
  Status s = decode_valence_section(section.bytes.data(), size, torus.num_vertices(), too_many, &out);
  EXPECT_EQ(s.code(), StatusCode::kParseError);
  EXPECT_EQ(s.message(), "connectivity: the header's " + std::to_string(too_many) +
                             " triangles are more than a block of " + std::to_string(size) + " bytes can describe");

  // One proper triangle and as many degenerate ones as the header may
  // declare for a stream this short, far more than its last bytes can hold
  // (a forged 115-byte file declaring 100M once cost 13.8 s and 1.6 GB
  // before it was refused).
  const uint32_t degenerate = static_cast<uint32_t>(2 * max_decisions(8));
  RangeEncoder enc;
  const ClosedMesh closed = close_boundaries(cut_to_manifold(3, {0, 1, 2}));
  std::vector<int32_t> order;
  encode_valences(closed, &enc, &order);
  UIntCoder stitch_count, degenerate_count;
  stitch_count.encode(&enc, 0);
  degenerate_count.encode(&enc, degenerate);
  const std::vector<uint8_t> forged = enc.finish();
  ASSERT_GE(forged.size(), 8u);
  ASSERT_LE(forged.size(), 64u);
  s = decode_valence_section(forged.data(), forged.size(), 3, static_cast<int32_t>(degenerate + 1), &out);
  EXPECT_EQ(s.code(), StatusCode::kParseError);
  EXPECT_NE(s.message().find(std::to_string(degenerate) + " degenerate triangles are more than the stream's last"),
            std::string::npos)
      << s.message();
}

}  // namespace
}  // namespace gab
