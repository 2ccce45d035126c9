// The paper's Figure 4 on our meshes (Sorkine et al. 2005): how the relaxed
// basis behaves as the anchor weight w grows, beside the interpolatory
// basis with the same anchors. k anchors (default 1% of n) spread by
// farthest-point sampling in hops, coefficients = their exact positions.
// For each w: the relaxed reconstruction's vertex RMS error, the RMS anchor
// residual |x_a - c_a| and the RMS distance to the interpolatory
// reconstruction, all relative to the bounding-box diagonal. Prints a
// markdown table.
//
//   bench/figure4 [--anchors K] [mesh]   (default: ../shared/meshes/camel-head.off, K = n / 100)
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "gab/mesh/edge_graph.h"
#include "gab/mesh/graph_distance.h"
#include "gab/mesh/interpolatory_reconstruction.h"
#include "gab/mesh/mesh_io.h"
#include "gab/mesh/metrics.h"
#include "gab/mesh/relaxed_reconstruction.h"

namespace {

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// sqrt(mean over `vertices` of |a_v - b_v|^2); all vertices when empty.
double rms_distance(const std::vector<double>& a, const std::vector<double>& b, const std::vector<int32_t>& vertices) {
  const size_t count = vertices.empty() ? a.size() / 3 : vertices.size();
  double sum = 0.0;
  for (size_t i = 0; i < count; ++i) {
    const size_t v = vertices.empty() ? i : static_cast<size_t>(vertices[i]);
    for (int c = 0; c < 3; ++c) sum += (a[3 * v + c] - b[3 * v + c]) * (a[3 * v + c] - b[3 * v + c]);
  }
  return std::sqrt(sum / static_cast<double>(count));
}

int fail(const gab::Status& s) {
  std::fprintf(stderr, "figure4: %s\n", s.message().c_str());
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  std::string path = std::string(GAB_SHARED_MESHES) + "/camel-head.off";
  int32_t k = 0;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--anchors") && i + 1 < argc) {
      k = std::atoi(argv[++i]);
    } else {
      path = argv[i];
    }
  }
  gab::Mesh mesh;
  gab::Status s = gab::read_mesh(path, &mesh);
  if (!s.ok()) return fail(s);
  const gab::EdgeGraph g = gab::build_edge_graph(mesh);
  const int32_t n = mesh.num_vertices();
  if (k <= 0) k = n / 100 > 0 ? n / 100 : 1;
  // farthest_point_sampling gives every component a vertex first, so the
  // systems are nonsingular whenever k covers the components.
  std::vector<int32_t> anchors;
  if (!(s = gab::farthest_point_sampling(g, k, {}, &anchors)).ok()) return fail(s);
  std::vector<double> coef;
  for (int32_t a : anchors)
    for (int c = 0; c < 3; ++c) coef.push_back(mesh.positions[3 * static_cast<size_t>(a) + c]);
  const double diagonal = gab::bounding_box_diagonal(mesh);

  double t0 = now();
  gab::InterpolatoryReconstruction interpolatory;
  std::vector<double> exact;
  if (!(s = interpolatory.init(g, anchors, coef)).ok() || !(s = interpolatory.reconstruct(&exact)).ok()) return fail(s);
  const double interpolatory_s = now() - t0;

  const std::string name = path.substr(path.find_last_of('/') + 1);
  std::printf("%s: n = %d, k = %zu anchors (farthest-point, exact coefficients), bbox diagonal %.6g\n\n",
              name.c_str(), n, anchors.size(), diagonal);
  std::printf("| basis | w | vertex RMS / diag | anchor RMS residual / diag | RMS to interpolatory / diag | init + reconstruct s |\n");
  std::printf("|---|---:|---:|---:|---:|---:|\n");
  std::printf("| interpolatory | inf | %.4e | 0 | 0 | %.3f |\n", rms_distance(exact, mesh.positions, {}) / diagonal,
              interpolatory_s);
  for (double w : {0.1, 0.3, 1.0, 3.0, 10.0, 30.0, 100.0, 300.0, 1000.0}) {
    t0 = now();
    gab::RelaxedReconstruction relaxed;
    std::vector<double> pos;
    if (!(s = relaxed.init(g, w, anchors, coef)).ok() || !(s = relaxed.reconstruct(&pos)).ok()) return fail(s);
    const double seconds = now() - t0;
    std::printf("| relaxed | %g | %.4e | %.4e | %.4e | %.3f |\n", w,
                rms_distance(pos, mesh.positions, {}) / diagonal, rms_distance(pos, mesh.positions, anchors) / diagonal,
                rms_distance(pos, exact, {}) / diagonal, seconds);
    std::fflush(stdout);
  }
  return 0;
}
