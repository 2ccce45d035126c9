// The manifold cut: glued edges are exactly the two-triangle, opposite-
// direction ones; every vertex of the cut mesh is one fan; mapping copies
// back gives the input's oriented triangles; hand-made non-manifold cases
// get the copies they must.
#include "gab/mesh/manifold_cut.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <map>
#include <random>
#include <set>
#include <vector>

#include "mesh_test_util.h"

namespace gab {
namespace {

// The invariants every cut must hold, checked from scratch.
void expect_valid_cut(int32_t n, const std::vector<int32_t>& input, const ManifoldCut& cut) {
  const int32_t corners = static_cast<int32_t>(cut.triangles.size());
  ASSERT_EQ(cut.opposite.size(), cut.triangles.size());
  ASSERT_EQ(cut.source_triangle.size() * 3, cut.triangles.size());
  ASSERT_EQ(cut.num_vertices, n + static_cast<int32_t>(cut.copy_of.size()));
  auto original = [&](int32_t v) { return v < n ? v : cut.copy_of[v - n]; };

  // Every input triangle comes back, oriented and with its corners in order.
  std::vector<int32_t> back(input.size(), -1);
  for (size_t t = 0; t < cut.source_triangle.size(); ++t) {
    for (int i = 0; i < 3; ++i) back[3 * cut.source_triangle[t] + i] = original(cut.triangles[3 * t + i]);
  }
  for (size_t t = 0; t < cut.degenerate_source.size(); ++t) {
    for (int i = 0; i < 3; ++i) back[3 * cut.degenerate_source[t] + i] = cut.degenerate[3 * t + i];
  }
  EXPECT_EQ(back, input);

  // Gluing: an involution between half-edges running opposite ways, and an
  // undirected edge glued at most once.
  std::map<std::pair<int32_t, int32_t>, int> uses;  // by the input's vertices
  for (int32_t c = 0; c < corners; ++c) {
    const int32_t a = original(cut.triangles[c]), b = original(cut.triangles[next_corner(c)]);
    ++uses[{std::min(a, b), std::max(a, b)}];
  }
  for (int32_t c = 0; c < corners; ++c) {
    const int32_t o = cut.opposite[c];
    const int32_t a = original(cut.triangles[c]), b = original(cut.triangles[next_corner(c)]);
    if (o < 0) {
      EXPECT_EQ(o, -1);
      continue;
    }
    ASSERT_LT(o, corners);
    EXPECT_EQ(cut.opposite[o], c);
    EXPECT_EQ(cut.triangles[o], cut.triangles[next_corner(c)]);
    EXPECT_EQ(cut.triangles[next_corner(o)], cut.triangles[c]);
    EXPECT_EQ((uses[{std::min(a, b), std::max(a, b)}]), 2) << "a glued edge of more than two triangles";
  }
  // Each cut vertex's corners form one fan (connected by rotation), and
  // every vertex index below num_vertices that has a corner is used.
  std::vector<int32_t> fan(static_cast<size_t>(corners));
  for (int32_t c = 0; c < corners; ++c) fan[c] = c;
  // The fan's representative: a plain walk up the links (the engine's
  // union-find is its own; a test mesh is small).
  const auto fan_root = [&fan](int32_t c) {
    while (fan[c] != c) c = fan[c];
    return c;
  };
  for (int32_t c = 0; c < corners; ++c) {
    if (cut.opposite[c] >= 0) fan[fan_root(c)] = fan_root(next_corner(cut.opposite[c]));
  }
  std::map<int32_t, int32_t> fan_of_vertex;
  for (int32_t c = 0; c < corners; ++c) {
    const int32_t v = cut.triangles[c];
    ASSERT_GE(v, 0);
    ASSERT_LT(v, cut.num_vertices);
    const int32_t root = fan_root(c);
    const auto it = fan_of_vertex.emplace(v, root).first;
    EXPECT_EQ(fan_root(it->second), root) << "vertex " << v << " has two fans";
  }
  for (size_t k = 0; k < cut.copy_of.size(); ++k) EXPECT_TRUE(fan_of_vertex.count(n + static_cast<int32_t>(k)));
}

int32_t boundary_half_edges(const ManifoldCut& cut) {
  return static_cast<int32_t>(std::count(cut.opposite.begin(), cut.opposite.end(), -1));
}

TEST(ManifoldCutTest, ClosedTorusIsGluedEverywhereWithoutCopies) {
  const Mesh torus = testing_util::torus(8, 5);
  const ManifoldCut cut = cut_to_manifold(torus.num_vertices(), torus.triangles);
  expect_valid_cut(torus.num_vertices(), torus.triangles, cut);
  EXPECT_EQ(boundary_half_edges(cut), 0);
  EXPECT_TRUE(cut.copy_of.empty());
  EXPECT_EQ(cut.triangles, torus.triangles);
}

TEST(ManifoldCutTest, OpenGridKeepsItsBoundaryAndVertices) {
  const Mesh grid = testing_util::grid(4, 3);
  const ManifoldCut cut = cut_to_manifold(grid.num_vertices(), grid.triangles);
  expect_valid_cut(grid.num_vertices(), grid.triangles, cut);
  EXPECT_EQ(boundary_half_edges(cut), 2 * (4 + 3));
  EXPECT_TRUE(cut.copy_of.empty());
}

TEST(ManifoldCutTest, TwoTetrahedraPinchedAtAVertexGetOneCopy) {
  // Tetrahedron 0 1 2 3 and tetrahedron 0 4 5 6, sharing only vertex 0.
  const std::vector<int32_t> t = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3,
                                  0, 5, 4, 0, 4, 6, 0, 6, 5, 4, 5, 6};
  const ManifoldCut cut = cut_to_manifold(7, t);
  expect_valid_cut(7, t, cut);
  EXPECT_EQ(cut.copy_of, std::vector<int32_t>{0});
  EXPECT_EQ(boundary_half_edges(cut), 0);
  EXPECT_EQ(cut.triangles[12], 7);  // the second fan's corners take the copy
}

TEST(ManifoldCutTest, ThreePagesOnOneEdgeAreCutApart) {
  // Spine 0-1; pages with apexes 2, 3, 4.
  const std::vector<int32_t> t = {0, 1, 2, 1, 0, 3, 0, 1, 4};
  const ManifoldCut cut = cut_to_manifold(5, t);
  expect_valid_cut(5, t, cut);
  EXPECT_EQ(boundary_half_edges(cut), 9);
  // Each spine vertex: three fans, two copies, numbered by first corner:
  // corner 3 (vertex 1), 4 (0), 6 (0), 7 (1).
  EXPECT_EQ(cut.copy_of, (std::vector<int32_t>{1, 0, 0, 1}));
}

TEST(ManifoldCutTest, TwoTrianglesDisagreeingOnOrientationAreNotGlued) {
  const std::vector<int32_t> t = {0, 1, 2, 0, 1, 3};  // both run 0 -> 1
  const ManifoldCut cut = cut_to_manifold(4, t);
  expect_valid_cut(4, t, cut);
  EXPECT_EQ(boundary_half_edges(cut), 6);
  EXPECT_EQ(cut.copy_of, (std::vector<int32_t>{0, 1}));
}

TEST(ManifoldCutTest, MoebiusStripBecomesAnOrientedStrip) {
  // A strip of 5 quads whose ends are glued with a half twist.
  const int32_t k = 5;
  std::vector<int32_t> t;
  for (int32_t i = 0; i < k; ++i) {
    int32_t a = i, b = i + 1, c = k + 1 + i, d = k + 2 + i;  // a-b bottom, c-d top
    if (i == k - 1) {
      b = k + 1;  // the twist: bottom end meets the top start
      d = 0;
    }
    t.insert(t.end(), {a, b, d, a, d, c});
  }
  const int32_t n = 2 * k + 1;
  const ManifoldCut cut = cut_to_manifold(n, t);
  expect_valid_cut(n, t, cut);
  EXPECT_FALSE(cut.copy_of.empty());  // a one-sided surface cannot stay whole
}

TEST(ManifoldCutTest, DegenerateAndDuplicateTrianglesAreKept) {
  const std::vector<int32_t> t = {0, 1, 2, 2, 1, 3, 1, 1, 3, 0, 1, 2, 4, 4, 4};
  const ManifoldCut cut = cut_to_manifold(5, t);
  expect_valid_cut(5, t, cut);
  EXPECT_EQ(cut.degenerate, (std::vector<int32_t>{1, 1, 3, 4, 4, 4}));
  EXPECT_EQ(cut.degenerate_source, (std::vector<int32_t>{2, 4}));
  EXPECT_EQ(cut.source_triangle, (std::vector<int32_t>{0, 1, 3}));
  // The duplicate of 0 1 2 makes 0-1 and 2-0 edges of two same-way
  // triangles and 1-2 an edge of three: nothing is glued.
  EXPECT_EQ(boundary_half_edges(cut), 9);
}

TEST(ManifoldCutTest, RandomSoupsHoldEveryInvariant) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 200; ++trial) {
    int32_t n = 0;
    const std::vector<int32_t> t = testing_util::random_soup(&rng, 3, 14, 30, false, &n);
    const ManifoldCut cut = cut_to_manifold(n, t);
    expect_valid_cut(n, t, cut);
    if (HasFailure()) return;
  }
}

}  // namespace
}  // namespace gab
