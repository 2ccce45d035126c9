// Least-squares optimal anchor coefficients against a dense oracle.
#include <gtest/gtest.h>

#include <cmath>

#include "gab/mesh/edge_graph.h"
#include "gab/mesh/optimal_coefficients.h"
#include "gab/mesh/relaxed_reconstruction.h"
#include "mesh/mesh_test_util.h"

namespace gab {
namespace {

Mesh wavy_torus() {
  Mesh m = testing_util::torus(16, 8);
  for (int32_t v = 0; v < m.num_vertices(); ++v) {
    double* p = &m.positions[3 * static_cast<size_t>(v)];
    p[2] += 0.05 * std::sin(4 * p[0]) * std::cos(3 * p[1]);
  }
  return m;
}

double squared_error(const Mesh& m, const std::vector<double>& x) {
  double s = 0;
  for (size_t i = 0; i < x.size(); ++i) s += (x[i] - m.positions[i]) * (x[i] - m.positions[i]);
  return s;
}

TEST(OptimalCoefficientsTest, MatchesTheDenseLeastSquaresSolution) {
  const Mesh m = wavy_torus();
  const EdgeGraph g = build_edge_graph(m);
  const std::vector<int32_t> anchors = {0, 17, 40, 63, 77, 90, 101, 120};
  std::vector<double> c;
  for (int32_t a : anchors)
    for (int j = 0; j < 3; ++j) c.push_back(m.positions[3 * static_cast<size_t>(a) + j]);
  RelaxedReconstruction rec;
  ASSERT_TRUE(rec.init(g, 10.0, anchors, c).ok());
  // The basis B (n x k) column by column: B e_i = M^-1 w^2 e_{a_i}, same for x, y, z.
  const size_t n = m.num_vertices(), k = anchors.size();
  std::vector<std::vector<double>> basis(k);
  for (size_t i = 0; i < k; ++i) {
    std::vector<double> b(3 * n, 0.0);
    b[anchors[i]] = 100.0;
    ASSERT_TRUE(rec.solve_system(b.data()).ok());
    basis[i].assign(b.begin(), b.begin() + n);
  }
  // Dense normal equations per coordinate, by Gaussian elimination.
  std::vector<double> expected(3 * k);
  for (int j = 0; j < 3; ++j) {
    std::vector<double> a(k * k), rhs(k);
    for (size_t r = 0; r < k; ++r) {
      for (size_t s = 0; s < k; ++s) {
        for (size_t v = 0; v < n; ++v) a[r * k + s] += basis[r][v] * basis[s][v];
      }
      for (size_t v = 0; v < n; ++v) rhs[r] += basis[r][v] * m.positions[3 * v + j];
    }
    for (size_t p = 0; p < k; ++p) {
      for (size_t r = p + 1; r < k; ++r) {
        const double f = a[r * k + p] / a[p * k + p];
        for (size_t s = p; s < k; ++s) a[r * k + s] -= f * a[p * k + s];
        rhs[r] -= f * rhs[p];
      }
    }
    for (size_t p = k; p-- > 0;) {
      double s = rhs[p];
      for (size_t q = p + 1; q < k; ++q) s -= a[p * k + q] * expected[3 * q + j];
      expected[3 * p + j] = s / a[p * k + p];
    }
  }
  std::vector<double> got = c;
  OptimalCoefficientsReport report;
  ASSERT_TRUE(optimal_coefficients(&rec, m, 200, 1e-12, &got, &report).ok());
  EXPECT_LE(report.iterations, static_cast<int32_t>(k) + 5);  // CG: at most k steps, up to rounding
  for (size_t i = 0; i < 3 * k; ++i) EXPECT_NEAR(got[i], expected[i], 1e-8) << i;
}

TEST(OptimalCoefficientsTest, LowersTheErrorOfTheReconstruction) {
  const Mesh m = wavy_torus();
  const EdgeGraph g = build_edge_graph(m);
  std::vector<int32_t> anchors;
  for (int32_t v = 0; v < m.num_vertices(); v += 9) anchors.push_back(v);
  std::vector<double> c;
  for (int32_t a : anchors)
    for (int j = 0; j < 3; ++j) c.push_back(m.positions[3 * static_cast<size_t>(a) + j]);
  RelaxedReconstruction rec, optimal;
  ASSERT_TRUE(rec.init(g, 100.0, anchors, c).ok());
  std::vector<double> before, after, ls = c;
  ASSERT_TRUE(rec.reconstruct(&before).ok());
  OptimalCoefficientsReport report;
  ASSERT_TRUE(optimal_coefficients(&rec, m, 50, 1e-10, &ls, &report).ok());
  EXPECT_LT(report.relative_gradient, 1e-10);
  ASSERT_TRUE(optimal.init(g, 100.0, anchors, ls).ok());
  ASSERT_TRUE(optimal.reconstruct(&after).ok());
  EXPECT_LT(squared_error(m, after), 0.9 * squared_error(m, before));
}

TEST(OptimalCoefficientsTest, ClearErrors) {
  const Mesh m = wavy_torus();
  const EdgeGraph g = build_edge_graph(m);
  RelaxedReconstruction rec;
  ASSERT_TRUE(rec.init(g, 1.0, {0}, {0, 0, 0}).ok());
  std::vector<double> c = {0, 0};
  OptimalCoefficientsReport report;
  EXPECT_EQ(optimal_coefficients(&rec, m, 5, 1e-6, &c, &report).message(),
            "need 3 starting coefficients per anchor: got 2 for 1 anchors");
  Mesh other = testing_util::grid(3, 3);
  c = {0, 0, 0};
  EXPECT_EQ(optimal_coefficients(&rec, other, 5, 1e-6, &c, &report).message(),
            "mesh and reconstruction have different vertex counts");
}

}  // namespace
}  // namespace gab
