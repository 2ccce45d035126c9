// CRC-32 against the published check value and its chaining contract.
#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <vector>

#include "container/crc32.h"

namespace gab {
namespace {

const uint8_t* bytes_of(const char* s) { return reinterpret_cast<const uint8_t*>(s); }

// Bit-at-a-time CRC straight from the definition (no table): the reference.
uint32_t crc32_bitwise(const uint8_t* data, size_t size) {
  uint32_t r = 0xFFFFFFFFu;
  for (size_t i = 0; i < size; ++i) {
    r ^= data[i];
    for (int k = 0; k < 8; ++k) r = (r >> 1) ^ (0xEDB88320u & (0u - (r & 1u)));
  }
  return ~r;
}

TEST(Crc32, KnownVectors) {
  EXPECT_EQ(crc32(bytes_of("123456789"), 9), 0xCBF43926u);
  EXPECT_EQ(crc32(nullptr, 0), 0u);
  EXPECT_EQ(crc32(bytes_of("a"), 1), 0xE8B7BE43u);
  const char* fox = "The quick brown fox jumps over the lazy dog";
  EXPECT_EQ(crc32(bytes_of(fox), std::strlen(fox)), 0x414FA339u);
}

TEST(Crc32, MatchesBitwiseDefinition) {
  std::mt19937 rng(7);
  for (size_t size : {1u, 2u, 3u, 7u, 64u, 1000u}) {
    std::vector<uint8_t> data(size);
    for (auto& b : data) b = static_cast<uint8_t>(rng());
    EXPECT_EQ(crc32(data.data(), size), crc32_bitwise(data.data(), size)) << size;
  }
}

TEST(Crc32, ChainsAcrossSplits) {
  std::mt19937 rng(11);
  std::vector<uint8_t> data(257);
  for (auto& b : data) b = static_cast<uint8_t>(rng());
  const uint32_t whole = crc32(data.data(), data.size());
  for (size_t cut = 0; cut <= data.size(); ++cut) {
    const uint32_t first = crc32(data.data(), cut);
    ASSERT_EQ(crc32(data.data() + cut, data.size() - cut, first), whole) << cut;
  }
  // Continuing with nothing changes nothing; a changed byte changes the CRC.
  EXPECT_EQ(crc32(data.data(), 0, whole), whole);
  data[100] ^= 1;
  EXPECT_NE(crc32(data.data(), data.size()), whole);
}

}  // namespace
}  // namespace gab
