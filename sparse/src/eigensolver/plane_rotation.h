// sqrt(a^2 + b^2) for the plane rotations of the band reduction and QL
// (internal). std::hypot guards against overflow and underflow at every
// call and was a tenth of a 1,000-eigenpair solve; the plain formula is
// exact enough wherever the squares are representable, which is checked.
#pragma once

#include <algorithm>
#include <cmath>

namespace gab {
namespace eigen_detail {

inline double rotation_norm(double a, double b) {
  const double s = std::max(std::abs(a), std::abs(b));
  if (s > 1e-150 && s < 1e150) return std::sqrt(a * a + b * b);
  return std::hypot(a, b);
}

}  // namespace eigen_detail
}  // namespace gab
