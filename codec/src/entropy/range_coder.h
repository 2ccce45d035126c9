// A binary adaptive range coder (the arithmetic-coding family of Rissanen,
// Martin 1979 "range encoding", in the carry-less-by-cache form popularized
// by LZMA), written from the descriptions. Every symbol of the .gab format
// is coded through it, bit by bit, with adaptive probabilities.
//
// State: a 32-bit range, renormalized (one byte out / in) whenever it drops
// below 2^24; a bit with P(0) = p0 / 2^16 splits the range at
// bound = (range >> 16) * p0. Carries are resolved with a cached byte plus a
// count of pending 0xFF bytes, so output is written strictly in order.
//
// Stream length: the encoder writes exactly one byte per renormalization
// plus 4 flush bytes, and the decoder reads 4 bytes at construction plus one
// per renormalization; the two perform the same renormalizations, so a
// decoder that decodes every coded symbol reads every byte and no more.
//
// Decoder contract on untrusted input: it never reads outside its buffer.
// Past the end it behaves as if the input continued with zero bytes and
// sets overrun(); callers treat an overrun as a corrupt stream. Garbage in
// gives garbage bits out, never undefined behaviour.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace gab {

// Probability that the next bit is 0, in units of 2^-16, adapting after
// every coded bit: p0 += (kMax - p0) >> kAdaptShift after a 0,
// p0 -= (p0 - kMin) >> kAdaptShift after a 1. Starts at 1/2. p0 never leaves
// [kMin, kMax], so neither side of a split can vanish (only the coder
// changes p0; a hand-set value outside that interval is a caller bug).
//
// kAdaptShift = 5 (a memory of about 32 bits), chosen over 4 by measuring
// both on the codec's own sources: 5 costs 1.2% over the entropy of fair
// bits (4: 2.5%), 2.7% at P(1) = 0.1 (4: 6.1%), 1.0-2.6% on geometric
// integers (4: 1.7-4.6%), 1.2-1.7% over log2 C(u, b) on dense subsets (4:
// 2.5%), and 0.8% less on the connectivity of the shared meshes (6 is no
// better there). The price of adaptation is about 0.0115 bit per coded bit
// whatever its probability, so very skewed stationary bits pay most in
// relative terms (+10% at P(1) = 0.02).
//
// A model may adapt faster or slower than that default (`shift`, 1..12):
// the codec's position residuals follow an error level that falls chunk by
// chunk and code 4.5% smaller with shift 4 (measured on camel-head and
// horse at 1e-3), while a rare, stationary flag wants a long memory.
struct BitModel {
  static constexpr int kAdaptShift = 5;
  static constexpr uint32_t kMin = 32;
  static constexpr uint32_t kMax = 65536 - 32;
  BitModel() = default;
  explicit BitModel(int adapt_shift) : shift(static_cast<uint8_t>(adapt_shift)) {}
  uint16_t p0 = 1u << 15;
  uint8_t shift = kAdaptShift;
};

class RangeEncoder {
 public:
  // One bit (0 or nonzero) with the model's probability; updates the model. O(1).
  void encode(BitModel* model, int bit);
  // The low `nbits` (0..32) bits of `value`, most significant first, at
  // probability 1/2 each (exactly 1 bit of output per bit). O(nbits).
  void encode_raw(uint32_t value, int nbits);
  // Flushes the state (4 bytes) and returns all the bytes; the encoder is
  // then spent. O(1) amortized.
  std::vector<uint8_t> finish();

 private:
  void shift_low();
  uint64_t low_ = 0;             // 33 bits: bit 32 is a carry into the cached byte
  uint32_t range_ = 0xFFFFFFFFu;
  uint8_t cache_ = 0;            // last byte not yet written (a carry may still change it)
  uint64_t cache_size_ = 1;      // cache_ plus the 0xFF bytes pending behind it
  std::vector<uint8_t> out_;
};

// The most decisions (coded bits) a stream of `bytes` bytes can hold: a
// decision narrows the range by at least -log2(kMax / 2^16) = 0.000704 bit
// and the decoder reads a byte per 8 bits of narrowing, so at most 11,354
// decisions a byte, the 4 bytes read first included. What bounds the work a
// forged count can ask of a decoder before its stream overruns.
constexpr uint64_t kMaxDecisionsPerByte = 11354;
inline uint64_t max_decisions(size_t bytes) { return (static_cast<uint64_t>(bytes) + 1) * kMaxDecisionsPerByte; }

class RangeDecoder {
 public:
  // Reads the first 4 bytes. `data` must outlive the decoder.
  RangeDecoder(const uint8_t* data, size_t size);
  // Mirrors RangeEncoder::encode with a model in the same state. O(1).
  int decode(BitModel* model);
  // Mirrors RangeEncoder::encode_raw; nbits is clamped to 0..32. O(nbits).
  uint32_t decode_raw(int nbits);
  // True once the decoder needed a byte beyond its input. Never true while
  // decoding a complete stream (up to and including its last symbol); true
  // by then for a stream cut short by any number of bytes, because the
  // decoder, reading the same bytes, asks for every byte the encoder wrote.
  bool overrun() const { return overrun_; }
  // Bytes of the input read so far. After the last symbol of a complete
  // stream this equals the stream's size; a smaller value means trailing data.
  size_t bytes_consumed() const { return pos_; }
  // The input's size in bytes.
  size_t size() const { return size_; }

 private:
  uint8_t next_byte();
  void normalize();
  const uint8_t* data_;
  size_t size_;
  size_t pos_ = 0;
  uint32_t range_ = 0xFFFFFFFFu;
  uint32_t code_ = 0;  // the input's value minus the interval's low end
  bool overrun_ = false;
};

}  // namespace gab
