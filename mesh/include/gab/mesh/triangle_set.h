// A triangle list as a set of oriented triangles: what stays when the order
// of the triangles and which corner comes first are forgotten (a reordered
// .gab file keeps exactly this). Each triangle is rotated to start at its
// smallest vertex, orientation kept, and the list is sorted.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

namespace gab {

// O(T log T).
std::vector<std::array<int32_t, 3>> oriented_triangle_set(const std::vector<int32_t>& triangles);

}  // namespace gab
