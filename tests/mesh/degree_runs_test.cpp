// DegreeRuns: a block's kept vertices, each visited once, grouped by degree
// with the degree known at compile time where it has a loop of its own.
#include "degree_runs.h"

#include <gtest/gtest.h>

#include <vector>

#include "common/test_meshes.h"
#include "gab/mesh/edge_graph.h"

namespace gab {
namespace {

TEST(DegreeRunsTest, EachKeptVertexOnceInItsBlockByDegree) {
  // A bumpy torus (degree 6 everywhere) with a fan glued on: degrees from
  // 2 to past kHighest, in blocks of 37 vertices (the last one short).
  Mesh m = testing_util::bumpy_torus(12, 8);
  const int32_t hub = m.num_vertices();
  m.positions.insert(m.positions.end(), {0, 0, 5});
  for (int32_t i = 0; i < 12; ++i) m.triangles.insert(m.triangles.end(), {hub, i, i + 1});
  const EdgeGraph g = build_edge_graph(m);
  const int32_t n = g.num_vertices(), block = 37;
  auto keep = [](int32_t v) { return v % 5 != 2; };
  DegreeRuns runs;
  runs.resize(n, block);
  for (int32_t b = 0; b * block < n; ++b) runs.fill(g, b, b * block, std::min(n, (b + 1) * block), keep);
  std::vector<int> seen(n, 0);
  int32_t unknown = 0;
  for (int32_t b = 0; b * block < n; ++b) {
    int32_t last_degree = 0, last_vertex = -1;
    runs.visit(b, [&](auto degree, int32_t v) {
      constexpr int32_t kDegree = decltype(degree)::value;
      const int32_t actual = g.offsets[v + 1] - g.offsets[v];
      EXPECT_GE(v, b * block);
      EXPECT_LT(v, (b + 1) * block);
      if (kDegree == 0) {
        ++unknown;
        EXPECT_TRUE(actual < DegreeRuns::kLowest || actual > DegreeRuns::kHighest) << v;
      } else {
        EXPECT_EQ(kDegree, actual) << v;
      }
      // Groups in increasing degree (the others last), vertices increasing in each.
      const int32_t group = kDegree == 0 ? 1000 : kDegree;
      EXPECT_GE(group, last_degree);
      if (group == last_degree) {
        EXPECT_GT(v, last_vertex);
      }
      last_degree = group;
      last_vertex = v;
      ++seen[v];
    });
  }
  for (int32_t v = 0; v < n; ++v) EXPECT_EQ(seen[v], keep(v) ? 1 : 0) << v;
  EXPECT_GT(unknown, 0);  // the hub (degree 13), and the fan's rim ends
}

}  // namespace
}  // namespace gab
