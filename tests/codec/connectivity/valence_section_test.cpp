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
#include "gab/mesh/triangle_set.h"

namespace gab {
namespace {

void expect_round_trip(int32_t n, const std::vector<int32_t>& triangles, int version) {
  const ValenceSection section = encode_valence_section(n, triangles, version);
  ASSERT_EQ(section.new_index.size(), static_cast<size_t>(n));
  std::vector<int32_t> sorted = section.new_index;
  std::sort(sorted.begin(), sorted.end());
  for (int32_t i = 0; i < n; ++i) ASSERT_EQ(sorted[i], i) << "new_index is not a permutation";
  std::vector<int32_t> decoded;
  const int32_t t = static_cast<int32_t>(triangles.size() / 3);
  const Status s = decode_valence_section(section.bytes.data(), section.bytes.size(), n, t, &decoded, version);
  ASSERT_TRUE(s.ok()) << s.message();
  std::vector<int32_t> renamed;
  for (int32_t v : triangles) renamed.push_back(section.new_index[v]);
  EXPECT_EQ(oriented_triangle_set(decoded), oriented_triangle_set(renamed));
}

// Every test runs every coder version.
class ValenceSectionTest : public ::testing::TestWithParam<int> {};

TEST_P(ValenceSectionTest, MeshesOfEveryKindRoundTrip) {
  const int version = GetParam();
  const Mesh torus = testing_util::torus(9, 7);
  expect_round_trip(torus.num_vertices(), torus.triangles, version);
  const Mesh grid = testing_util::grid(5, 4);
  expect_round_trip(grid.num_vertices(), grid.triangles, version);
  const Mesh bumpy = testing_util::bumpy_torus(30, 20);
  expect_round_trip(bumpy.num_vertices(), bumpy.triangles, version);
  // Two components, an isolated vertex (7), a degenerate and a duplicate
  // triangle, a pinched vertex.
  expect_round_trip(9, {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 8, 0, 5, 4, 1, 1, 2, 0, 1, 2}, version);
  expect_round_trip(3, {0, 0, 0}, version);  // only a degenerate triangle
}

TEST_P(ValenceSectionTest, RandomSoupsRoundTrip) {
  std::mt19937 rng(3);
  for (int trial = 0; trial < 300; ++trial) {
    int32_t n = 0;
    const std::vector<int32_t> t = testing_util::random_soup(&rng, 1, 20, 40, false, &n);
    expect_round_trip(n, t, GetParam());
    if (HasFailure()) {
      ADD_FAILURE() << "trial " << trial;
      return;
    }
  }
}

TEST_P(ValenceSectionTest, WrongCountsAndDamageAreErrors) {
  const int version = GetParam();
  const Mesh torus = testing_util::torus(9, 7);
  const ValenceSection section = encode_valence_section(torus.num_vertices(), torus.triangles, version);
  const int32_t n = torus.num_vertices(), t = torus.num_triangles();
  std::vector<int32_t> out;
  EXPECT_EQ(decode_valence_section(section.bytes.data(), section.bytes.size(), n, t + 1, &out, version).message(),
            "connectivity: triangle count disagrees with the header");
  EXPECT_EQ(decode_valence_section(section.bytes.data(), section.bytes.size(), n - 1, t, &out, version).message(),
            "connectivity: more vertices than the header says");
  EXPECT_FALSE(decode_valence_section(section.bytes.data(), section.bytes.size() - 1, n, t, &out, version).ok());
  std::vector<uint8_t> longer = section.bytes;
  longer.push_back(0);
  EXPECT_EQ(decode_valence_section(longer.data(), longer.size(), n, t, &out, version).message(),
            "connectivity: trailing bytes");
  // Every single-byte change decodes to an error or to some valid mesh.
  for (size_t i = 0; i < section.bytes.size(); ++i) {
    std::vector<uint8_t> bad = section.bytes;
    bad[i] ^= 0x5A;
    if (decode_valence_section(bad.data(), bad.size(), n, t, &out, version).ok()) {
      for (int32_t v : out) ASSERT_TRUE(v >= 0 && v < n);
      EXPECT_EQ(out.size(), 3u * t);
    }
  }
}

TEST_P(ValenceSectionTest, DamagedIrregularStreamsNeverCrash) {
  // Soups cut into many pieces exercise SPLIT, MERGE, dummies and stitches;
  // every byte flipped must decode to an error or to some valid mesh.
  const int version = GetParam();
  std::mt19937 rng(21);
  for (int trial = 0; trial < 20; ++trial) {
    int32_t n = 0;
    const std::vector<int32_t> soup = testing_util::random_soup(&rng, 10, 60, 120, trial % 2 == 0, &n);
    const int32_t t = static_cast<int32_t>(soup.size() / 3);
    const ValenceSection section = encode_valence_section(n, soup, version);
    std::vector<int32_t> out;
    for (size_t i = 0; i < section.bytes.size(); ++i) {
      for (uint8_t flip : {0x01, 0x80, 0xFF}) {
        std::vector<uint8_t> bad = section.bytes;
        bad[i] ^= flip;
        const Status s = decode_valence_section(bad.data(), bad.size(), n, t, &out, version);
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

INSTANTIATE_TEST_SUITE_P(Versions, ValenceSectionTest, ::testing::Range(1, kValenceVersionLatest + 1));

// The fingerprint of a version's sections over a fixed set of meshes: their
// total size and the FNV-1a hash of their concatenated bytes.
struct Fingerprint {
  size_t total = 0;
  uint64_t hash = 1469598103934665603ull;
};

Fingerprint fingerprint(int version) {
  Fingerprint f;
  auto eat = [&](const std::vector<uint8_t>& bytes) {
    f.total += bytes.size();
    for (uint8_t b : bytes) f.hash = (f.hash ^ b) * 1099511628211ull;
  };
  const Mesh torus = testing_util::torus(12, 8);
  eat(encode_valence_section(torus.num_vertices(), torus.triangles, version).bytes);
  const Mesh grid = testing_util::grid(7, 5);
  eat(encode_valence_section(grid.num_vertices(), grid.triangles, version).bytes);
  std::mt19937 rng(11);
  for (int i = 0; i < 50; ++i) {
    int32_t n = 0;
    const std::vector<int32_t> t = testing_util::random_soup(&rng, 4, 30, 60, i % 2 == 0, &n);
    eat(encode_valence_section(n, t, version).bytes);
  }
  return f;
}

// Version 1's bytes are what files written before version 2 hold: they must
// not change. The fingerprint was taken from the coder before version 2
// existed.
TEST(ValenceSectionVersionTest, VersionOneBytesAreFrozen) {
  const Fingerprint f = fingerprint(1);
  EXPECT_EQ(f.total, 6897u);
  EXPECT_EQ(f.hash, 0x8cf5e017db345647ull);
}

// Version 2's bytes, pinned the same way (once files hold them, a change
// to the coder is a version 3).
TEST(ValenceSectionVersionTest, VersionTwoBytesAreFrozen) {
  const Fingerprint f = fingerprint(2);
  EXPECT_EQ(f.total, 5543u);  // version 1: 6897 on the same input
  EXPECT_EQ(f.hash, 0xb049cecb260a0bdcull);
}

TEST(ValenceSectionVersionTest, UnknownVersionIsAParseError) {
  const Mesh torus = testing_util::torus(9, 7);
  const ValenceSection section = encode_valence_section(torus.num_vertices(), torus.triangles);
  std::vector<int32_t> out;
  const Status s = decode_valence_section(section.bytes.data(), section.bytes.size(), torus.num_vertices(),
                                          torus.num_triangles(), &out, kValenceVersionLatest + 1);
  EXPECT_EQ(s.code(), StatusCode::kParseError);
  EXPECT_EQ(s.message(), "connectivity: unknown valence coder version " + std::to_string(kValenceVersionLatest + 1));
}

}  // namespace
}  // namespace gab
