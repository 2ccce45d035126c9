// The valence coder: every closed (or closed-up) mesh round-trips to the
// same oriented triangles over the numbering the encoder reports; the
// decoder refuses garbage without crashing. (Random soups go through the
// whole section: valence_section_test.)
#include "connectivity/valence_coder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include "common/test_meshes.h"
#include "gab/mesh/triangle_set.h"

namespace gab {
namespace {

// Encodes the closed-up cut of `triangles`, decodes, and checks the decoded
// triangles are the closed mesh's under the reported order; returns bytes.
size_t round_trip(int32_t n, const std::vector<int32_t>& triangles) {
  const ClosedMesh closed = close_boundaries(cut_to_manifold(n, triangles));
  RangeEncoder enc;
  std::vector<int32_t> order;
  encode_valences(closed, &enc, &order);
  const std::vector<uint8_t> bytes = enc.finish();
  RangeDecoder dec(bytes.data(), bytes.size());
  DecodedConnectivity out;
  const Status s = decode_valences(&dec, closed.num_vertices, static_cast<int64_t>(closed.triangles.size() / 3), &out);
  EXPECT_TRUE(s.ok()) << s.message();
  if (!s.ok()) return 0;
  EXPECT_EQ(dec.bytes_consumed(), bytes.size());
  EXPECT_EQ(out.num_vertices, static_cast<int32_t>(order.size()));
  // Every closed-mesh vertex with a triangle is numbered once.
  std::vector<int32_t> sorted = order;
  std::sort(sorted.begin(), sorted.end());
  EXPECT_TRUE(std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end());
  for (int32_t k = 0; k < out.num_vertices; ++k) EXPECT_EQ(out.dummy[k], closed.dummy[order[k]]);
  std::vector<int32_t> renamed = out.triangles;
  for (int32_t& v : renamed) v = order[v];
  EXPECT_EQ(oriented_triangle_set(renamed), oriented_triangle_set(closed.triangles));
  return bytes.size();
}

TEST(ValenceCoderTest, ClosedTorusRoundTrips) {
  const Mesh torus = testing_util::torus(12, 8);
  EXPECT_GT(round_trip(torus.num_vertices(), torus.triangles), 0u);
}

TEST(ValenceCoderTest, OpenGridRoundTripsThroughItsDummy) {
  const Mesh grid = testing_util::grid(7, 5);
  EXPECT_GT(round_trip(grid.num_vertices(), grid.triangles), 0u);
}

TEST(ValenceCoderTest, RegularMeshCostsLittle) {
  // A 40 x 40 torus: every valence is 6, so the stream costs under a bit
  // per vertex (an index list would take about 6 log2(n) = 64).
  const Mesh torus = testing_util::torus(40, 40);
  const size_t bytes = round_trip(torus.num_vertices(), torus.triangles);
  EXPECT_LT(bytes * 8, static_cast<size_t>(torus.num_vertices())) << bytes << " bytes";
}

TEST(ValenceCoderTest, PinchesCutsAndSeveralComponentsRoundTrip) {
  const std::vector<int32_t> pinched = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3, 0, 5, 4, 0, 4, 6, 0, 6, 5, 4, 5, 6};
  round_trip(7, pinched);
  round_trip(5, {0, 1, 2, 1, 0, 3, 0, 1, 4});   // three pages on one edge
  round_trip(4, {0, 1, 2, 0, 1, 3});            // disagreeing orientations
  round_trip(4, {0, 1, 2, 1, 0, 2});            // a two-triangle pillow
  round_trip(3, {0, 1, 2});                     // one triangle
}

TEST(ValenceCoderTest, ProperSoupsRoundTrip) {
  // Soups without degenerate triangles cut into many pinched, handled,
  // many-boundaried pieces: every event of the traversal occurs.
  std::mt19937 rng(7);
  for (int trial = 0; trial < 300 && !HasFailure(); ++trial) {
    int32_t n = 0;
    const std::vector<int32_t> t = testing_util::random_soup(&rng, 3, 40, 80, true, &n);
    round_trip(n, t);
    if (HasFailure()) ADD_FAILURE() << "trial " << trial;
  }
}

TEST(ValenceCoderTest, GarbageNeverCrashes) {
  std::mt19937 rng(5);
  for (int trial = 0; trial < 2000; ++trial) {
    std::vector<uint8_t> bytes(1 + rng() % 64);
    for (uint8_t& b : bytes) b = static_cast<uint8_t>(rng());
    RangeDecoder dec(bytes.data(), bytes.size());
    DecodedConnectivity out;
    const Status s = decode_valences(&dec, 100, 200, &out);
    if (s.ok()) {
      EXPECT_LE(out.num_vertices, 100);
      EXPECT_LE(out.triangles.size(), 600u);
    }
  }
}

}  // namespace
}  // namespace gab
