#include "gab/mesh/normal_matrix.h"

#include <gtest/gtest.h>

#include <cstring>

#include "gab/mesh/edge_graph.h"
#include "mesh_test_util.h"

namespace gab {
namespace {

// Two disjoint pieces: a square split in two triangles, and a lone triangle,
// plus an isolated vertex 7.
Mesh two_pieces() {
  Mesh m;
  m.positions = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 5, 5, 5, 6, 5, 5, 5, 6, 5, 9, 9, 9};
  m.triangles = {0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 4, 5 /* degenerate */};
  return m;
}

TEST(EdgeGraphTest, DeduplicatedSortedNoSelfLoops) {
  const EdgeGraph g = build_edge_graph(two_pieces());
  EXPECT_EQ(g.num_vertices(), 8);
  EXPECT_EQ(g.offsets, (std::vector<int32_t>{0, 3, 5, 8, 10, 12, 14, 16, 16}));
  EXPECT_EQ(std::vector<int32_t>(g.neighbors.begin(), g.neighbors.begin() + 3), (std::vector<int32_t>{1, 2, 3}));
  int32_t count = 0;
  const std::vector<int32_t> comp = connected_components(g, &count);
  EXPECT_EQ(count, 3);
  EXPECT_EQ(comp, (std::vector<int32_t>{0, 0, 0, 0, 1, 1, 1, 2}));
}

TEST(NormalMatrixTest, EqualsDenseLaplacianSquaredPlusAnchors) {
  const Mesh mesh = two_pieces();
  const EdgeGraph g = build_edge_graph(mesh);
  const int32_t n = g.num_vertices();
  const std::vector<int32_t> anchors = {1, 5, 7};
  CscMatrix m;
  ASSERT_TRUE(assemble_normal_matrix(g, anchors, 3.0, &m).ok());
  std::vector<double> l(n * n, 0.0), expect(n * n, 0.0);
  for (int32_t v = 0; v < n; ++v) {
    l[v * n + v] = g.degree(v);
    for (int32_t p = g.offsets[v]; p < g.offsets[v + 1]; ++p) l[v * n + g.neighbors[p]] = -1.0;
  }
  for (int32_t i = 0; i < n; ++i)
    for (int32_t j = 0; j < n; ++j)
      for (int32_t k = 0; k < n; ++k) expect[i * n + j] += l[k * n + i] * l[k * n + j];
  for (int32_t a : anchors) expect[a * n + a] += 9.0;
  std::vector<double> got(n * n, 0.0);
  for (int32_t j = 0; j < n; ++j) {
    EXPECT_EQ(m.rowind[m.colptr[j]], j) << "diagonal always present";
    for (int32_t p = m.colptr[j]; p < m.colptr[j + 1]; ++p) got[m.rowind[p] * n + j] = m.values[p];
  }
  for (int32_t i = 0; i < n; ++i)
    for (int32_t j = 0; j <= i; ++j) EXPECT_EQ(got[i * n + j], expect[i * n + j]) << i << "," << j;
}

TEST(NormalMatrixTest, TwoThreadsAssembleTheSameBits) {
  // Large enough (20,800 vertices) for the second thread to take part.
  const Mesh mesh = testing_util::grid(160, 130);
  const EdgeGraph g = build_edge_graph(mesh);
  const std::vector<int32_t> anchors = benchmark_anchors(g, 300);
  CscMatrix one, two;
  ASSERT_TRUE(assemble_normal_matrix(g, anchors, 100.0, &one, 1).ok());
  ASSERT_TRUE(assemble_normal_matrix(g, anchors, 100.0, &two, 2).ok());
  EXPECT_EQ(one.colptr, two.colptr);
  EXPECT_EQ(one.rowind, two.rowind);
  ASSERT_EQ(one.values.size(), two.values.size());
  EXPECT_EQ(std::memcmp(one.values.data(), two.values.data(), sizeof(double) * one.values.size()), 0);
  EXPECT_TRUE(check_csc(two).ok());
}

TEST(NormalMatrixTest, RejectsBadAnchors) {
  const EdgeGraph g = build_edge_graph(two_pieces());
  CscMatrix m;
  EXPECT_EQ(assemble_normal_matrix(g, {8}, 1.0, &m).message(), "anchor 8 is not a vertex (n = 8)");
  EXPECT_EQ(assemble_normal_matrix(g, {2, 2}, 1.0, &m).message(), "anchor 2 given twice");
}

TEST(BenchmarkAnchorsTest, SpreadThenOnePerUncoveredComponent) {
  const EdgeGraph g = build_edge_graph(two_pieces());
  // k0 = 2: vertices 0 and 4 (floor(j*8/2)); component {7} gets vertex 7.
  EXPECT_EQ(benchmark_anchors(g, 2), (std::vector<int32_t>{0, 4, 7}));
  // k0 = 1: vertex 0; components {4,5,6} and {7} get their smallest.
  EXPECT_EQ(benchmark_anchors(g, 1), (std::vector<int32_t>{0, 4, 7}));
  // k0 > n: duplicates of floor(j n / k0) are dropped.
  EXPECT_EQ(benchmark_anchors(g, 16).size(), 8u);
}

TEST(NormalMatrixTest, BenchmarkUpdateSequenceFollowsTheRule) {
  // n = 10: t * 2654435761 mod 10 = t mod 10 (the multiplier ends in 1), so
  // the rule visits 1, 2, 3, ... skipping the initial anchors 0, 2 and 5.
  EXPECT_EQ(benchmark_update_sequence(10, {0, 2, 5}, 4), (std::vector<int32_t>{1, 3, 4, 6}));
  // Never more than the free vertices, each once.
  EXPECT_EQ(benchmark_update_sequence(10, {0, 2, 5, 2}, 100), (std::vector<int32_t>{1, 3, 4, 6, 7, 8, 9}));
}

}  // namespace
}  // namespace gab
