// ByteWriter / ByteReader: little-endian layout, varint canonical form, and
// a reader that fails (without moving) instead of reading past its end.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

#include "container/byte_io.h"

namespace gab {
namespace {

TEST(ByteIo, FixedWidthLayoutIsLittleEndian) {
  ByteWriter w;
  w.u8(0xAB);
  w.u32(0x01020304u);
  w.u64(0x1122334455667788ull);
  const std::vector<uint8_t> expected = {0xAB, 0x04, 0x03, 0x02, 0x01, 0x88, 0x77,
                                         0x66, 0x55, 0x44, 0x33, 0x22, 0x11};
  EXPECT_EQ(w.data(), expected);
}

TEST(ByteIo, RoundTripsEveryField) {
  ByteWriter w;
  const double values[] = {0.0, -0.0, 1.5, -3.25e-300, std::numeric_limits<double>::infinity(),
                           std::numeric_limits<double>::denorm_min()};
  const uint64_t varints[] = {0, 1, 127, 128, 16383, 16384, 0xFFFFFFFFull, ~0ull};
  w.u8(7);
  w.u32(0xDEADBEEFu);
  w.u64(~0ull);
  for (double d : values) w.f64(d);
  w.f64(std::nan(""));
  for (uint64_t v : varints) w.varint(v);
  const uint8_t blob[3] = {9, 8, 7};
  w.bytes(blob, 3);
  const size_t patch_at = w.size();
  w.u32(0);
  w.patch_u32(patch_at, 0xCAFEF00Du);
  const std::vector<uint8_t> data = w.take();

  ByteReader r(data.data(), data.size());
  uint8_t b;
  uint32_t u;
  uint64_t q;
  double d;
  ASSERT_TRUE(r.u8(&b));
  EXPECT_EQ(b, 7);
  ASSERT_TRUE(r.u32(&u));
  EXPECT_EQ(u, 0xDEADBEEFu);
  ASSERT_TRUE(r.u64(&q));
  EXPECT_EQ(q, ~0ull);
  for (double expected : values) {
    ASSERT_TRUE(r.f64(&d));
    EXPECT_EQ(std::memcmp(&d, &expected, sizeof d), 0) << expected;  // bit-exact, sign of zero too
  }
  ASSERT_TRUE(r.f64(&d));
  EXPECT_TRUE(std::isnan(d));
  for (uint64_t expected : varints) {
    ASSERT_TRUE(r.varint(&q));
    EXPECT_EQ(q, expected);
  }
  const uint8_t* p = nullptr;
  ASSERT_TRUE(r.bytes(3, &p));
  EXPECT_EQ(std::memcmp(p, blob, 3), 0);
  ASSERT_TRUE(r.u32(&u));
  EXPECT_EQ(u, 0xCAFEF00Du);
  EXPECT_EQ(r.remaining(), 0u);
  EXPECT_EQ(r.offset(), data.size());
  EXPECT_FALSE(r.u8(&b));
}

TEST(ByteIo, VarintSizes) {
  auto size_of = [](uint64_t v) {
    ByteWriter w;
    w.varint(v);
    return w.size();
  };
  EXPECT_EQ(size_of(0), 1u);
  EXPECT_EQ(size_of(127), 1u);
  EXPECT_EQ(size_of(128), 2u);
  EXPECT_EQ(size_of(uint64_t{1} << 63), 10u);
  EXPECT_EQ(size_of(~0ull), 10u);
}

TEST(ByteIo, TruncationFailsWithoutMoving) {
  ByteWriter w;
  w.u32(1);
  w.u64(2);
  w.varint(~0ull);
  const std::vector<uint8_t> full = w.data();
  for (size_t cut = 0; cut < full.size(); ++cut) {
    ByteReader r(full.data(), cut);
    uint32_t u = 77;
    uint64_t q = 77;
    bool ok = r.u32(&u) && r.u64(&q) && r.varint(&q);
    EXPECT_FALSE(ok) << cut;
    // Whatever failed left its output and the position alone.
    ByteReader again(full.data(), cut);
    uint64_t before = 123;
    if (cut < 4) {
      EXPECT_FALSE(again.u32(&u));
      EXPECT_EQ(again.offset(), 0u);
    } else if (cut < 12) {
      ASSERT_TRUE(again.u32(&u));
      EXPECT_FALSE(again.u64(&before));
      EXPECT_EQ(before, 123u);
      EXPECT_EQ(again.offset(), 4u);
    } else {
      ASSERT_TRUE(again.u32(&u) && again.u64(&q));
      EXPECT_FALSE(again.varint(&before));
      EXPECT_EQ(before, 123u);
      EXPECT_EQ(again.offset(), 12u);
    }
  }
  ByteReader r(full.data(), 2);
  const uint8_t* p = nullptr;
  EXPECT_FALSE(r.bytes(3, &p));
  EXPECT_EQ(p, nullptr);
  double d;
  EXPECT_FALSE(r.f64(&d));
}

TEST(ByteIo, RejectsOverlongAndNonMinimalVarints) {
  auto parse = [](std::vector<uint8_t> bytes, uint64_t* v) {
    ByteReader r(bytes.data(), bytes.size());
    return r.varint(v);
  };
  uint64_t v = 0;
  // 10 bytes whose last carries more than bit 63.
  EXPECT_FALSE(parse({0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0x02}, &v));
  // 11 bytes: continuation on the tenth.
  EXPECT_FALSE(parse({0x80, 0x80, 0x80, 0x80, 0x80, 0x80, 0x80, 0x80, 0x80, 0x81, 0x00}, &v));
  // Zero padding: 0 as two bytes, 1 as three.
  EXPECT_FALSE(parse({0x80, 0x00}, &v));
  EXPECT_FALSE(parse({0x81, 0x80, 0x00}, &v));
  // Continuation with nothing after it.
  EXPECT_FALSE(parse({0x80}, &v));
  // The largest value, in its one encoding, is accepted.
  ASSERT_TRUE(parse({0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0x01}, &v));
  EXPECT_EQ(v, ~0ull);
}

}  // namespace
}  // namespace gab
