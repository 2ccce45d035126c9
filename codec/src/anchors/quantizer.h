// Uniform scalar quantization of vertex coordinates over the bounding box
// (the grid whose origin and step a .gab header stores: gab_format.h): q bits
// per coordinate, one step for all three axes (the longest side over
// 2^q - 1), so the quantization error is isotropic and the 3D error a user
// asks for maps to one grid.
//
// Also the codec's prediction rounding, which makes residual coding safe
// without bit-identical floating point: see round_prediction.
#pragma once

#include <cstdint>

namespace gab {

struct Quantizer {
  double min[3] = {0, 0, 0};  // the box's low corner
  double step = 0.0;          // grid spacing; 0 for a box of zero size
  int32_t max_index = 0;      // 2^q - 1

  // The grid for coordinates in [min, max] per axis at q bits (1 <= q <= 30).
  static Quantizer for_box(const double min[3], const double max[3], int bits);

  // The grid a file stores: origin, step and q.
  static Quantizer from_grid(const double min[3], double step, int bits);

  // Nearest grid index of coordinate v on axis c, clamped to [0, max_index].
  int32_t quantize(double v, int c) const;
  // The grid point: min[c] + index * step (exactly this expression on both
  // sides of the codec, so coefficients agree bit for bit).
  double dequantize(int32_t index, int c) const { return min[c] + index * step; }
  // (v - min[c]) / step clamped to [0, max_index]; 0 when step is 0.
  double scaled(double v, int c) const;
};

// Rounding a decoder-side prediction to the grid, made robust to the tiny
// floating-point differences between encoder and decoder (other SIMD level,
// other update/refactorization path, other machine): when the encoder's
// scaled prediction lies within kPredictionGuard of a rounding boundary
// (a half-integer), it says so in one adaptive flag and sends the direction
// it rounded, so both sides agree on the integer whenever their predictions
// differ by less than the guard. The flag is almost always 0 and costs ~0.01
// bits.
constexpr double kPredictionGuard = 1.0 / 1024;

// True if the scaled prediction s is within `guard` of a half-integer.
bool prediction_is_near_tie(double s, double guard = kPredictionGuard);
// The encoder's rounding of s; near a tie also `round_up` (the direction).
int64_t round_prediction(double s, bool* round_up);
// The decoder's integer for its own s, given the encoder's flag/direction.
int64_t resolve_prediction(double s, bool near_tie, bool round_up);

}  // namespace gab
