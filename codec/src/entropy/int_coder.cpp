// Adaptive Elias-gamma-like integer coding (see int_coder.h).
#include "entropy/int_coder.h"

#include <algorithm>
#include <limits>

namespace gab {
namespace {

int bit_length(uint32_t v) {
  int length = 0;
  while (v != 0) {
    ++length;
    v >>= 1;
  }
  return length;
}

// The top two mantissa bits are adaptive, the rest raw.
constexpr int kAdaptiveMantissaBits = 2;

}  // namespace

UIntCoder::UIntCoder(int contexts, int adapt_shift)
    : models_(static_cast<size_t>(std::max(contexts, 1)) * kModelsPerContext, BitModel(adapt_shift)),
      contexts_(std::max(contexts, 1)) {}

int UIntCoder::contexts() const { return contexts_; }

BitModel* UIntCoder::context_models(int context) {
  context = std::min(std::max(context, 0), contexts_ - 1);
  return models_.data() + static_cast<size_t>(context) * kModelsPerContext;
}

void UIntCoder::encode(RangeEncoder* enc, uint32_t value, int context) {
  BitModel* length_models = context_models(context);
  BitModel* mantissa_models = length_models + kLengthModels;
  const int length = bit_length(value);

  // Length: models[0] says "32"; otherwise a 5-bit tree over nodes 1..31.
  enc->encode(&length_models[0], length == 32);
  if (length != 32) {
    int node = 1;
    for (int i = 4; i >= 0; --i) {
      const int bit = (length >> i) & 1;
      enc->encode(&length_models[node], bit);
      node = 2 * node + bit;
    }
  }

  // Mantissa: bits length-2 .. 0 (none for length <= 1).
  int node = 0;  // 0: first bit; 1 + b: second bit after first bit b
  for (int i = length - 2; i >= 0; --i) {
    const int bit = (value >> i) & 1;
    if (length - 2 - i < kAdaptiveMantissaBits) {
      enc->encode(&mantissa_models[3 * length + node], bit);
      node = 1 + bit;
    } else {
      enc->encode_raw(value, i + 1);  // the remaining i + 1 low bits
      break;
    }
  }
}

uint32_t UIntCoder::decode(RangeDecoder* dec, int context) {
  BitModel* length_models = context_models(context);
  BitModel* mantissa_models = length_models + kLengthModels;

  int length = 32;
  if (!dec->decode(&length_models[0])) {
    int node = 1;
    for (int i = 0; i < 5; ++i) node = 2 * node + dec->decode(&length_models[node]);
    length = node - 32;  // node is in [32, 63]
  }
  if (length == 0) return 0;

  uint32_t value = 1;
  int node = 0;
  for (int i = length - 2; i >= 0; --i) {
    if (length - 2 - i < kAdaptiveMantissaBits) {
      const int bit = dec->decode(&mantissa_models[3 * length + node]);
      value = (value << 1) | static_cast<uint32_t>(bit);
      node = 1 + bit;
    } else {
      // i + 1 <= 29 raw bits under the (at most 3) bits decoded so far.
      value = (value << (i + 1)) | dec->decode_raw(i + 1);
      break;
    }
  }
  return value;
}

SIntCoder::SIntCoder(int contexts, int adapt_shift)
    : zero_(static_cast<size_t>(std::max(contexts, 1)), BitModel(adapt_shift)),
      sign_(static_cast<size_t>(std::max(contexts, 1)), BitModel(adapt_shift)),
      magnitude_(contexts, adapt_shift) {}

int SIntCoder::clamp(int context) const {
  return std::min(std::max(context, 0), static_cast<int>(zero_.size()) - 1);
}

void SIntCoder::encode(RangeEncoder* enc, int32_t value, int context) {
  context = clamp(context);
  enc->encode(&zero_[context], value == 0);
  if (value == 0) return;
  enc->encode(&sign_[context], value < 0);
  // |v| - 1 in [0, 2^31 - 1], computed without overflowing int32.
  const int64_t magnitude = value < 0 ? -static_cast<int64_t>(value) : value;
  magnitude_.encode(enc, static_cast<uint32_t>(magnitude - 1), context);
}

int32_t SIntCoder::decode(RangeDecoder* dec, int context) {
  context = clamp(context);
  if (dec->decode(&zero_[context])) return 0;
  const bool negative = dec->decode(&sign_[context]) != 0;
  const int64_t magnitude = int64_t{magnitude_.decode(dec, context)} + 1;
  constexpr int64_t kMax = std::numeric_limits<int32_t>::max();
  if (negative) return static_cast<int32_t>(-std::min(magnitude, kMax + 1));
  return static_cast<int32_t>(std::min(magnitude, kMax));
}

}  // namespace gab
