#include "gab/mesh/greedy_anchors.h"

#include <algorithm>
#include <cmath>
#include <utility>

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

std::vector<int32_t> pick_error_maxima(const EdgeGraph& graph, const std::vector<double>& error,
                                       const RelaxedReconstruction& rec, int32_t count) {
  const int32_t n = graph.num_vertices();
  // Batches rank the maxima by the error's mean over the closed 1-ring: an
  // anchor pulls a neighbourhood into place, so a broad bump gains more than
  // a one-vertex spike of the same height. Against ranking by the peak, at
  // equal anchors (w = 100, 2% batches, exact positions): camel-head 466 /
  // 1,138: -7% / -2% RMS, horse 1,312 / 4,848: -9% / -4%, feline 1,339 /
  // 4,986: -6% / -5%; the max error rises a little.
  auto ring_mean = [&](int32_t v) {
    double sum = error[v];
    for (int32_t p = graph.offsets[v]; p < graph.offsets[v + 1]; ++p) sum += error[graph.neighbors[p]];
    return sum / (1 + graph.offsets[v + 1] - graph.offsets[v]);
  };
  std::vector<std::pair<double, int32_t>> candidates;  // (rank key, vertex)
  for (int32_t v = 0; v < n; ++v) {
    if (rec.is_anchor(v)) continue;
    bool local_max = true;
    for (int32_t p = graph.offsets[v]; p < graph.offsets[v + 1] && local_max && count > 1; ++p) {
      local_max = error[v] >= error[graph.neighbors[p]];
    }
    if (local_max) candidates.emplace_back(count > 1 ? ring_mean(v) : error[v], v);
  }
  if (candidates.empty()) {
    // Every free vertex has an anchored neighbour with a larger error: fall
    // back to the worst free vertex so the loop always makes progress.
    for (int32_t v = 0; v < n; ++v) {
      if (!rec.is_anchor(v) && (candidates.empty() || error[v] > candidates[0].first)) candidates.assign(1, {error[v], v});
    }
  }
  const size_t keep = std::min<size_t>(static_cast<size_t>(count), candidates.size());
  std::partial_sort(candidates.begin(), candidates.begin() + keep, candidates.end(),
                    [](const std::pair<double, int32_t>& a, const std::pair<double, int32_t>& b) {
                      return a.first > b.first || (a.first == b.first && a.second < b.second);
                    });
  std::vector<int32_t> picked(keep);
  for (size_t i = 0; i < keep; ++i) picked[i] = candidates[i].second;
  return picked;
}

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
  rec.set_threads(options.threads);
  GAB_RETURN_IF_ERROR(rec.init(graph, options.weight, chosen, coefficients_of(mesh, chosen)));
  const double diagonal = bounding_box_diagonal(mesh);
  const double scale = diagonal > 0 ? 1.0 / diagonal : 1.0;
  curve->clear();
  std::vector<double> shape, error(n);
  while (true) {
    GAB_RETURN_IF_ERROR(rec.reconstruct(&shape));
    VertexDistance d;
    squared_vertex_errors(mesh, shape, &error, &d);
    const double rms_rel = d.rms * scale;
    curve->push_back({rec.num_anchors(), rms_rel, d.linf * scale});
    if (rec.num_anchors() >= options.max_anchors || rec.num_anchors() >= n ||
        (options.target_rms_rel > 0 && rms_rel <= options.target_rms_rel)) {
      break;
    }
    const int64_t wanted = options.batch_fraction > 0
                               ? static_cast<int64_t>(std::ceil(options.batch_fraction * rec.num_anchors()))
                               : 1;
    const int32_t room = options.max_anchors - rec.num_anchors();
    const std::vector<int32_t> next =
        pick_error_maxima(graph, error, rec, static_cast<int32_t>(std::min<int64_t>(std::max<int64_t>(wanted, 1), room)));
    GAB_RETURN_IF_ERROR(rec.add_anchors_cheapest(next, coefficients_of(mesh, next)));
  }
  *anchors = rec.anchors();
  return Status::Ok();
}

}  // namespace gab
