// The detail layer's walk (codec/src/detail/detail_topology.h): a maximum
// cardinality order over every vertex, and per step exactly the decoded
// neighbours and valid parallelograms, the earliest-decoded edge first, on
// clean meshes, random soups (non-manifold, degenerate, isolated vertices)
// and a fan that would make the lists quadratic.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
#include <tuple>

#include "common/test_meshes.h"
#include "detail/detail_topology.h"
#include "gab/mesh/edge_graph.h"

namespace gab {
namespace {

Mesh of_triangles(int32_t n, std::vector<int32_t> triangles) {
  Mesh m;
  m.positions.assign(3 * static_cast<size_t>(n), 0.0);
  m.triangles = std::move(triangles);
  return m;
}

// Checks every property of the walk against brute force; returns the steps
// with at least two parallelograms.
int check_walk(const Mesh& mesh) {
  const int32_t n = mesh.num_vertices();
  const EdgeGraph g = build_edge_graph(mesh);
  const DetailTopology topo = build_detail_topology(n, mesh.triangles, g);
  EXPECT_EQ(topo.order.size(), static_cast<size_t>(n));
  std::vector<int32_t> position(n, -1);
  for (size_t i = 0; i < topo.order.size(); ++i) {
    EXPECT_EQ(position[topo.order[i]], -1) << "vertex listed twice";
    position[topo.order[i]] = static_cast<int32_t>(i);
  }
  // Oriented triangles as (v, next, next-next) for each corner.
  std::set<std::tuple<int32_t, int32_t, int32_t>> corners;
  std::set<std::set<int32_t>> unoriented;
  for (size_t t = 0; t + 2 < mesh.triangles.size(); t += 3) {
    const int32_t a = mesh.triangles[t], b = mesh.triangles[t + 1], c = mesh.triangles[t + 2];
    corners.insert({a, b, c});
    corners.insert({b, c, a});
    corners.insert({c, a, b});
    unoriented.insert({a, b, c});
  }
  int rich = 0;
  std::vector<int32_t> count(n, 0);  // decoded neighbours so far
  std::vector<char> done(n, 0);
  for (size_t i = 0; i < topo.order.size(); ++i) {
    const int32_t v = topo.order[i];
    // Maximum cardinality: no unvisited vertex has more decoded neighbours;
    // with none anywhere, the smallest unvisited vertex starts a component.
    int32_t best = 0, smallest = -1;
    for (int32_t u = 0; u < n; ++u) {
      if (done[u]) continue;
      best = std::max(best, count[u]);
      if (smallest < 0) smallest = u;
    }
    EXPECT_EQ(count[v], best) << "step " << i;
    if (best == 0) {
      EXPECT_EQ(v, smallest) << "step " << i;
    }
    // Known neighbours: exactly the decoded ones, ascending.
    std::vector<int32_t> known;
    for (int32_t p = g.offsets[v]; p < g.offsets[v + 1]; ++p) {
      if (done[g.neighbors[p]]) known.push_back(g.neighbors[p]);
    }
    EXPECT_EQ(std::vector<int32_t>(topo.known.begin() + topo.known_offsets[i],
                                   topo.known.begin() + topo.known_offsets[i + 1]),
              known)
        << "step " << i;
    // Parallelograms: decoded, real triangles on both sides, the earliest first.
    const int32_t first = topo.parallelogram_offsets[i], last = topo.parallelogram_offsets[i + 1];
    EXPECT_LE(last - first, kMaxParallelograms);
    for (int32_t p = first; p < last; ++p) {
      const int32_t a = topo.parallelograms[3 * p], b = topo.parallelograms[3 * p + 1];
      const int32_t c = topo.parallelograms[3 * p + 2];
      EXPECT_TRUE(done[a] && done[b] && done[c]) << "step " << i;
      EXPECT_TRUE(corners.count({v, a, b})) << "step " << i;
      EXPECT_TRUE(unoriented.count({a, b, c})) << "step " << i;
      EXPECT_NE(c, v);
      EXPECT_LE(std::min(position[topo.parallelograms[3 * first]], position[topo.parallelograms[3 * first + 1]]),
                std::min(position[a], position[b]))
          << "step " << i;
    }
    rich += last - first >= 2 ? 1 : 0;
    done[v] = 1;
    for (int32_t p = g.offsets[v]; p < g.offsets[v + 1]; ++p) ++count[g.neighbors[p]];
  }
  return rich;
}

TEST(DetailTopology, TheWalkOnAClosedMeshFindsTwoParallelogramsMostly) {
  // (96% on igea; a small torus loses more to where its front closes.)
  const Mesh torus = testing_util::torus(24, 12);
  const int rich = check_walk(torus);
  EXPECT_GT(rich, torus.num_vertices() * 8 / 10);
}

TEST(DetailTopology, RandomSoupsGiveValidWalks) {
  std::mt19937 rng(7);
  for (int round = 0; round < 150; ++round) {
    int32_t n = 0;
    std::vector<int32_t> soup = testing_util::random_soup(&rng, 1, 30, 40, round % 2 == 0, &n);
    check_walk(of_triangles(n, std::move(soup)));
    if (HasFailure()) return;
  }
}

TEST(DetailTopology, ANonManifoldFanKeepsItsListsShort) {
  // 200 triangles on the edge 0-1, then a vertex seeing that edge from
  // every side: at most kMaxParallelograms each.
  std::vector<int32_t> t;
  for (int32_t k = 0; k < 200; ++k) t.insert(t.end(), {0, 1, 2 + k});
  t.insert(t.end(), {1, 0, 202});
  const Mesh fan = of_triangles(203, t);
  check_walk(fan);
  const EdgeGraph g = build_edge_graph(fan);
  const DetailTopology topo = build_detail_topology(203, fan.triangles, g);
  // 0, then 1, then 2..202 first in, first out: 202 comes last and sees 200 triangles across 1-0.
  ASSERT_EQ(topo.order.back(), 202);
  EXPECT_EQ(topo.parallelogram_offsets[203] - topo.parallelogram_offsets[202], kMaxParallelograms);
}

}  // namespace
}  // namespace gab
