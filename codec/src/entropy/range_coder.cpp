// Binary adaptive range coder: see range_coder.h for the state and the
// stream-length argument behind overrun().
#include "entropy/range_coder.h"

#include <utility>

namespace gab {
namespace {

constexpr uint32_t kTop = 1u << 24;  // renormalize below this range

inline void adapt(BitModel* model, int bit) {
  const uint32_t p0 = model->p0;
  if (bit == 0) {
    model->p0 = static_cast<uint16_t>(p0 + ((BitModel::kMax - p0) >> model->shift));
  } else {
    model->p0 = static_cast<uint16_t>(p0 - ((p0 - BitModel::kMin) >> model->shift));
  }
}

}  // namespace

// Moves the top byte of low_ out. A byte below 0xFF can absorb any later
// carry, so the cached byte and the 0xFF run behind it become final (plus
// the carry in bit 32, which turns the 0xFFs into 0x00s). A 0xFF byte might
// still receive a carry: it only lengthens the pending run.
void RangeEncoder::shift_low() {
  if (low_ < 0xFF000000u || low_ >= (uint64_t{1} << 32)) {
    const uint8_t carry = static_cast<uint8_t>(low_ >> 32);
    uint8_t byte = cache_;
    do {
      out_.push_back(static_cast<uint8_t>(byte + carry));
      byte = 0xFF;
    } while (--cache_size_ != 0);
    cache_ = static_cast<uint8_t>(low_ >> 24);
  }
  ++cache_size_;
  low_ = (low_ & 0x00FFFFFFu) << 8;
}

void RangeEncoder::encode(BitModel* model, int bit) {
  const uint32_t bound = (range_ >> 16) * model->p0;
  if (bit == 0) {
    range_ = bound;
  } else {
    low_ += bound;
    range_ -= bound;
  }
  adapt(model, bit != 0);
  while (range_ < kTop) {
    range_ <<= 8;
    shift_low();
  }
}

void RangeEncoder::encode_raw(uint32_t value, int nbits) {
  if (nbits > 32) nbits = 32;
  for (int i = nbits - 1; i >= 0; --i) {
    range_ >>= 1;
    if ((value >> i) & 1u) low_ += range_;
    while (range_ < kTop) {
      range_ <<= 8;
      shift_low();
    }
  }
}

std::vector<uint8_t> RangeEncoder::finish() {
  // Four shifts move the 32 bits of low_ into the cache; the fifth writes
  // the last of them. The first byte ever written is the initial cache
  // byte, always 0 (the interval starts inside [0, 2^32), so nothing can
  // carry into it): it is dropped, and the decoder starts one byte later.
  for (int i = 0; i < 5; ++i) shift_low();
  out_.erase(out_.begin());
  return std::move(out_);
}

RangeDecoder::RangeDecoder(const uint8_t* data, size_t size) : data_(data), size_(size) {
  for (int i = 0; i < 4; ++i) code_ = (code_ << 8) | next_byte();
}

uint8_t RangeDecoder::next_byte() {
  if (pos_ < size_) return data_[pos_++];
  overrun_ = true;
  return 0;
}

void RangeDecoder::normalize() {
  while (range_ < kTop) {
    range_ <<= 8;
    code_ = (code_ << 8) | next_byte();
  }
}

int RangeDecoder::decode(BitModel* model) {
  const uint32_t bound = (range_ >> 16) * model->p0;
  int bit;
  if (code_ < bound) {
    range_ = bound;
    bit = 0;
  } else {
    code_ -= bound;
    range_ -= bound;
    bit = 1;
  }
  adapt(model, bit);
  normalize();
  return bit;
}

uint32_t RangeDecoder::decode_raw(int nbits) {
  if (nbits > 32) nbits = 32;
  uint32_t value = 0;
  for (int i = 0; i < nbits; ++i) {
    range_ >>= 1;
    uint32_t bit = 0;
    if (code_ >= range_) {
      code_ -= range_;
      bit = 1;
    }
    value = (value << 1) | bit;
    normalize();
  }
  return value;
}

}  // namespace gab
