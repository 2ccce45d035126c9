// The checks every reconstruction applies to its anchors and their
// coefficients (internal to the mesh layer).
#pragma once

#include <cmath>
#include <string>
#include <vector>

#include "gab/mesh/edge_graph.h"
#include "gab/status.h"

namespace gab {

// Three finite coefficients per anchor.
inline Status check_anchor_coefficients(size_t anchors, const std::vector<double>& coefficients) {
  if (coefficients.size() != 3 * anchors) {
    return Status::Error(StatusCode::kInvalidArgument, "need 3 coefficients per anchor: got " +
                                                           std::to_string(coefficients.size()) + " for " +
                                                           std::to_string(anchors) + " anchors");
  }
  for (double c : coefficients) {
    if (!std::isfinite(c)) return Status::Error(StatusCode::kInvalidArgument, "anchor coefficient is not finite");
  }
  return Status::Ok();
}

// Every connected component holds one of `anchors` (valid vertices), or the
// relaxed system is singular there: the error names a vertex of the first
// component without one. O(V + E).
inline Status check_components_anchored(const EdgeGraph& graph, const std::vector<int32_t>& anchors) {
  int32_t count = 0;
  const std::vector<int32_t> component = connected_components(graph, &count);
  std::vector<char> covered(count, 0);
  for (int32_t a : anchors) covered[component[a]] = 1;
  for (int32_t v = 0; v < graph.num_vertices(); ++v) {
    if (!covered[component[v]]) {
      return Status::Error(StatusCode::kInvalidArgument, "the connected component of vertex " + std::to_string(v) +
                                                             " has no anchor (every component needs one)");
    }
  }
  return Status::Ok();
}

}  // namespace gab
