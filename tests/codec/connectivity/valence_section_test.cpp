// The valence section: any triangle list (non-manifold, degenerate,
// duplicate, isolated vertices, several components) decodes to the same
// oriented triangles after the reported renumbering; counts that disagree
// with the stream and damaged streams are errors.
#include "connectivity/valence_section.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "common/test_meshes.h"
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
  EXPECT_EQ(decode_valence_section(longer.data(), longer.size(), n, t, &out).message(), "connectivity: trailing bytes");
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

}  // namespace
}  // namespace gab
