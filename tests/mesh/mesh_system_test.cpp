// The engine on real mesh matrices: L^T L + E^T E by the benchmark anchor
// rule, factored and solved to the accuracy, and updated in place.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "gab/mesh/edge_graph.h"
#include "gab/mesh/normal_matrix.h"
#include "gab/mesh/off_io.h"
#include "gab/sparse/cholesky.h"

namespace gab {
namespace {

double residual(const CscMatrix& a, const std::vector<double>& x, const std::vector<double>& b) {
  const int32_t n = a.ncols;
  std::vector<double> ax(n);
  double num = 0.0, den = 0.0;
  for (int r = 0; r < 3; ++r) {
    symmetric_lower_matvec(a, x.data() + static_cast<size_t>(r) * n, ax.data());
    for (int32_t i = 0; i < n; ++i) {
      const double bi = b[i + static_cast<size_t>(r) * n];
      num += (ax[i] - bi) * (ax[i] - bi);
      den += bi * bi;
    }
  }
  return std::sqrt(num / den);
}

class MeshSystemTest : public ::testing::TestWithParam<const char*> {};

TEST_P(MeshSystemTest, FactorSolveAndUpdateToResidual1e12) {
  const std::string path = std::string(GAB_SHARED_MESHES) + "/" + GetParam();
  if (!std::ifstream(path)) GTEST_SKIP() << path << " not present";
  Mesh mesh;
  ASSERT_TRUE(read_off(path, &mesh).ok());
  const EdgeGraph g = build_edge_graph(mesh);
  std::vector<int32_t> anchors = benchmark_anchors(g, 100);
  CscMatrix a;
  ASSERT_TRUE(assemble_normal_matrix(g, anchors, 1.0, &a).ok());
  Cholesky chol;
  ASSERT_TRUE(chol.analyze(a).ok());
  ASSERT_TRUE(chol.factorize(a).ok());
  std::vector<double> b = anchor_right_hand_sides(mesh, anchors, 1.0), x = b;
  ASSERT_TRUE(chol.solve(x.data(), 3, a.ncols).ok());
  EXPECT_LT(residual(a, x, b), 1e-12);

  // 50 more anchors through the updater: the solve must see them.
  const int32_t n = a.ncols;
  std::vector<char> anchored(n, 0);
  for (int32_t v : anchors) anchored[v] = 1;
  for (uint64_t t = 1; anchors.size() < 150; ++t) {
    const int32_t v = static_cast<int32_t>((t * 2654435761ull) % static_cast<uint64_t>(n));
    if (anchored[v]) continue;
    anchored[v] = 1;
    anchors.push_back(v);
    ASSERT_TRUE(chol.add_anchor(v, 1.0).ok());
  }
  ASSERT_TRUE(assemble_normal_matrix(g, anchors, 1.0, &a).ok());
  b = anchor_right_hand_sides(mesh, anchors, 1.0);
  x = b;
  ASSERT_TRUE(chol.solve(x.data(), 3, n).ok());
  EXPECT_LT(residual(a, x, b), 1e-12);
}

INSTANTIATE_TEST_SUITE_P(SharedMeshes, MeshSystemTest,
                         ::testing::Values("bunny-small.off", "camel-head.off", "max-planck.off"));

}  // namespace
}  // namespace gab
