// BFS hop distances and farthest-point sampling on the edge graph.
#include "gab/mesh/graph_distance.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "mesh_test_util.h"

namespace gab {
namespace {

TEST(BfsTest, GridDistancesAreManhattanLikeAndUnreachableIsMinusOne) {
  // On the split-square grid the diagonals (v, ur) are edges, so the hop
  // distance from (0, 0) to (i, j) is max(i, j).
  Mesh m = testing_util::grid(5, 4);
  m.positions.insert(m.positions.end(), {9, 9, 9});  // isolated vertex 30
  const EdgeGraph g = build_edge_graph(m);
  std::vector<int32_t> d;
  ASSERT_TRUE(bfs_distances(g, {0}, &d).ok());
  for (int j = 0; j <= 4; ++j)
    for (int i = 0; i <= 5; ++i) EXPECT_EQ(d[i + 6 * j], std::max(i, j)) << i << "," << j;
  EXPECT_EQ(d[30], -1);
  // Several sources: the nearest one counts.
  ASSERT_TRUE(bfs_distances(g, {0, 29, 29}, &d).ok());
  EXPECT_EQ(d[29], 0);
  EXPECT_EQ(d[5], 4);  // (5, 0): 5 from vertex 0, 4 from (5, 4)
  EXPECT_EQ(bfs_distances(g, {31}, &d).message(), "source 31 is not a vertex (n = 31)");
}

// Three components: the grid 0..29, a lone triangle 30..32, an isolated vertex 33.
EdgeGraph grid_triangle_and_point() {
  Mesh m = testing_util::grid(5, 4);
  m.positions.insert(m.positions.end(), {20, 0, 0, 21, 0, 0, 20, 1, 0, 40, 40, 40});
  m.triangles.insert(m.triangles.end(), {30, 31, 32});
  return build_edge_graph(m);
}

TEST(FarthestPointTest, CoversComponentsFirstThenSpreads) {
  const EdgeGraph g = grid_triangle_and_point();
  std::vector<int32_t> picked;
  ASSERT_TRUE(farthest_point_sampling(g, 6, {}, &picked).ok());
  // 0 first (nothing chosen: all infinitely far, smallest index), then the
  // smallest vertex of each component still without a pick, then the grid
  // grid vertex farthest from 0: (5, 0) = 5 and (5, 4) = 29 are both 5
  // hops away (diagonals are edges), and the tie goes to the smaller index.
  ASSERT_EQ(picked.size(), 6u);
  EXPECT_EQ(std::vector<int32_t>(picked.begin(), picked.begin() + 4), (std::vector<int32_t>{0, 30, 33, 5}));
  // The result is a deterministic function of the input.
  std::vector<int32_t> again;
  ASSERT_TRUE(farthest_point_sampling(g, 6, {}, &again).ok());
  EXPECT_EQ(again, picked);
}

TEST(FarthestPointTest, GreedyPropertyAndSeeds) {
  const Mesh m = testing_util::torus(30, 20);
  const EdgeGraph g = build_edge_graph(m);
  std::vector<int32_t> picked;
  ASSERT_TRUE(farthest_point_sampling(g, 40, {17, 250}, &picked).ok());
  ASSERT_EQ(picked.size(), 40u);
  EXPECT_EQ(picked[0], 17);
  EXPECT_EQ(picked[1], 250);
  // Each pick is at maximal distance from those before it (checked by BFS).
  for (size_t k = 2; k < picked.size(); ++k) {
    std::vector<int32_t> d;
    ASSERT_TRUE(bfs_distances(g, std::vector<int32_t>(picked.begin(), picked.begin() + k), &d).ok());
    const int32_t far = *std::max_element(d.begin(), d.end());
    EXPECT_EQ(d[picked[k]], far) << "pick " << k;
    EXPECT_EQ(std::find(d.begin(), d.end(), far) - d.begin(), picked[k]) << "ties go to the smallest index";
  }
  // Asking for more than n gives every vertex exactly once.
  ASSERT_TRUE(farthest_point_sampling(g, 100000, {}, &picked).ok());
  std::vector<int32_t> sorted = picked;
  std::sort(sorted.begin(), sorted.end());
  ASSERT_EQ(sorted.size(), static_cast<size_t>(g.num_vertices()));
  for (int32_t v = 0; v < g.num_vertices(); ++v) EXPECT_EQ(sorted[v], v);
  EXPECT_EQ(farthest_point_sampling(g, 3, {5, 5}, &picked).message(), "seed 5 given twice");
  EXPECT_EQ(farthest_point_sampling(g, 3, {-1}, &picked).message(), "seed -1 is not a vertex (n = 600)");
}

TEST(FarthestPointTest, TheSamplerTakenInPiecesMakesTheSamePicks) {
  // Three components (the later two picked in the scan for unreached
  // ones), with and without candidates, in pieces of every size from 1:
  // the one run's picks.
  const EdgeGraph g = grid_triangle_and_point();
  std::vector<int32_t> odd;
  for (int32_t v = 1; v < g.num_vertices(); v += 2) odd.push_back(v);
  const std::vector<int32_t>* none = nullptr;
  for (const std::vector<int32_t>* candidates : {none, static_cast<const std::vector<int32_t>*>(&odd)}) {
    std::vector<int32_t> whole;
    ASSERT_TRUE(farthest_point_sampling(g, 1000, {7, 12}, candidates, &whole).ok());
    EXPECT_EQ(whole.size(), candidates ? odd.size() + 1 : static_cast<size_t>(g.num_vertices()));  // 7 is odd
    for (int32_t piece = 1; piece <= 7; ++piece) {
      FarthestPointSampler sampler;
      ASSERT_TRUE(sampler.start(g, {7, 12}, candidates).ok());
      std::vector<int32_t> picked;
      while (sampler.next(piece, &picked) == piece) {
      }
      EXPECT_EQ(picked, whole) << "pieces of " << piece;
      EXPECT_EQ(sampler.next(5, &picked), 0);  // nothing left
    }
  }
  FarthestPointSampler sampler;
  EXPECT_EQ(sampler.start(g, {3, 3}, nullptr).message(), "seed 3 given twice");
}

// (hops << 32) | nearest of `chosen`, the fewest hops then the lowest
// index, by a search from each; kUnreached where none reaches.
std::vector<uint64_t> nearest_by_brute_force(const EdgeGraph& g, const std::vector<int32_t>& chosen) {
  std::vector<uint64_t> nearest(g.num_vertices(), FarthestPointSampler::kUnreached);
  for (int32_t c : chosen) {
    std::vector<int32_t> d;
    EXPECT_TRUE(bfs_distances(g, {c}, &d).ok());
    for (int32_t v = 0; v < g.num_vertices(); ++v) {
      if (d[v] >= 0) nearest[v] = std::min(nearest[v], (static_cast<uint64_t>(d[v]) << 32) | static_cast<uint64_t>(c));
    }
  }
  return nearest;
}

TEST(FarthestPointTest, TheSamplersNearestMapIsTheFewestHopsThenTheLowestChosen) {
  // A torus whose seeds tie often (many at once, spread evenly, so a
  // vertex is reached at the same hops from several: the lower wins even
  // when the higher reaches it first), then picks one by one; and the
  // three components, two of them unreached until their scan picks.
  const EdgeGraph torus = build_edge_graph(testing_util::torus(30, 20));
  std::vector<int32_t> seeds;
  for (int32_t v = 599; v >= 0; v -= 37) seeds.push_back(v);
  const EdgeGraph parts = grid_triangle_and_point();
  for (const auto& [g, start] : {std::make_pair(&torus, seeds), std::make_pair(&parts, std::vector<int32_t>{7})}) {
    FarthestPointSampler sampler;
    ASSERT_TRUE(sampler.start(*g, start, nullptr).ok());
    std::vector<int32_t> chosen;
    ASSERT_EQ(sampler.next(static_cast<int32_t>(start.size()), &chosen), static_cast<int32_t>(start.size()));
    EXPECT_EQ(sampler.nearest(), nearest_by_brute_force(*g, chosen));
    for (int pick = 0; pick < 30; ++pick) {
      ASSERT_EQ(sampler.next(1, &chosen), 1);
      ASSERT_EQ(sampler.nearest(), nearest_by_brute_force(*g, chosen)) << chosen.size() << " chosen";
    }
    // The lowest index decided often: vertices with another chosen vertex
    // as few hops away as their nearest.
    const std::vector<uint64_t>& nearest = sampler.nearest();
    int32_t ties = 0;
    for (int32_t c : chosen) {
      std::vector<int32_t> d;
      ASSERT_TRUE(bfs_distances(*g, {c}, &d).ok());
      for (int32_t v = 0; v < g->num_vertices(); ++v) {
        ties += d[v] >= 0 && static_cast<uint64_t>(d[v]) == nearest[v] >> 32 && (nearest[v] & 0xffffffffu) < static_cast<uint64_t>(c);
      }
    }
    EXPECT_GT(ties, g == &torus ? 100 : 0);
  }
}

}  // namespace
}  // namespace gab
