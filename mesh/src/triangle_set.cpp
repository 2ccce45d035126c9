#include "gab/mesh/triangle_set.h"

#include <algorithm>

namespace gab {

std::vector<std::array<int32_t, 3>> oriented_triangle_set(const std::vector<int32_t>& triangles) {
  std::vector<std::array<int32_t, 3>> set;
  set.reserve(triangles.size() / 3);
  for (size_t i = 0; i + 2 < triangles.size(); i += 3) {
    std::array<int32_t, 3> t = {triangles[i], triangles[i + 1], triangles[i + 2]};
    std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    set.push_back(t);
  }
  std::sort(set.begin(), set.end());
  return set;
}

}  // namespace gab
