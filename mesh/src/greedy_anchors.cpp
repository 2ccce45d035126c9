#include "gab/mesh/greedy_anchors.h"

#include <algorithm>
#include <cmath>

#include "gab/mesh/graph_distance.h"
#include "gab/mesh/metrics.h"
#include "gab/mesh/relaxed_reconstruction.h"

namespace gab {

namespace {

std::vector<double> coefficients_of(const Mesh& mesh, const std::vector<int32_t>& anchors) {
  std::vector<double> c;
  c.reserve(anchors.size() * 3);
  for (int32_t a : anchors) {
    for (int k = 0; k < 3; ++k) c.push_back(mesh.positions[3 * static_cast<size_t>(a) + k]);
  }
  return c;
}

}  // namespace

Status select_anchors_greedy(const Mesh& mesh, const EdgeGraph& graph, const GreedyOptions& options,
                             std::vector<int32_t>* anchors, std::vector<GreedyStep>* curve) {
  const int32_t n = mesh.num_vertices();
  if (graph.num_vertices() != n) {
    return Status::Error(StatusCode::kInvalidArgument, "edge graph and mesh have different vertex counts");
  }
  int32_t ncomp = 0;
  connected_components(graph, &ncomp);
  std::vector<int32_t> chosen;
  GAB_RETURN_IF_ERROR(farthest_point_sampling(graph, std::max(options.initial, ncomp), {}, &chosen));
  RelaxedReconstruction rec;
  GAB_RETURN_IF_ERROR(rec.init(graph, options.weight, chosen, coefficients_of(mesh, chosen)));
  const double diagonal = bounding_box_diagonal(mesh);
  const double scale = diagonal > 0 ? 1.0 / diagonal : 1.0;
  curve->clear();
  std::vector<double> shape;
  while (true) {
    GAB_RETURN_IF_ERROR(rec.reconstruct(&shape));
    // One scan: the RMS and max over all vertices, and the worst vertex not
    // anchored yet (ties: the smallest index).
    double sum2 = 0.0, linf = 0.0, worst = -1.0;
    int32_t worst_vertex = -1;
    for (int32_t v = 0; v < n; ++v) {
      double d2 = 0.0;
      for (int k = 0; k < 3; ++k) {
        const double d = shape[3 * static_cast<size_t>(v) + k] - mesh.positions[3 * static_cast<size_t>(v) + k];
        d2 += d * d;
      }
      sum2 += d2;
      linf = std::max(linf, d2);
      if (!rec.is_anchor(v) && d2 > worst) {
        worst = d2;
        worst_vertex = v;
      }
    }
    const double rms_rel = std::sqrt(sum2 / std::max(n, 1)) * scale;
    curve->push_back({rec.num_anchors(), rms_rel, std::sqrt(linf) * scale});
    if (rec.num_anchors() >= options.max_anchors || worst_vertex < 0 ||
        (options.target_rms_rel > 0 && rms_rel <= options.target_rms_rel)) {
      break;
    }
    const std::vector<int32_t> next = {worst_vertex};
    GAB_RETURN_IF_ERROR(rec.add_anchors(next, coefficients_of(mesh, next)));
  }
  *anchors = rec.anchors();
  return Status::Ok();
}

}  // namespace gab
