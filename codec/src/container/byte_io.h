// Little-endian byte writer and a bounds-checked reader for the .gab
// container (header fields, chunk lengths). The reader never reads past its
// end: every getter returns false instead, leaving the output and the
// position untouched. Every call is O(1), bytes() O(size).
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace gab {

class ByteWriter {
 public:
  void u8(uint8_t v);
  void u32(uint32_t v);
  void u64(uint64_t v);
  void f64(double v);           // IEEE-754 bits, little-endian
  void varint(uint64_t v);      // LEB128: 7 bits per byte, low first
  void bytes(const uint8_t* data, size_t size);
  void patch_u32(size_t offset, uint32_t v);  // overwrite 4 bytes written earlier (ignored if out of range)

  size_t size() const { return data_.size(); }
  const std::vector<uint8_t>& data() const { return data_; }
  std::vector<uint8_t> take() { return std::move(data_); }

 private:
  std::vector<uint8_t> data_;
};

class ByteReader {
 public:
  ByteReader(const uint8_t* data, size_t size) : data_(data), size_(size) {}

  bool u8(uint8_t* v);
  bool u32(uint32_t* v);
  bool u64(uint64_t* v);
  bool f64(double* v);
  // At most 10 bytes; false on a truncated, over-long (> 64 bits) or
  // non-minimal (last byte 0 after the first) varint. O(1).
  bool varint(uint64_t* v);
  // Points *p at the next `size` bytes (inside the reader's buffer, no copy) and skips them.
  bool bytes(size_t size, const uint8_t** p);

  size_t offset() const { return pos_; }
  size_t remaining() const { return size_ - pos_; }

 private:
  const uint8_t* data_;
  size_t size_;
  size_t pos_ = 0;
};

}  // namespace gab
