#include "benchmark_system.h"

#include "cli.h"
#include "gab/mesh/edge_graph.h"
#include "gab/mesh/normal_matrix.h"
#include "gab/mesh/mesh_io.h"
#include "gab/mesh/subdivide.h"
#include "gab/sparse/matrix_market.h"

namespace gab {
namespace cli {

Status load_benchmark_system(const std::string& path, int32_t k0, BenchmarkSystem* out,
                             int subdivide) {
  const std::string ext = extension(path);
  BenchmarkSystem sys;
  if (ext == "mtx") {
    GAB_RETURN_IF_ERROR(read_symmetric_matrix_market(path, &sys.lower));
    // b = A x for a known smooth x, so the residual is meaningful.
    const int32_t n = sys.lower.ncols;
    std::vector<double> x(n);
    sys.rhs.assign(static_cast<size_t>(n) * 3, 0.0);
    for (int r = 0; r < 3; ++r) {
      for (int32_t i = 0; i < n; ++i) x[i] = 1.0 + 0.5 * ((i * (r + 3)) % 17) / 17.0;
      symmetric_lower_matvec(sys.lower, x.data(), sys.rhs.data() + static_cast<size_t>(r) * n);
    }
  } else if (ext == "obj" || ext == "off" || ext == "ply") {
    Mesh mesh;
    GAB_RETURN_IF_ERROR(read_mesh(path, &mesh, &sys.read_notes));
    if (subdivide > 0) mesh = subdivide_midpoint(mesh, subdivide);
    sys.faces = mesh.num_triangles();
    const EdgeGraph graph = build_edge_graph(mesh);
    sys.anchors = benchmark_anchors(graph, k0);
    GAB_RETURN_IF_ERROR(assemble_normal_matrix(graph, sys.anchors, 1.0, &sys.lower));
    sys.rhs = anchor_right_hand_sides(mesh, sys.anchors, 1.0);
    sys.from_mesh = true;
  } else {
    return Status::Error(StatusCode::kInvalidArgument,
                         path + ": unsupported input type '." + ext + "' (expected .obj, .off, .ply or .mtx)");
  }
  *out = std::move(sys);
  return Status::Ok();
}

}  // namespace cli
}  // namespace gab
