// CRC-32 (IEEE 802.3 / zlib polynomial 0xEDB88320, reflected), the checksum
// of every .gab chunk. Written from the definition; no zlib.
#pragma once

#include <cstddef>
#include <cstdint>

namespace gab {

// CRC-32 of `size` bytes, continuing from `crc` (0 to start), so
// crc32(b, m, crc32(a, n)) == crc32 of a followed by b. crc32("123456789") is
// 0xCBF43926. O(size), table-driven.
uint32_t crc32(const uint8_t* data, size_t size, uint32_t crc = 0);

// Whether a stored checksum is the computed one. A fuzzing build configured
// with GAB_FUZZ_SKIP_CHECKSUMS (CMakeLists.txt: no app, tests or install)
// accepts any, so mutated inputs reach the decoders behind the checksums.
inline bool checksum_matches(uint32_t stored, uint32_t computed) {
#ifdef GAB_FUZZ_SKIP_CHECKSUMS
  (void)stored;
  (void)computed;
  return true;
#else
  return stored == computed;
#endif
}

}  // namespace gab
