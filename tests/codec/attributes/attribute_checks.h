// How far a decoded mesh's attributes are from the input's: each decoded
// corner matched with its input corner through the encoder's vertex map
// (EncodeStats::new_index, empty when the order was kept), the largest
// difference over every corner (degrees between directions for normals).
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "attributes/corner_correspondence.h"
#include "gab/mesh/mesh.h"

namespace gab {
namespace testing_util {

inline double angle_degrees(const double* a, const double* b) {
  const double la = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  const double lb = std::sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
  if (!(la > 0) || !(lb > 0)) return 0;
  const double c = (a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) / (la * lb);
  return std::acos(std::min(1.0, std::max(-1.0, c))) * (180 / 3.14159265358979323846);
}

// The largest error of attribute `which` of `decoded` against `input`'s
// (same index: the decoder returns them in the input's order).
inline double largest_attribute_error(const Mesh& input, const Mesh& decoded, const std::vector<int32_t>& new_index,
                                      size_t which) {
  const MeshAttribute& a = input.attributes[which];
  const MeshAttribute& d = decoded.attributes[which];
  const size_t k = static_cast<size_t>(a.components);
  std::vector<int32_t> renamed(input.triangles.size());
  for (size_t i = 0; i < renamed.size(); ++i) {
    renamed[i] = new_index.empty() ? input.triangles[i] : new_index[input.triangles[i]];
  }
  std::vector<int32_t> input_corner;
  EXPECT_TRUE(match_corners(renamed, decoded.triangles, &input_corner).ok());
  if (input_corner.size() != decoded.triangles.size()) return INFINITY;
  double worst = 0;
  for (size_t c = 0; c < decoded.triangles.size(); ++c) {
    const int32_t ci = input_corner[c];
    const double* x = &a.values[k * static_cast<size_t>(a.per_corner() ? a.corners[ci] : input.triangles[ci])];
    const double* y = &d.values[k * static_cast<size_t>(d.per_corner() ? d.corners[c] : decoded.triangles[c])];
    if (a.kind == AttributeKind::kNormal) {
      worst = std::max(worst, angle_degrees(x, y));
    } else {
      for (size_t i = 0; i < k; ++i) worst = std::max(worst, std::fabs(x[i] - y[i]));
    }
  }
  return worst;
}

}  // namespace testing_util
}  // namespace gab
