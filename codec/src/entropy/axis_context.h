// The context both chunk coders use for one anchor's three signed values
// (position residuals, refinement corrections): the bit length, capped at
// buckets - 1, of the largest value already coded for this anchor (for
// axis 0, the previous anchor's largest), so the statistics follow the local
// error level. Internal to the codec.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstdlib>

namespace gab {

// The largest magnitude of an anchor's three values.
inline int32_t max_magnitude(const int32_t v[3]) { return std::max({std::abs(v[0]), std::abs(v[1]), std::abs(v[2])}); }

// Context of axis c (0..3 * buckets - 1) given the values of axes < c.
inline int axis_context(int c, const int32_t v[3], int32_t previous_max, int buckets) {
  int32_t m = previous_max;
  if (c == 1) m = std::abs(v[0]);
  if (c == 2) m = std::max(std::abs(v[0]), std::abs(v[1]));
  int bucket = 0;
  while (m > 0 && bucket < buckets - 1) {
    m >>= 1;
    ++bucket;
  }
  return c * buckets + bucket;
}

}  // namespace gab
