// The interpolatory system: principal submatrix of L^T L and its right-hand
// side, checked against dense algebra and by solving with the engine.
#include "gab/mesh/interpolatory_system.h"

#include <gtest/gtest.h>

#include <cmath>

#include "gab/mesh/normal_matrix.h"
#include "gab/sparse/cholesky.h"
#include "mesh_test_util.h"

namespace gab {
namespace {

std::vector<double> dense_ltl(const EdgeGraph& g) {
  const int32_t n = g.num_vertices();
  std::vector<double> l(static_cast<size_t>(n) * n, 0.0), m(static_cast<size_t>(n) * n, 0.0);
  for (int32_t v = 0; v < n; ++v) {
    l[v * n + v] = g.degree(v);
    for (int32_t p = g.offsets[v]; p < g.offsets[v + 1]; ++p) l[v * n + g.neighbors[p]] = -1.0;
  }
  for (int32_t i = 0; i < n; ++i)
    for (int32_t j = 0; j < n; ++j)
      for (int32_t k = 0; k < n; ++k) m[i * n + j] += l[k * n + i] * l[k * n + j];
  return m;
}

TEST(InterpolatorySystemTest, MatrixAndRightHandSideMatchDenseAlgebra) {
  const Mesh mesh = testing_util::grid(3, 2);
  const EdgeGraph g = build_edge_graph(mesh);
  const int32_t n = g.num_vertices();
  const std::vector<int32_t> anchors = {5, 0, 11};
  InterpolatorySystem sys;
  ASSERT_TRUE(assemble_interpolatory_matrix(g, anchors, &sys).ok());
  EXPECT_TRUE(check_csc(sys.lower).ok());
  ASSERT_EQ(sys.free_vertices.size(), 9u);
  EXPECT_EQ(sys.free_index[0], -1);
  EXPECT_EQ(sys.free_index[1], 0);
  const std::vector<double> m = dense_ltl(g);
  const int32_t nf = 9;
  std::vector<double> got(nf * nf, 0.0);
  for (int32_t j = 0; j < nf; ++j) {
    EXPECT_EQ(sys.lower.rowind[sys.lower.colptr[j]], j) << "diagonal first";
    for (int32_t p = sys.lower.colptr[j]; p < sys.lower.colptr[j + 1]; ++p) got[sys.lower.rowind[p] * nf + j] = sys.lower.values[p];
  }
  for (int32_t i = 0; i < nf; ++i)
    for (int32_t j = 0; j <= i; ++j)
      EXPECT_EQ(got[i * nf + j], m[sys.free_vertices[i] * n + sys.free_vertices[j]]) << i << "," << j;

  const std::vector<double> coef = {1, 2, 3, -1, 0.5, 4, 7, 8, 9};
  std::vector<double> rhs;
  ASSERT_TRUE(interpolatory_right_hand_sides(g, sys, anchors, coef, &rhs).ok());
  for (int axis = 0; axis < 3; ++axis) {
    for (int32_t i = 0; i < nf; ++i) {
      double expect = 0;
      for (size_t a = 0; a < anchors.size(); ++a) expect -= m[sys.free_vertices[i] * n + anchors[a]] * coef[3 * a + axis];
      EXPECT_DOUBLE_EQ(rhs[axis * nf + i], expect);
    }
  }
}

TEST(InterpolatorySystemTest, SolutionKeepsAnchorsAndZeroesTheFreeResidual) {
  const Mesh mesh = testing_util::torus(16, 10);
  const EdgeGraph g = build_edge_graph(mesh);
  const std::vector<int32_t> anchors = {0, 37, 80, 121, 150};
  std::vector<double> coef;
  for (int32_t a : anchors)
    for (int c = 0; c < 3; ++c) coef.push_back(mesh.positions[3 * a + c]);
  InterpolatorySystem sys;
  ASSERT_TRUE(assemble_interpolatory_matrix(g, anchors, &sys).ok());
  std::vector<double> x;
  ASSERT_TRUE(interpolatory_right_hand_sides(g, sys, anchors, coef, &x).ok());
  Cholesky chol;
  ASSERT_TRUE(chol.analyze(sys.lower).ok());
  ASSERT_TRUE(chol.factorize(sys.lower).ok());
  const int32_t nf = sys.lower.ncols;
  ASSERT_TRUE(chol.solve(x.data(), 3, nf).ok());
  const std::vector<double> pos = interpolatory_positions(sys, anchors, coef, x);
  for (size_t a = 0; a < anchors.size(); ++a)
    for (int c = 0; c < 3; ++c) EXPECT_EQ(pos[3 * anchors[a] + c], coef[3 * a + c]);
  // (L^T L p)_F = 0: the free part minimizes ||L p||.
  CscMatrix full;
  ASSERT_TRUE(assemble_normal_matrix(g, {}, 0.0, &full).ok());
  const int32_t n = g.num_vertices();
  for (int c = 0; c < 3; ++c) {
    std::vector<double> pc(n), r(n);
    for (int32_t v = 0; v < n; ++v) pc[v] = pos[3 * v + c];
    symmetric_lower_matvec(full, pc.data(), r.data());
    for (int32_t v : sys.free_vertices) EXPECT_NEAR(r[v], 0.0, 1e-10);
  }
}

TEST(InterpolatorySystemTest, RejectsBadInput) {
  const EdgeGraph g = build_edge_graph(testing_util::grid(1, 1));
  InterpolatorySystem sys;
  EXPECT_EQ(assemble_interpolatory_matrix(g, {4}, &sys).message(), "anchor 4 is not a vertex (n = 4)");
  EXPECT_EQ(assemble_interpolatory_matrix(g, {1, 1}, &sys).message(), "anchor 1 given twice");
  ASSERT_TRUE(assemble_interpolatory_matrix(g, {1}, &sys).ok());
  std::vector<double> rhs;
  EXPECT_EQ(interpolatory_right_hand_sides(g, sys, {1}, {1, 2}, &rhs).message(),
            "expected 3 coefficients (x y z per anchor), got 2");
  EXPECT_EQ(interpolatory_right_hand_sides(g, sys, {2}, {1, 2, 3}, &rhs).message(),
            "vertex 2 is not an anchor of the system");
}

}  // namespace
}  // namespace gab
