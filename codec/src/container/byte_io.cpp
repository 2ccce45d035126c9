// Little-endian fixed-width fields and LEB128 varints for the .gab container.
#include "container/byte_io.h"

#include <cstring>

namespace gab {

void ByteWriter::u8(uint8_t v) { data_.push_back(v); }

void ByteWriter::u32(uint32_t v) {
  for (int i = 0; i < 4; ++i) data_.push_back(static_cast<uint8_t>(v >> (8 * i)));
}

void ByteWriter::u64(uint64_t v) {
  for (int i = 0; i < 8; ++i) data_.push_back(static_cast<uint8_t>(v >> (8 * i)));
}

void ByteWriter::f64(double v) {
  uint64_t bits;
  std::memcpy(&bits, &v, sizeof bits);
  u64(bits);
}

void ByteWriter::varint(uint64_t v) {
  while (v >= 0x80u) {
    data_.push_back(static_cast<uint8_t>(v | 0x80u));
    v >>= 7;
  }
  data_.push_back(static_cast<uint8_t>(v));
}

void ByteWriter::bytes(const uint8_t* data, size_t size) {
  if (size > 0) data_.insert(data_.end(), data, data + size);
}

void ByteWriter::patch_u32(size_t offset, uint32_t v) {
  // Contract: the 4 bytes were written earlier; out of range is a caller bug.
  if (offset > data_.size() || data_.size() - offset < 4) return;
  for (int i = 0; i < 4; ++i) data_[offset + i] = static_cast<uint8_t>(v >> (8 * i));
}

bool ByteReader::u8(uint8_t* v) {
  if (remaining() < 1) return false;
  *v = data_[pos_++];
  return true;
}

bool ByteReader::u32(uint32_t* v) {
  if (remaining() < 4) return false;
  uint32_t r = 0;
  for (int i = 0; i < 4; ++i) r |= static_cast<uint32_t>(data_[pos_ + i]) << (8 * i);
  pos_ += 4;
  *v = r;
  return true;
}

bool ByteReader::u64(uint64_t* v) {
  if (remaining() < 8) return false;
  uint64_t r = 0;
  for (int i = 0; i < 8; ++i) r |= static_cast<uint64_t>(data_[pos_ + i]) << (8 * i);
  pos_ += 8;
  *v = r;
  return true;
}

bool ByteReader::f64(double* v) {
  uint64_t bits;
  if (!u64(&bits)) return false;
  std::memcpy(v, &bits, sizeof bits);
  return true;
}

bool ByteReader::varint(uint64_t* v) {
  // Byte k carries bits 7k..7k+6. The tenth byte (k = 9) may only carry bit
  // 63, so it must be 0 or 1 (and it ends the varint). A last byte of 0 after
  // the first is a non-minimal encoding: rejected, so each value has exactly
  // one encoding (what the writer produces).
  uint64_t r = 0;
  for (int k = 0; k < 10; ++k) {
    if (pos_ + k >= size_) return false;
    const uint8_t byte = data_[pos_ + k];
    if (k == 9 && byte > 1) return false;
    r |= static_cast<uint64_t>(byte & 0x7Fu) << (7 * k);
    if ((byte & 0x80u) == 0) {
      if (k > 0 && byte == 0) return false;
      pos_ += k + 1;
      *v = r;
      return true;
    }
  }
  return false;
}

bool ByteReader::bytes(size_t size, const uint8_t** p) {
  if (remaining() < size) return false;
  *p = data_ + pos_;
  pos_ += size;
  return true;
}

}  // namespace gab
