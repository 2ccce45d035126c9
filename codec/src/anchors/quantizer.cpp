#include "anchors/quantizer.h"

#include <algorithm>
#include <cmath>

namespace gab {

Quantizer Quantizer::for_box(const double min[3], const double max[3], int bits) {
  double extent = 0.0;
  for (int c = 0; c < 3; ++c) extent = std::max(extent, max[c] - min[c]);
  const double levels = static_cast<double>((int64_t{1} << bits) - 1);
  return from_grid(min, extent > 0 ? extent / levels : 0.0, bits);
}

Quantizer Quantizer::from_grid(const double min[3], double step, int bits) {
  Quantizer q;
  for (int c = 0; c < 3; ++c) q.min[c] = min[c];
  q.step = step;
  q.max_index = static_cast<int32_t>((int64_t{1} << bits) - 1);
  return q;
}

double Quantizer::scaled(double v, int c) const {
  if (!(step > 0)) return 0.0;
  const double s = (v - min[c]) / step;
  if (!(s > 0)) return 0.0;  // also NaN
  return std::min(s, static_cast<double>(max_index));
}

int32_t Quantizer::quantize(double v, int c) const {
  return static_cast<int32_t>(std::floor(scaled(v, c) + 0.5));
}

bool prediction_is_near_tie(double s, double guard) {
  const double frac = s - std::floor(s);
  return std::fabs(frac - 0.5) < guard;
}

int64_t round_prediction(double s, bool* round_up) {
  const double f = std::floor(s);
  *round_up = s - f >= 0.5;
  return static_cast<int64_t>(f) + (*round_up ? 1 : 0);
}

int64_t resolve_prediction(double s, bool near_tie, bool round_up) {
  // Near a tie both sides' s lie within the guard of the same half-integer
  // k + 1/2, so floor(s) = k on both; elsewhere plain rounding agrees.
  if (near_tie) return static_cast<int64_t>(std::floor(s)) + (round_up ? 1 : 0);
  return static_cast<int64_t>(std::floor(s + 0.5));
}

}  // namespace gab
