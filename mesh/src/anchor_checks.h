// The checks every reconstruction applies to anchor coefficients (internal
// to the mesh layer).
#pragma once

#include <cmath>
#include <string>
#include <vector>

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

}  // namespace gab
