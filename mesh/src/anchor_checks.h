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

// "vertex V is already an anchor": what check_new_anchors says of a vertex
// that is one, unless the reconstruction names its kinds of anchor.
inline std::string already_an_anchor(int32_t v, int) { return "vertex " + std::to_string(v) + " is already an anchor"; }

// New anchors with their coefficients (check_anchor_coefficients) for a
// reconstruction whose per-vertex `state` is `free` for a vertex that is not
// an anchor: each anchor a vertex, not an anchor yet (`taken(v, state)` says
// what it is), not given twice; the first problem in the given order is
// named. New anchors are marked `mark` while checking, then set back to
// `free`. O(anchors).
template <class T, class Taken = std::string (*)(int32_t, int)>
Status check_new_anchors(const std::vector<int32_t>& anchors, const std::vector<double>& coefficients,
                         std::vector<T>* state, T free, T mark, Taken taken = already_an_anchor) {
  GAB_RETURN_IF_ERROR(check_anchor_coefficients(anchors.size(), coefficients));
  const int32_t n = static_cast<int32_t>(state->size());
  Status status;
  size_t marked = 0;
  for (; marked < anchors.size(); ++marked) {
    const int32_t a = anchors[marked];
    if (a < 0 || a >= n) {
      status = Status::Error(StatusCode::kInvalidArgument,
                             "anchor " + std::to_string(a) + " is not a vertex (n = " + std::to_string(n) + ")");
      break;
    }
    if ((*state)[a] != free) {
      status = Status::Error(StatusCode::kInvalidArgument, (*state)[a] == mark ? "anchor " + std::to_string(a) + " given twice"
                                                                                : taken(a, (*state)[a]));
      break;
    }
    (*state)[a] = mark;
  }
  for (size_t i = 0; i < marked; ++i) (*state)[anchors[i]] = free;
  return status;
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
