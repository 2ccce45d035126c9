// The connectivity block: exact round trips (order and orientation) on
// generated and real meshes, the decoder's errors on corrupt input, and the
// FNV-1a hash against its definition.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "connectivity/connectivity_coder.h"
#include "gab/mesh/mesh_io.h"

namespace gab {
namespace {

void expect_round_trip(int32_t n, const std::vector<int32_t>& triangles, const std::string& what) {
  const std::vector<uint8_t> bytes = encode_connectivity(n, triangles);
  std::vector<int32_t> decoded = {1, 2, 3};  // replaced by the decoder
  const int32_t count = static_cast<int32_t>(triangles.size() / 3);
  const Status status = decode_connectivity(bytes.data(), bytes.size(), n, count, &decoded);
  ASSERT_TRUE(status.ok()) << what << ": " << status.message();
  ASSERT_EQ(decoded, triangles) << what;
}

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

// The same triangles in a random order, each rotated at random.
std::vector<int32_t> shuffled(const std::vector<int32_t>& triangles, unsigned seed) {
  std::mt19937 rng(seed);
  std::vector<size_t> order(triangles.size() / 3);
  std::iota(order.begin(), order.end(), 0);
  std::shuffle(order.begin(), order.end(), rng);
  std::vector<int32_t> out;
  for (size_t t : order) {
    const int r = static_cast<int>(rng() % 3);
    for (int k = 0; k < 3; ++k) out.push_back(triangles[3 * t + (r + k) % 3]);
  }
  return out;
}

TEST(ConnectivityCoder, RoundTripsGeneratedMeshes) {
  expect_round_trip(0, {}, "empty");
  expect_round_trip(3, {0, 1, 2}, "one triangle");
  expect_round_trip(3, {2, 1, 0}, "one triangle, reversed");
  const std::vector<int32_t> g = grid(40, 30);
  expect_round_trip(41 * 31, g, "grid");
  expect_round_trip(41 * 31, shuffled(g, 1), "shuffled grid");
  // Vertices introduced out of order: reverse the numbering.
  std::vector<int32_t> reversed = g;
  for (int32_t& v : reversed) v = 41 * 31 - 1 - v;
  expect_round_trip(41 * 31, reversed, "grid, reversed numbering");

  std::mt19937 rng(2);
  std::vector<int32_t> soup(3 * 5000);
  for (int32_t& v : soup) v = static_cast<int32_t>(rng() % 1000);
  expect_round_trip(1000, soup, "random triangles");

  // Duplicates (same and opposite orientation) and degenerate triangles.
  std::vector<int32_t> odd = {0, 1, 2, 0, 1, 2, 2, 1, 0, 0, 1, 2, 3, 3, 4, 5, 5, 5,
                              4, 3, 3, 1, 0, 1, 0, 0, 0, 2, 2, 1, 1, 2, 2, 0, 1, 2};
  expect_round_trip(6, odd, "duplicates and degenerates");
  std::vector<int32_t> mixed = g;
  mixed.insert(mixed.end(), g.begin(), g.begin() + 300);  // 100 triangles again
  mixed.insert(mixed.end(), {7, 7, 7, 8, 9, 8});
  expect_round_trip(41 * 31, shuffled(mixed, 3), "grid with duplicates, shuffled");

  // Isolated vertices: n far above what the triangles use.
  std::vector<int32_t> sparse_use = {50, 51, 52, 52, 51, 60, 60, 51, 59};
  expect_round_trip(100, sparse_use, "isolated vertices");
  // Indices at the top of the int32 range: large explicit deltas.
  const int32_t top = 0x7FFFFFFF;
  expect_round_trip(top, {top - 1, 0, top - 2, 0, top - 1, 5, 1 << 30, top - 1, 0}, "huge indices");
  // One vertex in a huge fan: long open-edge lists at one vertex.
  std::vector<int32_t> fan;
  for (int32_t i = 1; i < 3000; ++i) fan.insert(fan.end(), {0, i, i + 1});
  expect_round_trip(3001, fan, "fan");
  expect_round_trip(3001, shuffled(fan, 4), "shuffled fan");
}

TEST(ConnectivityCoder, OrderedGridIsCheap) {
  const std::vector<int32_t> g = grid(100, 100);
  const double bits = 8.0 * encode_connectivity(101 * 101, g).size();
  EXPECT_LT(bits / 20000, 2.0);  // a regular strip-like order: well under 2 bits a triangle
}

TEST(ConnectivityCoder, SharedMeshesRoundTrip) {
  const char* names[] = {"bunny-small", "camel-head", "max-planck", "bunny", "horse", "feline", "nefertiti", "igea"};
  int found = 0;
  for (const char* name : names) {
    const std::string path = std::string(GAB_SHARED_MESHES) + "/" + name + ".off";
    if (!std::ifstream(path)) continue;
    Mesh mesh;
    ASSERT_TRUE(read_mesh(path, &mesh).ok()) << path;
    ++found;
    const auto t0 = std::chrono::steady_clock::now();
    const std::vector<uint8_t> bytes = encode_connectivity(mesh.num_vertices(), mesh.triangles);
    const auto t1 = std::chrono::steady_clock::now();
    std::vector<int32_t> decoded;
    const Status status =
        decode_connectivity(bytes.data(), bytes.size(), mesh.num_vertices(), mesh.num_triangles(), &decoded);
    const auto t2 = std::chrono::steady_clock::now();
    ASSERT_TRUE(status.ok()) << name << ": " << status.message();
    ASSERT_EQ(decoded, mesh.triangles) << name;
    const double bits_per_triangle = 8.0 * bytes.size() / mesh.num_triangles();
    std::printf("[ measure  ] %-12s %7d triangles: %6.2f bits/triangle, encode %.0f ms, decode %.0f ms\n", name,
                mesh.num_triangles(), bits_per_triangle,
                std::chrono::duration<double, std::milli>(t1 - t0).count(),
                std::chrono::duration<double, std::milli>(t2 - t1).count());
    // Far below 3 log2(n) bits for 3 plain indices, whatever the order.
    EXPECT_LT(bits_per_triangle, 24.0) << name;
  }
  if (found == 0) GTEST_SKIP() << "no shared meshes in " << GAB_SHARED_MESHES;
}

// A fan whose vertices appear in index order: vertex k + 2 is first used by
// triangle k, coded as "the next new vertex".
TEST(ConnectivityCoder, OutOfRangeIndexNamesTheTriangle) {
  std::vector<int32_t> fan;
  for (int32_t k = 0; k < 8; ++k) fan.insert(fan.end(), {0, k + 1, k + 2});
  const std::vector<uint8_t> bytes = encode_connectivity(10, fan);
  std::vector<int32_t> decoded;
  const Status status = decode_connectivity(bytes.data(), bytes.size(), 5, 8, &decoded);
  ASSERT_FALSE(status.ok());
  EXPECT_EQ(status.code(), StatusCode::kParseError);
  EXPECT_EQ(status.message(), "connectivity: triangle 3: vertex index 5 out of range [0, 5)");
  // The same stream with the right count decodes.
  EXPECT_TRUE(decode_connectivity(bytes.data(), bytes.size(), 10, 8, &decoded).ok());
}

TEST(ConnectivityCoder, NegativeCountsAreInvalid) {
  std::vector<int32_t> decoded;
  const uint8_t bytes[4] = {0, 0, 0, 0};
  EXPECT_EQ(decode_connectivity(bytes, 4, -1, 0, &decoded).code(), StatusCode::kInvalidArgument);
  EXPECT_EQ(decode_connectivity(bytes, 4, 3, -1, &decoded).code(), StatusCode::kInvalidArgument);
}

TEST(ConnectivityCoder, EveryTruncationIsAnError) {
  const std::vector<int32_t> triangles = shuffled(grid(6, 5), 5);
  const int32_t n = 7 * 6, count = static_cast<int32_t>(triangles.size() / 3);
  const std::vector<uint8_t> bytes = encode_connectivity(n, triangles);
  for (size_t cut = 0; cut < bytes.size(); ++cut) {
    std::vector<uint8_t> prefix(bytes.begin(), bytes.begin() + cut);  // exact size for ASan
    std::vector<int32_t> decoded;
    const Status status = decode_connectivity(prefix.data(), prefix.size(), n, count, &decoded);
    ASSERT_FALSE(status.ok()) << "cut at " << cut;
    EXPECT_EQ(status.code(), StatusCode::kParseError);
    EXPECT_EQ(status.message().rfind("connectivity: ", 0), 0u) << status.message();
  }
  // A lying triangle count overruns the stream, naming the first missing triangle.
  std::vector<int32_t> decoded;
  const Status more = decode_connectivity(bytes.data(), bytes.size(), n, count + 1000000, &decoded);
  ASSERT_FALSE(more.ok());
  EXPECT_NE(more.message().find("stream ends inside the triangle"), std::string::npos) << more.message();
  // Trailing garbage is an error too.
  std::vector<uint8_t> longer = bytes;
  longer.push_back(0);
  const Status trailing = decode_connectivity(longer.data(), longer.size(), n, count, &decoded);
  EXPECT_EQ(trailing.message(), "connectivity: 1 trailing bytes after " + std::to_string(count) + " triangles");
  // Fewer triangles than coded leaves bytes unread.
  EXPECT_FALSE(decode_connectivity(bytes.data(), bytes.size(), n, count - 1, &decoded).ok());
}

TEST(ConnectivityCoder, GarbageNeverCrashes) {
  std::mt19937 rng(6);
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<uint8_t> garbage(rng() % 300);
    for (auto& b : garbage) b = static_cast<uint8_t>(rng());
    const int32_t n = static_cast<int32_t>(rng() % 2000);
    const int32_t count = trial % 3 == 0 ? 0x7FFFFFFF : static_cast<int32_t>(rng() % 500);
    std::vector<int32_t> decoded;
    const Status status = decode_connectivity(garbage.data(), garbage.size(), n, count, &decoded);
    if (status.ok()) {
      ASSERT_EQ(decoded.size(), 3u * count);
      for (int32_t v : decoded) ASSERT_TRUE(v >= 0 && v < n);
    } else {
      ASSERT_EQ(status.code(), StatusCode::kParseError);
      ASSERT_LT(decoded.size(), 3u * 3000 * (garbage.size() + 1));  // a lying count allocates nothing extra
    }
  }
}

// FNV-1a, 64 bits, from its definition: h = offset basis; for each byte,
// h = (h xor byte) * prime.
uint64_t fnv1a(const std::vector<uint8_t>& bytes) {
  uint64_t h = 14695981039346656037ull;
  for (uint8_t b : bytes) h = (h ^ b) * 1099511628211ull;
  return h;
}

TEST(ConnectivityCoder, HashFollowsFnv1aDefinition) {
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

TEST(ConnectivityCoder, HashSeesEveryChange) {
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
