// CRC-32, reflected form of the IEEE 802.3 polynomial (0x04C11DB7, bit-
// reversed 0xEDB88320): register preset to all ones, bytes fed low bit
// first, result complemented. One 256-entry table, one byte per step.
#include "container/crc32.h"

#include <array>

namespace gab {
namespace {

// table[b] = the register after shifting the 8 bits of b through it.
std::array<uint32_t, 256> make_crc_table() {
  std::array<uint32_t, 256> table{};
  for (uint32_t b = 0; b < 256; ++b) {
    uint32_t r = b;
    for (int bit = 0; bit < 8; ++bit) r = (r & 1u) ? (r >> 1) ^ 0xEDB88320u : r >> 1;
    table[b] = r;
  }
  return table;
}

const std::array<uint32_t, 256> kCrcTable = make_crc_table();

}  // namespace

uint32_t crc32(const uint8_t* data, size_t size, uint32_t crc) {
  // Undo the previous final complement so that calls chain.
  uint32_t r = ~crc;
  for (size_t i = 0; i < size; ++i) r = kCrcTable[(r ^ data[i]) & 0xFFu] ^ (r >> 8);
  return ~r;
}

}  // namespace gab
