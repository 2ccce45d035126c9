#include "connectivity/connectivity_hash.h"

namespace gab {

uint64_t connectivity_hash(int32_t num_vertices, const std::vector<int32_t>& triangles) {
  uint64_t h = 0xcbf29ce484222325ull;  // FNV-1a 64 offset basis
  auto feed = [&h](int32_t value) {
    const uint32_t u = static_cast<uint32_t>(value);
    for (int i = 0; i < 4; ++i) {
      h ^= (u >> (8 * i)) & 0xFFu;
      h *= 0x100000001b3ull;  // FNV-1a 64 prime
    }
  };
  feed(num_vertices);
  feed(static_cast<int32_t>(triangles.size() / 3));
  for (const int32_t index : triangles) feed(index);
  return h;
}

}  // namespace gab
