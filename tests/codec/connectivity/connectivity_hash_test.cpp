// The geometry-only hash against FNV-1a's definition, and that it sees
// every change of the triangles.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "connectivity/connectivity_hash.h"

namespace gab {
namespace {

// A w x h grid of quads, two triangles each, in row order.
std::vector<int32_t> grid(int w, int h) {
  std::vector<int32_t> t;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const int32_t a = y * (w + 1) + x, b = a + 1, c = a + w + 1, d = c + 1;
      t.insert(t.end(), {a, b, d, a, d, c});
    }
  }
  return t;
}

// FNV-1a, 64 bits, from its definition: h = offset basis; for each byte,
// h = (h xor byte) * prime.
uint64_t fnv1a(const std::vector<uint8_t>& bytes) {
  uint64_t h = 14695981039346656037ull;
  for (uint8_t b : bytes) h = (h ^ b) * 1099511628211ull;
  return h;
}

TEST(ConnectivityHash, FollowsFnv1aDefinition) {
  // The published FNV-1a 64 test vectors anchor the reference.
  EXPECT_EQ(fnv1a({}), 0xcbf29ce484222325ull);
  EXPECT_EQ(fnv1a({'a'}), 0xaf63dc4c8601ec8cull);
  // n = 3, one triangle (2, 0, 1): every field as 4 little-endian bytes.
  const std::vector<uint8_t> bytes = {3, 0, 0, 0, 1, 0, 0, 0, 2, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0};
  EXPECT_EQ(connectivity_hash(3, {2, 0, 1}), fnv1a(bytes));
  EXPECT_EQ(connectivity_hash(0, {}), fnv1a({0, 0, 0, 0, 0, 0, 0, 0}));
  // Index 0x01020304 shows the byte order.
  EXPECT_EQ(connectivity_hash(0x7FFFFFFF, {0x01020304, 0, 0}),
            fnv1a({0xFF, 0xFF, 0xFF, 0x7F, 1, 0, 0, 0, 4, 3, 2, 1, 0, 0, 0, 0, 0, 0, 0, 0}));
}

TEST(ConnectivityHash, SeesEveryChange) {
  const std::vector<int32_t> g = grid(5, 4);
  const int32_t n = 6 * 5;
  const uint64_t h = connectivity_hash(n, g);
  EXPECT_NE(connectivity_hash(n + 1, g), h);
  for (size_t i = 0; i < g.size(); ++i) {
    std::vector<int32_t> changed = g;
    changed[i] = (changed[i] + 1) % n;
    ASSERT_NE(connectivity_hash(n, changed), h) << i;
  }
  std::vector<int32_t> rotated = g;
  std::rotate(rotated.begin(), rotated.begin() + 1, rotated.begin() + 3);  // same triangle, other first corner
  EXPECT_NE(connectivity_hash(n, rotated), h);
  std::vector<int32_t> fewer(g.begin(), g.end() - 3);
  EXPECT_NE(connectivity_hash(n, fewer), h);
}

}  // namespace
}  // namespace gab
