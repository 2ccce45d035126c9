// Which input corner each corner of the coded triangles is: the connectivity
// coder returns the triangles as a set, in its own order and each from a
// corner of its choosing, so per-corner attributes must follow it. Internal
// to the codec.
#pragma once

#include <cstdint>
#include <vector>

#include "gab/status.h"

namespace gab {

// For each corner of `coded`, the corner of `input` it is: both the same
// triangles (vertex triples) up to order and rotation, in one numbering.
// kInvalidArgument if they are not (a bug: the coder keeps every triangle). O(T log T).
Status match_corners(const std::vector<int32_t>& input, const std::vector<int32_t>& coded,
                     std::vector<int32_t>* input_corner);

}  // namespace gab
