// The relaxed geometry-aware reconstruction (greedy selection: the codec,
// tests/codec/pipeline/greedy_selection_test.cpp).
#include <gtest/gtest.h>

#include <cmath>

#include "gab/mesh/edge_graph.h"
#include "gab/mesh/relaxed_reconstruction.h"
#include "gab/mesh/subdivide.h"

namespace gab {
namespace {

// A bumpy closed surface: an octahedron subdivided `levels` times, pushed
// onto a sphere with radial bumps.
Mesh bumpy_sphere(int levels) {
  Mesh m;
  m.positions = {1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1};
  m.triangles = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};
  m = subdivide_midpoint(m, levels);
  for (int32_t v = 0; v < m.num_vertices(); ++v) {
    double* p = &m.positions[3 * static_cast<size_t>(v)];
    const double r = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    const double bump = 1.0 + 0.15 * std::sin(5 * p[0] / r) * std::cos(3 * p[1] / r);
    for (int k = 0; k < 3; ++k) p[k] *= bump / r;
  }
  return m;
}

std::vector<double> coefficients(const Mesh& m, const std::vector<int32_t>& anchors) {
  std::vector<double> c;
  for (int32_t a : anchors)
    for (int k = 0; k < 3; ++k) c.push_back(m.positions[3 * static_cast<size_t>(a) + k]);
  return c;
}

TEST(RelaxedReconstructionTest, UpdatedEqualsFreshFactorization) {
  const Mesh m = bumpy_sphere(3);
  const EdgeGraph g = build_edge_graph(m);
  const std::vector<int32_t> first = {0, 1, 2, 3, 4, 5}, more = {10, 50, 77, 120, 200, 31, 9, 150, 8, 99};
  RelaxedReconstruction updated, fresh;
  ASSERT_TRUE(updated.init(g, 3.0, first, coefficients(m, first)).ok());
  ASSERT_TRUE(updated.add_anchors(more, coefficients(m, more)).ok());
  std::vector<int32_t> all = first;
  all.insert(all.end(), more.begin(), more.end());
  ASSERT_TRUE(fresh.init(g, 3.0, all, coefficients(m, all)).ok());
  std::vector<double> a, b;
  ASSERT_TRUE(updated.reconstruct(&a).ok());
  ASSERT_TRUE(fresh.reconstruct(&b).ok());
  ASSERT_EQ(a.size(), b.size());
  for (size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], 1e-11);
  EXPECT_EQ(updated.num_anchors(), 16);
}

TEST(RelaxedReconstructionTest, RefactoringAndCheapestAgreeWithUpdates) {
  const Mesh m = bumpy_sphere(3);
  const EdgeGraph g = build_edge_graph(m);
  const std::vector<int32_t> first = {0, 1, 2, 3, 4, 5}, more = {10, 50, 77, 120, 200, 31, 9, 150, 8, 99};
  RelaxedReconstruction updated, refactored, cheapest;
  for (RelaxedReconstruction* r : {&updated, &refactored, &cheapest}) {
    ASSERT_TRUE(r->init(g, 3.0, first, coefficients(m, first)).ok());
  }
  ASSERT_TRUE(updated.add_anchors(more, coefficients(m, more)).ok());
  ASSERT_TRUE(refactored.add_anchors_refactoring(more, coefficients(m, more)).ok());
  ASSERT_TRUE(cheapest.add_anchors_cheapest(more, coefficients(m, more)).ok());
  std::vector<double> a, b, c;
  ASSERT_TRUE(updated.reconstruct(&a).ok());
  ASSERT_TRUE(refactored.reconstruct(&b).ok());
  ASSERT_TRUE(cheapest.reconstruct(&c).ok());
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_NEAR(a[i], b[i], 1e-11);
    EXPECT_NEAR(a[i], c[i], 1e-11);
  }
  EXPECT_EQ(refactored.num_anchors(), 16);
  EXPECT_TRUE(refactored.is_anchor(150));
  // Refactoring refuses what updates refuse.
  EXPECT_EQ(refactored.add_anchors_refactoring({150}, coefficients(m, {150})).message(),
            "vertex 150 is already an anchor");
}

TEST(RelaxedReconstructionTest, SetCoefficientsEqualsAFreshStart) {
  const Mesh m = bumpy_sphere(3);
  const EdgeGraph g = build_edge_graph(m);
  const std::vector<int32_t> anchors = {0, 1, 2, 3, 4, 5, 60, 90};
  std::vector<double> c = coefficients(m, anchors), moved = c;
  for (size_t i = 9; i < moved.size(); ++i) moved[i] += 0.01 * static_cast<double>(i);
  RelaxedReconstruction changed, fresh;
  ASSERT_TRUE(changed.init(g, 3.0, anchors, c).ok());
  ASSERT_TRUE(changed.set_coefficients(3, std::vector<double>(moved.begin() + 9, moved.end())).ok());
  ASSERT_TRUE(fresh.init(g, 3.0, anchors, moved).ok());
  EXPECT_EQ(changed.coefficients(), moved);
  std::vector<double> a, b;
  ASSERT_TRUE(changed.reconstruct(&a).ok());
  ASSERT_TRUE(fresh.reconstruct(&b).ok());
  for (size_t i = 0; i < a.size(); ++i) EXPECT_NEAR(a[i], b[i], 1e-12);
  EXPECT_EQ(changed.set_coefficients(9, {}).message(), "set_coefficients: need 3 coefficients per anchor from 9 on");
}

TEST(RelaxedReconstructionTest, UpdateCostRatioGrowsWithTheAnchors) {
  const Mesh m = bumpy_sphere(4);
  const EdgeGraph g = build_edge_graph(m);
  RelaxedReconstruction r;
  const std::vector<int32_t> first = {0, 1, 2, 3, 4, 5};
  ASSERT_TRUE(r.init(g, 3.0, first, coefficients(m, first)).ok());
  std::vector<int32_t> few = {100}, many;
  for (int32_t v = 6; v < m.num_vertices(); v += 2) many.push_back(v);
  const double one = r.update_cost_ratio(few), all = r.update_cost_ratio(many);
  EXPECT_GT(one, 0.0);
  EXPECT_LT(one, 1.0);   // one anchor: update
  EXPECT_GT(all, 1.0);   // half the vertices: refactor
  EXPECT_NEAR(r.update_cost_ratio({100, 100}), 2 * one, 1e-12 * one);
}

TEST(RelaxedReconstructionTest, ZeroCoordinateStaysExactlyZero) {
  // Every anchor has z = 0, so the minimizer's z is exactly 0 everywhere.
  Mesh m = bumpy_sphere(2);
  for (int32_t v = 0; v < m.num_vertices(); ++v) m.positions[3 * static_cast<size_t>(v) + 2] = 0.0;
  const EdgeGraph g = build_edge_graph(m);
  RelaxedReconstruction rec;
  const std::vector<int32_t> anchors = {0, 7, 33, 60};
  ASSERT_TRUE(rec.init(g, 1.0, anchors, coefficients(m, anchors)).ok());
  std::vector<double> x;
  ASSERT_TRUE(rec.reconstruct(&x).ok());
  for (int32_t v = 0; v < m.num_vertices(); ++v) EXPECT_EQ(x[3 * static_cast<size_t>(v) + 2], 0.0);
}

TEST(RelaxedReconstructionTest, HeavyAnchorsEverywhereReproduceTheShape) {
  const Mesh m = bumpy_sphere(2);
  const EdgeGraph g = build_edge_graph(m);
  std::vector<int32_t> all(m.num_vertices());
  for (int32_t v = 0; v < m.num_vertices(); ++v) all[v] = v;
  RelaxedReconstruction rec;
  ASSERT_TRUE(rec.init(g, 1000.0, all, coefficients(m, all)).ok());
  std::vector<double> x;
  ASSERT_TRUE(rec.reconstruct(&x).ok());
  for (size_t i = 0; i < x.size(); ++i) EXPECT_NEAR(x[i], m.positions[i], 1e-4);
}

TEST(RelaxedReconstructionTest, ClearErrors) {
  Mesh m = bumpy_sphere(1);
  // An extra isolated vertex: a component of its own.
  m.positions.insert(m.positions.end(), {5.0, 5.0, 5.0});
  const EdgeGraph g = build_edge_graph(m);
  const int32_t isolated = m.num_vertices() - 1;
  RelaxedReconstruction rec;
  EXPECT_EQ(rec.init(g, 1.0, {0}, coefficients(m, {0})).message(),
            "the connected component of vertex " + std::to_string(isolated) + " has no anchor (every component needs one)");
  EXPECT_EQ(rec.init(g, 0.0, {0, isolated}, coefficients(m, {0, isolated})).message(),
            "anchor weight must be positive and finite");
  EXPECT_EQ(rec.init(g, 1.0, {0, isolated}, {1.0}).message(), "need 3 coefficients per anchor: got 1 for 2 anchors");
  ASSERT_TRUE(rec.init(g, 1.0, {0, isolated}, coefficients(m, {0, isolated})).ok());
  EXPECT_EQ(rec.add_anchors({0}, coefficients(m, {0})).message(), "vertex 0 is already an anchor");
  EXPECT_EQ(rec.add_anchors({3, 3}, coefficients(m, {3, 3})).message(), "anchor 3 given twice");
  EXPECT_EQ(rec.add_anchors({-1}, {0, 0, 0}).message(), "anchor -1 is not a vertex (n = " + std::to_string(m.num_vertices()) + ")");
  // A failed call changes nothing: 3 can still be added.
  EXPECT_TRUE(rec.add_anchors({3}, coefficients(m, {3})).ok());
  EXPECT_EQ(rec.num_anchors(), 3);
}

}  // namespace
}  // namespace gab
