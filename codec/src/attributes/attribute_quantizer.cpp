#include "attributes/attribute_quantizer.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace gab {

AttributeQuantizer AttributeQuantizer::fit(const MeshAttribute& a, int bits) {
  AttributeQuantizer q;
  q.kind = a.kind;
  q.components = a.components;
  q.bits = bits;
  if (q.lattice()) return q;
  const size_t k = static_cast<size_t>(a.components);
  double lo[4] = {0, 0, 0, 0}, hi[4] = {0, 0, 0, 0};
  for (size_t c = 0; c < k; ++c) {
    lo[c] = hi[c] = a.values.empty() ? 0.0 : a.values[c];
  }
  for (size_t i = 0; i < a.values.size(); ++i) {
    lo[i % k] = std::min(lo[i % k], a.values[i]);
    hi[i % k] = std::max(hi[i % k], a.values[i]);
  }
  double span = 0;
  for (size_t c = 0; c < k; ++c) {
    q.origin[c] = lo[c];
    span = std::max(span, hi[c] - lo[c]);
  }
  if (is_integer_type(a.type)) {
    // Exact: step 1 and the bits the span needs, unless it needs more than
    // a grid has (a 32-bit property spanning over 2^31 - 1).
    q.step = 1;
    q.bits = 1;
    while (q.bits < kMaxGridBits && static_cast<double>(q.max_index()) < span) ++q.bits;
    while (static_cast<double>(q.max_index()) * q.step < span) q.step *= 2;
    return q;
  }
  q.step = span > 0 ? span / static_cast<double>(q.max_index()) : 0.0;
  return q;
}

void project_to_lattice(const int64_t p[3], int32_t r, int32_t out[3]) {
  const int64_t s = std::llabs(p[0]) + std::llabs(p[1]) + std::llabs(p[2]);
  // |p_c| * r / s rounded half up, and what the rounding left over (in
  // units of 1 / s): positive when rounded down.
  int64_t m[3], left[3], sum = 0;
  for (int c = 0; c < 3; ++c) {
    const int64_t a = std::llabs(p[c]) * r;
    m[c] = (2 * a + s) / (2 * s);
    left[c] = a - m[c] * s;
    sum += m[c];
  }
  while (sum != r) {
    // Too little: grow the component rounded furthest down; too much:
    // shrink the one rounded furthest up (never below zero). Ties go to the
    // lowest axis.
    int best = -1;
    for (int c = 0; c < 3; ++c) {
      if (sum > r && m[c] == 0) continue;
      if (best < 0 || (sum < r ? left[c] > left[best] : left[c] < left[best])) best = c;
    }
    const int64_t d = sum < r ? 1 : -1;
    m[best] += d;
    left[best] -= d * s;
    sum += d;
  }
  for (int c = 0; c < 3; ++c) out[c] = static_cast<int32_t>(p[c] < 0 ? -m[c] : m[c]);
}

void AttributeQuantizer::quantize(const double* values, int32_t* q) const {
  if (lattice()) {
    // The direction scaled so that the sum of magnitudes is about 2^40: an
    // integer vector precise to far below a lattice step.
    const double s = std::fabs(values[0]) + std::fabs(values[1]) + std::fabs(values[2]);
    if (!(s > 0)) {
      q[0] = q[1] = 0;
      q[2] = radius();
      return;
    }
    int64_t p[3];
    for (int c = 0; c < 3; ++c) p[c] = std::llround(values[c] / s * 1099511627776.0);
    project_to_lattice(p, radius(), q);
    return;
  }
  for (int c = 0; c < components; ++c) {
    double x = step > 0 ? std::floor((values[c] - origin[c]) / step + 0.5) : 0.0;
    x = std::min(std::max(x, 0.0), static_cast<double>(max_index()));
    q[c] = static_cast<int32_t>(x);
  }
}

void AttributeQuantizer::dequantize(const int32_t* q, double* values) const {
  if (lattice()) {
    const double x = q[0], y = q[1], z = q[2];
    const double length = std::sqrt(x * x + y * y + z * z);
    values[0] = x / length;
    values[1] = y / length;
    values[2] = z / length;
    return;
  }
  for (int c = 0; c < components; ++c) values[c] = origin[c] + static_cast<double>(q[c]) * step;
}

}  // namespace gab
