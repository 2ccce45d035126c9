// The interpolatory reconstruction and relaxed anchors on top of it, checked
// against the assembled L^T L, a dense solve of the combined system, and the
// relaxed basis's limit w -> infinity (the property behind the paper's
// Figure 4).
#include "gab/mesh/interpolatory_reconstruction.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "gab/mesh/graph_distance.h"
#include "gab/mesh/metrics.h"
#include "gab/mesh/normal_matrix.h"
#include "gab/mesh/relaxed_reconstruction.h"
#include "mesh_test_util.h"

namespace gab {
namespace {

std::vector<double> coefficients(const Mesh& m, const std::vector<int32_t>& anchors) {
  std::vector<double> c;
  for (int32_t a : anchors)
    for (int k = 0; k < 3; ++k) c.push_back(m.positions[3 * static_cast<size_t>(a) + k]);
  return c;
}

// A grid with a smooth height field, so all three coordinates carry shape.
Mesh wavy_grid(int nx, int ny) {
  Mesh m = testing_util::grid(nx, ny, 0.5);
  for (int32_t v = 0; v < m.num_vertices(); ++v) {
    double* p = &m.positions[3 * static_cast<size_t>(v)];
    p[2] = std::sin(1.3 * p[0]) * std::cos(0.9 * p[1]);
  }
  return m;
}

std::vector<int32_t> spread_anchors(const EdgeGraph& g, int32_t count) {
  std::vector<int32_t> picked;
  EXPECT_TRUE(farthest_point_sampling(g, count, {}, &picked).ok());
  return picked;
}

// Solves the dense n x n system a x = b (row-major a) by Gaussian
// elimination with partial pivoting; b is overwritten with x.
void dense_solve(std::vector<double> a, int n, std::vector<double>* b) {
  std::vector<double>& x = *b;
  for (int k = 0; k < n; ++k) {
    int p = k;
    for (int i = k + 1; i < n; ++i)
      if (std::fabs(a[i * n + k]) > std::fabs(a[p * n + k])) p = i;
    for (int j = 0; j < n; ++j) std::swap(a[k * n + j], a[p * n + j]);
    std::swap(x[k], x[p]);
    for (int i = k + 1; i < n; ++i) {
      const double f = a[i * n + k] / a[k * n + k];
      for (int j = k; j < n; ++j) a[i * n + j] -= f * a[k * n + j];
      x[i] -= f * x[k];
    }
  }
  for (int k = n - 1; k >= 0; --k) {
    for (int j = k + 1; j < n; ++j) x[k] -= a[k * n + j] * x[j];
    x[k] /= a[k * n + k];
  }
}

// Positions minimizing ||L x||^2 + sum_r w_r^2 |x_r - c_r|^2 with x_h = c_h
// at the hard anchors, from the dense L^T L: the oracle for the object.
std::vector<double> dense_reconstruction(const Mesh& mesh, const std::vector<int32_t>& hard,
                                         const std::vector<int32_t>& relaxed, const std::vector<double>& weights) {
  const EdgeGraph g = build_edge_graph(mesh);
  const int n = g.num_vertices();
  std::vector<double> l(static_cast<size_t>(n) * n, 0.0), m(static_cast<size_t>(n) * n, 0.0);
  for (int v = 0; v < n; ++v) {
    l[v * n + v] = g.degree(v);
    for (int32_t p = g.offsets[v]; p < g.offsets[v + 1]; ++p) l[v * n + g.neighbors[p]] = -1.0;
  }
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) m[i * n + j] += l[k * n + i] * l[k * n + j];
  std::vector<char> is_hard(n, 0);
  for (int32_t h : hard) is_hard[h] = 1;
  std::vector<int> free;
  for (int v = 0; v < n; ++v)
    if (!is_hard[v]) free.push_back(v);
  const int nf = static_cast<int>(free.size());
  std::vector<int> row_of(n, -1);
  for (int i = 0; i < nf; ++i) row_of[free[i]] = i;
  std::vector<double> a(static_cast<size_t>(nf) * nf);
  for (int i = 0; i < nf; ++i)
    for (int j = 0; j < nf; ++j) a[i * nf + j] = m[free[i] * n + free[j]];
  for (size_t r = 0; r < relaxed.size(); ++r) a[row_of[relaxed[r]] * nf + row_of[relaxed[r]]] += weights[r] * weights[r];
  std::vector<double> positions = mesh.positions;
  for (int c = 0; c < 3; ++c) {
    std::vector<double> b(nf, 0.0);
    for (int i = 0; i < nf; ++i)
      for (int32_t h : hard) b[i] -= m[free[i] * n + h] * mesh.positions[3 * h + c];
    for (size_t r = 0; r < relaxed.size(); ++r)
      b[row_of[relaxed[r]]] += weights[r] * weights[r] * mesh.positions[3 * relaxed[r] + c];
    dense_solve(a, nf, &b);
    for (int i = 0; i < nf; ++i) positions[3 * free[i] + c] = b[i];
  }
  return positions;
}

double max_abs_difference(const std::vector<double>& a, const std::vector<double>& b) {
  double d = 0.0;
  for (size_t i = 0; i < a.size(); ++i) d = std::max(d, std::fabs(a[i] - b[i]));
  return d;
}

// Relative residual of (L^T L)_FF x_F = -(L^T L)_FA c, computed with the
// full assembled L^T L: (L^T L p)_F is the residual, and (L^T L p_A)_F with
// p_A the positions zeroed off the anchors is the right-hand side's negative.
double free_residual(const EdgeGraph& g, const InterpolatoryReconstruction& rec, const std::vector<double>& pos) {
  CscMatrix full;
  EXPECT_TRUE(assemble_normal_matrix(g, {}, 0.0, &full).ok());
  const int32_t n = g.num_vertices();
  double r2 = 0.0, b2 = 0.0;
  std::vector<double> p(n), pa(n), r(n), b(n);
  for (int c = 0; c < 3; ++c) {
    for (int32_t v = 0; v < n; ++v) {
      p[v] = pos[3 * static_cast<size_t>(v) + c];
      pa[v] = rec.is_hard_anchor(v) ? p[v] : 0.0;
    }
    symmetric_lower_matvec(full, p.data(), r.data());
    symmetric_lower_matvec(full, pa.data(), b.data());
    for (int32_t v = 0; v < n; ++v) {
      if (rec.is_hard_anchor(v)) continue;
      r2 += r[v] * r[v];
      b2 += b[v] * b[v];
    }
  }
  return std::sqrt(r2 / b2);
}

TEST(InterpolatoryReconstructionTest, KeepsHardAnchorsAndSolvesTheFreeSystem) {
  for (const Mesh& mesh : {testing_util::torus(24, 14), wavy_grid(20, 15)}) {
    const EdgeGraph g = build_edge_graph(mesh);
    const std::vector<int32_t> hard = spread_anchors(g, 9);
    const std::vector<double> coef = coefficients(mesh, hard);
    InterpolatoryReconstruction rec;
    ASSERT_TRUE(rec.init(g, hard, coef).ok());
    EXPECT_EQ(rec.num_vertices(), mesh.num_vertices());
    EXPECT_EQ(rec.num_hard_anchors(), 9);
    EXPECT_EQ(rec.num_free(), mesh.num_vertices() - 9);
    EXPECT_EQ(rec.num_relaxed_anchors(), 0);
    std::vector<double> pos;
    ASSERT_TRUE(rec.reconstruct(&pos).ok());
    ASSERT_EQ(pos.size(), mesh.positions.size());
    for (size_t i = 0; i < hard.size(); ++i) {
      EXPECT_TRUE(rec.is_hard_anchor(hard[i]));
      for (int c = 0; c < 3; ++c) EXPECT_EQ(pos[3 * hard[i] + c], coef[3 * i + c]);
    }
    EXPECT_LE(free_residual(g, rec, pos), 1e-12);
  }
}

TEST(InterpolatoryReconstructionTest, RelaxedAnchorsThroughTheUpdaterMatchADenseSolve) {
  for (const Mesh& mesh : {testing_util::torus(9, 6), wavy_grid(7, 5)}) {
    const EdgeGraph g = build_edge_graph(mesh);
    const std::vector<int32_t> spread = spread_anchors(g, 17);
    const std::vector<int32_t> hard(spread.begin(), spread.begin() + 3);
    // Three batches with their own weights; the last is longer than the
    // updater's sweep of 8 paths.
    const std::vector<int32_t> first = {spread[3], spread[4]}, second = {spread[5]},
                               third(spread.begin() + 6, spread.end());
    InterpolatoryReconstruction rec;
    ASSERT_TRUE(rec.init(g, hard, coefficients(mesh, hard)).ok());
    ASSERT_TRUE(rec.add_relaxed_anchors(first, coefficients(mesh, first), 0.7).ok());
    ASSERT_TRUE(rec.add_relaxed_anchors(second, coefficients(mesh, second), 5.0).ok());
    ASSERT_TRUE(rec.add_relaxed_anchors(third, coefficients(mesh, third), 2.0).ok());
    EXPECT_EQ(rec.num_relaxed_anchors(), 14);
    EXPECT_TRUE(rec.is_relaxed_anchor(spread[5]));
    EXPECT_FALSE(rec.is_hard_anchor(spread[5]));
    std::vector<double> pos;
    ASSERT_TRUE(rec.reconstruct(&pos).ok());

    std::vector<int32_t> relaxed = first;
    relaxed.insert(relaxed.end(), second.begin(), second.end());
    relaxed.insert(relaxed.end(), third.begin(), third.end());
    std::vector<double> weights = {0.7, 0.7, 5.0};
    weights.resize(relaxed.size(), 2.0);
    const std::vector<double> expect = dense_reconstruction(mesh, hard, relaxed, weights);
    EXPECT_LE(max_abs_difference(pos, expect), 1e-10);
    for (int32_t h : hard)
      for (int c = 0; c < 3; ++c) EXPECT_EQ(pos[3 * h + c], mesh.positions[3 * h + c]);
  }
}

TEST(InterpolatoryReconstructionTest, RelaxedBasisTendsToTheInterpolatoryOneAsTheWeightGrows) {
  const Mesh mesh = testing_util::torus(40, 16);
  const EdgeGraph g = build_edge_graph(mesh);
  const std::vector<int32_t> anchors = spread_anchors(g, 16);
  const std::vector<double> coef = coefficients(mesh, anchors);
  const double diagonal = bounding_box_diagonal(mesh);
  InterpolatoryReconstruction interpolatory;
  ASSERT_TRUE(interpolatory.init(g, anchors, coef).ok());
  std::vector<double> exact;
  ASSERT_TRUE(interpolatory.reconstruct(&exact).ok());

  std::vector<double> distance, residual;
  for (double w : {1.0, 10.0, 100.0, 1e3, 1e4}) {
    RelaxedReconstruction relaxed;
    ASSERT_TRUE(relaxed.init(g, w, anchors, coef).ok());
    std::vector<double> pos;
    ASSERT_TRUE(relaxed.reconstruct(&pos).ok());
    distance.push_back(max_abs_difference(pos, exact) / diagonal);
    double r = 0.0;
    for (size_t i = 0; i < anchors.size(); ++i)
      for (int c = 0; c < 3; ++c) r = std::max(r, std::fabs(pos[3 * anchors[i] + c] - coef[3 * i + c]));
    residual.push_back(r / diagonal);
  }
  for (size_t i = 1; i < distance.size(); ++i) EXPECT_LT(distance[i], distance[i - 1]) << "step " << i;
  EXPECT_LT(distance.back(), 1e-5);
  // x_A - c = -(S + w^2 I)^{-1} S c, S the Schur complement of L^T L on the
  // anchors: a step from w to 10 w divides the residual by about
  // (100 w^2 + s) / (w^2 + s) for the eigenvalues s of S that c excites, so
  // by ~100 once w^2 dominates S, until rounding takes over. Here (40 free
  // vertices per anchor) S reaches ~2: the step 1 -> 10 gives ~32x, not yet
  // 1/w^2, and every later step ~97-100x.
  const double roundoff = 1e-11;
  EXPECT_GE(residual[0] / residual[1], 10.0);
  for (size_t i = 2; i < residual.size(); ++i) {
    if (residual[i] < roundoff) break;
    EXPECT_GE(residual[i - 1] / residual[i], 50.0) << "step " << i << ": " << residual[i - 1] << " -> " << residual[i];
  }
  EXPECT_GT(residual[3], roundoff) << "the range above roundoff should cover a few steps";
}

TEST(InterpolatoryReconstructionTest, IsolatedVerticesAndAllHard) {
  // An unreferenced vertex is a component of its own: a hard anchor keeps it.
  Mesh mesh = testing_util::grid(3, 3);
  mesh.positions.insert(mesh.positions.end(), {5.0, 6.0, 7.0});
  const EdgeGraph g = build_edge_graph(mesh);
  const int32_t isolated = mesh.num_vertices() - 1;
  InterpolatoryReconstruction rec;
  const std::vector<int32_t> hard = {isolated, 0, 15};
  ASSERT_TRUE(rec.init(g, hard, coefficients(mesh, hard)).ok());
  std::vector<double> pos;
  ASSERT_TRUE(rec.reconstruct(&pos).ok());
  EXPECT_EQ(pos[3 * isolated + 1], 6.0);

  std::vector<int32_t> all(mesh.num_vertices());
  for (int32_t v = 0; v < mesh.num_vertices(); ++v) all[v] = v;
  ASSERT_TRUE(rec.init(g, all, mesh.positions).ok());
  EXPECT_EQ(rec.num_free(), 0);
  ASSERT_TRUE(rec.reconstruct(&pos).ok());
  EXPECT_EQ(pos, mesh.positions);
  EXPECT_TRUE(rec.add_relaxed_anchors({}, {}, 1.0).ok());
}

TEST(InterpolatoryReconstructionTest, RejectsBadInputWithClearMessages) {
  Mesh mesh = testing_util::grid(2, 2);  // 9 vertices
  mesh.positions.insert(mesh.positions.end(), {1.0, 1.0, 1.0});
  const int32_t isolated = 9;
  const EdgeGraph g = build_edge_graph(mesh);
  InterpolatoryReconstruction rec;
  EXPECT_EQ(rec.reconstruct(nullptr).message(), "reconstruct before init");
  EXPECT_EQ(rec.add_relaxed_anchors({1}, {0, 0, 0}, 1.0).message(), "add_relaxed_anchors before init");
  EXPECT_EQ(rec.init(g, {3, isolated, 3}, coefficients(mesh, {3, isolated, 3})).message(), "anchor 3 given twice");
  EXPECT_EQ(rec.init(g, {0}, coefficients(mesh, {0})).message(),
            "the connected component of vertex 9 has no hard anchor (every component needs one)");
  EXPECT_EQ(rec.init(g, {isolated}, coefficients(mesh, {isolated})).message(),
            "the connected component of vertex 0 has no hard anchor (every component needs one)");
  EXPECT_EQ(rec.init(g, {0, isolated}, {1.0, 2.0}).message(), "need 3 coefficients per anchor: got 2 for 2 anchors");
  EXPECT_EQ(rec.init(g, {0, 10}, {0, 0, 0, 0, 0, 0}).message(), "anchor 10 is not a vertex (n = 10)");
  EXPECT_EQ(rec.init(g, {0, isolated}, {0, 0, 0, 0, NAN, 0}).message(), "anchor coefficient is not finite");
  EXPECT_EQ(rec.reconstruct(nullptr).message(), "reconstruct before init");

  const std::vector<int32_t> hard = {0, isolated};
  ASSERT_TRUE(rec.init(g, hard, coefficients(mesh, hard)).ok());
  std::vector<double> before, after;
  ASSERT_TRUE(rec.reconstruct(&before).ok());
  EXPECT_EQ(rec.add_relaxed_anchors({4, 0}, coefficients(mesh, {4, 0}), 1.0).message(), "vertex 0 is a hard anchor");
  EXPECT_EQ(rec.add_relaxed_anchors({4}, {1.0}, 1.0).message(), "need 3 coefficients per anchor: got 1 for 1 anchors");
  EXPECT_EQ(rec.add_relaxed_anchors({4, 4}, coefficients(mesh, {4, 4}), 1.0).message(), "anchor 4 given twice");
  EXPECT_EQ(rec.add_relaxed_anchors({-1}, {0, 0, 0}, 1.0).message(), "anchor -1 is not a vertex (n = 10)");
  EXPECT_EQ(rec.add_relaxed_anchors({4}, coefficients(mesh, {4}), 0.0).message(),
            "anchor weight must be positive and finite");
  EXPECT_EQ(rec.add_relaxed_anchors({4}, coefficients(mesh, {4}), INFINITY).message(),
            "anchor weight must be positive and finite");
  // Failed calls change nothing.
  EXPECT_EQ(rec.num_relaxed_anchors(), 0);
  EXPECT_FALSE(rec.is_relaxed_anchor(4));
  ASSERT_TRUE(rec.reconstruct(&after).ok());
  EXPECT_EQ(before, after);

  ASSERT_TRUE(rec.add_relaxed_anchors({4}, coefficients(mesh, {4}), 1.0).ok());
  EXPECT_EQ(rec.add_relaxed_anchors({8, 4}, coefficients(mesh, {8, 4}), 1.0).message(),
            "vertex 4 is already a relaxed anchor");
  EXPECT_EQ(rec.num_relaxed_anchors(), 1);
}

}  // namespace
}  // namespace gab
