// The vertex order block: any permutation round-trips over any triangle
// list; a coherent numbering costs a small part of log2(n!) bits, an
// arbitrary one no more than about that; the traversal's own numbering
// costs almost nothing; damaged blocks are errors or still permutations.
#include "connectivity/order_coder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <vector>

#include "common/test_meshes.h"

namespace gab {
namespace {

double log2_factorial_bytes(int32_t n) { return std::lgamma(n + 1.0) / std::log(2.0) / 8; }

// The block for `original` over `triangles`, checked to decode back.
std::vector<uint8_t> round_trip(int32_t n, const std::vector<int32_t>& triangles,
                                const std::vector<int32_t>& original) {
  const std::vector<uint8_t> block = encode_vertex_order(n, triangles, original);
  std::vector<int32_t> decoded;
  const Status s = decode_vertex_order(block.data(), block.size(), n, triangles, &decoded);
  EXPECT_TRUE(s.ok()) << s.message();
  EXPECT_EQ(decoded, original);
  return block;
}

std::vector<int32_t> shuffled(int32_t n, uint32_t seed) {
  std::vector<int32_t> p(static_cast<size_t>(n));
  std::iota(p.begin(), p.end(), 0);
  std::shuffle(p.begin(), p.end(), std::mt19937(seed));
  return p;
}

// The triangles as a decoder that numbers input vertex original[k] as k
// sees them.
std::vector<int32_t> in_decoder_numbering(const std::vector<int32_t>& triangles, const std::vector<int32_t>& original) {
  std::vector<int32_t> k_of(original.size());
  for (size_t k = 0; k < original.size(); ++k) k_of[original[k]] = static_cast<int32_t>(k);
  std::vector<int32_t> out(triangles.size());
  for (size_t i = 0; i < triangles.size(); ++i) out[i] = k_of[triangles[i]];
  return out;
}

TEST(OrderCoderTest, ACoherentNumberingCostsLittle) {
  // A 60 x 40 grid numbered row by row, seen by a decoder that numbers it
  // in some other order (here a random one): the rows are found again.
  const Mesh grid = testing_util::grid(60, 40);
  const int32_t n = grid.num_vertices();
  const std::vector<int32_t> original = shuffled(n, 7);
  const std::vector<uint8_t> block = round_trip(n, in_decoder_numbering(grid.triangles, original), original);
  EXPECT_LT(block.size(), 0.05 * log2_factorial_bytes(n));
}

TEST(OrderCoderTest, AnArbitraryNumberingCostsAboutLog2NFactorial) {
  const Mesh torus = testing_util::torus(50, 30);
  const int32_t n = torus.num_vertices();
  // Input numbering random relative to the mesh (and to the decoder's).
  const std::vector<int32_t> scramble = shuffled(n, 11);
  std::vector<int32_t> triangles(torus.triangles.size());
  for (size_t i = 0; i < triangles.size(); ++i) triangles[i] = scramble[torus.triangles[i]];
  const std::vector<int32_t> original = shuffled(n, 12);
  const std::vector<uint8_t> block = round_trip(n, triangles, original);
  EXPECT_LE(block.size(), log2_factorial_bytes(n) + 8);  // the mode and the coder's flush
  EXPECT_GT(block.size(), 0.99 * log2_factorial_bytes(n));  // nothing to find: no miracle either
}

TEST(OrderCoderTest, TheTraversalsOwnNumberingCostsAByteOrSo) {
  const Mesh torus = testing_util::torus(30, 20);
  std::vector<int32_t> identity(static_cast<size_t>(torus.num_vertices()));
  std::iota(identity.begin(), identity.end(), 0);
  EXPECT_LE(round_trip(torus.num_vertices(), torus.triangles, identity).size(), 5u);
}

TEST(OrderCoderTest, AnyTriangleListAndAnyPermutationRoundTrip) {
  std::mt19937 rng(5);
  for (int trial = 0; trial < 300; ++trial) {
    int32_t n = 0;
    // Soups: isolated vertices, degenerate and duplicate triangles,
    // non-manifold edges.
    const std::vector<int32_t> triangles = testing_util::random_soup(&rng, 1, 30, 50, false, &n);
    round_trip(n, triangles, shuffled(n, static_cast<uint32_t>(trial)));
    if (HasFailure()) {
      ADD_FAILURE() << "trial " << trial;
      return;
    }
  }
  round_trip(1, {0, 0, 0}, {0});
  round_trip(4, {}, {2, 0, 3, 1});  // no triangles at all
}

TEST(OrderCoderTest, DamagedBlocksAreErrorsOrPermutations) {
  const Mesh grid = testing_util::grid(12, 10);
  const int32_t n = grid.num_vertices();
  const std::vector<int32_t> original = shuffled(n, 3);
  const std::vector<int32_t> triangles = in_decoder_numbering(grid.triangles, original);
  const std::vector<uint8_t> block = round_trip(n, triangles, original);
  std::vector<int32_t> decoded;
  Status s = decode_vertex_order(block.data(), block.size() - 1, n, triangles, &decoded);
  EXPECT_EQ(s.code(), StatusCode::kParseError);
  std::vector<uint8_t> longer = block;
  longer.push_back(0);
  s = decode_vertex_order(longer.data(), longer.size(), n, triangles, &decoded);
  EXPECT_EQ(s.message(), "vertex order: trailing bytes");
  const uint8_t unknown_mode[] = {0xff, 0xff, 0xff, 0xff, 0xff};
  s = decode_vertex_order(unknown_mode, sizeof unknown_mode, n, triangles, &decoded);
  EXPECT_EQ(s.code(), StatusCode::kParseError);
  std::mt19937 rng(9);
  int ok = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    std::vector<uint8_t> bad = block;
    bad[rng() % bad.size()] ^= static_cast<uint8_t>(1 + rng() % 255);
    s = decode_vertex_order(bad.data(), bad.size(), n, triangles, &decoded);
    if (!s.ok()) {
      ASSERT_EQ(s.code(), StatusCode::kParseError) << s.message();
      continue;
    }
    ++ok;
    std::vector<int32_t> sorted = decoded;
    std::sort(sorted.begin(), sorted.end());
    for (int32_t i = 0; i < n; ++i) ASSERT_EQ(sorted[i], i) << "not a permutation, trial " << trial;
  }
  EXPECT_LT(ok, 2000);  // most damage is caught
}

}  // namespace
}  // namespace gab
