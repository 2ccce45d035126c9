// UIntCoder / SIntCoder: exact round trips (edges of the ranges included,
// across contexts), size near the entropy of geometric sources, and
// garbage decoding to values that round trip (saturated where out of range).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <random>
#include <vector>

#include "entropy/int_coder.h"

namespace gab {
namespace {

constexpr int32_t kMax32 = std::numeric_limits<int32_t>::max();
constexpr int32_t kMin32 = std::numeric_limits<int32_t>::min();

double empirical_entropy_bits(const std::vector<int64_t>& values) {
  std::map<int64_t, double> counts;
  for (int64_t v : values) counts[v] += 1;
  double bits = 0;
  for (const auto& kv : counts) bits -= kv.second * std::log2(kv.second / values.size());
  return bits;
}

TEST(IntCoder, UnsignedRoundTripsEdgesAndRandomAcrossContexts) {
  std::mt19937 rng(1);
  std::vector<uint32_t> values = {0, 1, 2, 3, 4, 5, 7, 8, 0x7FFFFFFFu, 0x80000000u, 0xFFFFFFFEu, 0xFFFFFFFFu};
  for (int k = 0; k < 32; ++k) {
    values.push_back(1u << k);
    values.push_back((1u << k) - 1);
    values.push_back((1u << k) + 1);
  }
  for (int i = 0; i < 20000; ++i) values.push_back(rng() >> (rng() % 32));
  UIntCoder coder(5);
  EXPECT_EQ(coder.contexts(), 5);
  RangeEncoder enc;
  // Contexts -1 and 5 are out of range: clamped to 0 and 4 on both sides.
  for (size_t i = 0; i < values.size(); ++i) coder.encode(&enc, values[i], static_cast<int>(i % 7) - 1);
  const std::vector<uint8_t> bytes = enc.finish();
  UIntCoder decoder(5);
  RangeDecoder dec(bytes.data(), bytes.size());
  for (size_t i = 0; i < values.size(); ++i) {
    ASSERT_EQ(decoder.decode(&dec, static_cast<int>(i % 7) - 1), values[i]) << i;
  }
  EXPECT_FALSE(dec.overrun());
  EXPECT_EQ(dec.bytes_consumed(), bytes.size());
}

TEST(IntCoder, SignedRoundTripsEdgesAndRandomAcrossContexts) {
  std::mt19937 rng(2);
  std::vector<int32_t> values = {0, 1, -1, 2, -2, kMax32, -kMax32, kMin32, kMax32 - 1, kMin32 + 1, 0, 0};
  for (int i = 0; i < 20000; ++i) {
    const int32_t magnitude = static_cast<int32_t>(rng() >> (1 + rng() % 31));
    values.push_back(rng() & 1 ? magnitude : -magnitude);
  }
  SIntCoder coder(3);
  RangeEncoder enc;
  for (size_t i = 0; i < values.size(); ++i) coder.encode(&enc, values[i], static_cast<int>(i % 3));
  const std::vector<uint8_t> bytes = enc.finish();
  SIntCoder decoder(3);
  RangeDecoder dec(bytes.data(), bytes.size());
  for (size_t i = 0; i < values.size(); ++i) ASSERT_EQ(decoder.decode(&dec, static_cast<int>(i % 3)), values[i]) << i;
  EXPECT_FALSE(dec.overrun());
}

// Geometric values: the adaptive length and top mantissa bits take most of
// the entropy; the raw low bits lose a little (their distribution is not
// quite flat), and adaptation costs about 0.01 bit per adaptive decision.
TEST(IntCoder, GeometricValuesCostNearTheirEntropy) {
  for (double mean : {0.5, 3.0, 20.0, 300.0}) {
    std::mt19937 rng(3);
    std::geometric_distribution<int64_t> geometric(1.0 / (1.0 + mean));
    std::vector<int64_t> values(100000);
    for (auto& v : values) v = geometric(rng);
    RangeEncoder enc;
    UIntCoder coder;
    for (int64_t v : values) coder.encode(&enc, static_cast<uint32_t>(v));
    const double bits = 8.0 * enc.finish().size();
    const double entropy = empirical_entropy_bits(values);
    std::printf("[ measure  ] geometric mean %g: %.3f bits/value, entropy %.3f (+%.1f%%)\n", mean,
                bits / values.size(), entropy / values.size(), 100 * (bits / entropy - 1));
    EXPECT_LE(bits, entropy * 1.04 + 0.06 * values.size()) << "mean " << mean;
  }
}

TEST(IntCoder, SignedGeometricCostNearEntropy) {
  std::mt19937 rng(4);
  std::geometric_distribution<int32_t> geometric(0.2);
  std::vector<int64_t> values(100000);
  for (auto& v : values) v = (rng() & 1) ? geometric(rng) : -geometric(rng);
  RangeEncoder enc;
  SIntCoder coder;
  for (int64_t v : values) coder.encode(&enc, static_cast<int32_t>(v));
  const double bits = 8.0 * enc.finish().size();
  const double entropy = empirical_entropy_bits(values);
  EXPECT_LE(bits, entropy * 1.04 + 0.06 * values.size());
}

TEST(IntCoder, GarbageDecodesToValuesThatRoundTrip) {
  // Whatever a corrupt stream decodes to is a value the coders can code:
  // coded afresh, the values decode back the same, in as many bytes as the
  // encoder wrote (and no undefined behaviour on the way: the sanitizer
  // builds run this).
  std::mt19937 rng(5);
  for (int trial = 0; trial < 100; ++trial) {
    std::vector<uint8_t> garbage(rng() % 128);
    for (auto& b : garbage) b = static_cast<uint8_t>(trial % 4 == 0 ? 0xFF : rng());
    RangeDecoder dec(garbage.data(), garbage.size());
    UIntCoder u(2);
    SIntCoder s(2);
    std::vector<uint32_t> unsigned_values;
    std::vector<int32_t> signed_values;
    for (int i = 0; i < 500; ++i) {
      unsigned_values.push_back(u.decode(&dec, i & 1));
      signed_values.push_back(s.decode(&dec, i & 1));
    }
    RangeEncoder enc;
    UIntCoder u_enc(2);
    SIntCoder s_enc(2);
    for (int i = 0; i < 500; ++i) {
      u_enc.encode(&enc, unsigned_values[i], i & 1);
      s_enc.encode(&enc, signed_values[i], i & 1);
    }
    const std::vector<uint8_t> bytes = enc.finish();
    RangeDecoder again(bytes.data(), bytes.size());
    UIntCoder u_dec(2);
    SIntCoder s_dec(2);
    for (int i = 0; i < 500; ++i) {
      ASSERT_EQ(u_dec.decode(&again, i & 1), unsigned_values[i]) << trial << " " << i;
      ASSERT_EQ(s_dec.decode(&again, i & 1), signed_values[i]) << trial << " " << i;
    }
    EXPECT_FALSE(again.overrun());
    EXPECT_EQ(again.bytes_consumed(), bytes.size());
  }
}

// Garbage whose magnitude exceeds the int32 range saturates: a stream that
// codes the unsigned magnitude 0xFFFFFFFF with a positive sign.
TEST(IntCoder, OutOfRangeSignedMagnitudeSaturates) {
  // SIntCoder's layout: zero flag (0 = nonzero), sign (0 = positive), then
  // |v| - 1 through a UIntCoder with the same context.
  for (int negative = 0; negative < 2; ++negative) {
    RangeEncoder enc;
    BitModel zero, sign;
    UIntCoder magnitude;
    enc.encode(&zero, 0);
    enc.encode(&sign, negative);
    magnitude.encode(&enc, 0xFFFFFFFFu);
    const std::vector<uint8_t> bytes = enc.finish();
    RangeDecoder dec(bytes.data(), bytes.size());
    SIntCoder s;
    EXPECT_EQ(s.decode(&dec), negative ? kMin32 : kMax32);
  }
}

}  // namespace
}  // namespace gab
