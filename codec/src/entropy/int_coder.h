// Adaptive integer models over the range coder: an Elias-gamma-like code
// whose bit-length symbol and leading mantissa bits are adaptive (per
// context), so small values that recur cost close to their entropy.
//
// A value v > 0 with bit length L (2^(L-1) <= v < 2^L) is coded as L, then
// the L-1 bits below its leading 1: the top two adaptively (models chosen by
// L and the bit above), the rest raw. L in 0..32 goes through a bit tree:
// one model for "L == 32", then a 5-bit tree for 0..31, so a decoder cannot
// produce L > 32 whatever the input. Cost per value: O(L).
#pragma once

#include <cstdint>
#include <vector>

#include "entropy/range_coder.h"

namespace gab {

// Unsigned 32-bit values. `contexts` (>= 1) independent sets of statistics;
// the caller picks one per value (for instance from a neighbour's
// magnitude). A context out of [0, contexts) is clamped into it.
// `adapt_shift`: how fast the models adapt (BitModel::shift).
class UIntCoder {
 public:
  explicit UIntCoder(int contexts = 1, int adapt_shift = BitModel::kAdaptShift);
  void encode(RangeEncoder* enc, uint32_t value, int context = 0);
  // Any input decodes to some uint32 (garbage in, garbage out, no UB).
  uint32_t decode(RangeDecoder* dec, int context = 0);
  int contexts() const;

 private:
  // Per context: kLengthModels for the bit length, then 3 per bit length
  // (the first mantissa bit, the second given the first).
  static constexpr int kLengthModels = 32;
  static constexpr int kModelsPerContext = kLengthModels + 3 * 33;
  BitModel* context_models(int context);
  std::vector<BitModel> models_;
  int contexts_;
};

// Signed values: zero flag, sign, |v| - 1 through a UIntCoder, all per
// context. Every int32 round trips (INT32_MIN included); a garbage magnitude
// beyond the int32 range decodes saturated to INT32_MAX / INT32_MIN.
class SIntCoder {
 public:
  explicit SIntCoder(int contexts = 1, int adapt_shift = BitModel::kAdaptShift);
  void encode(RangeEncoder* enc, int32_t value, int context = 0);
  int32_t decode(RangeDecoder* dec, int context = 0);

 private:
  int clamp(int context) const;
  std::vector<BitModel> zero_, sign_;
  UIntCoder magnitude_;
};

}  // namespace gab
