// The binary range coder: exact round trips, size against the models' own
// code length (the coder's arithmetic loses < 1%) and against the empirical
// entropy (adding the documented cost of adaptation), raw bits, and the
// decoder's contract on truncated and garbage input.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "entropy/range_coder.h"

namespace gab {
namespace {

double binary_entropy(double p) {
  if (p <= 0 || p >= 1) return 0;
  return -p * std::log2(p) - (1 - p) * std::log2(1 - p);
}

// Cost of coding `bit` with the model as it stands, before it adapts.
double model_cost(const BitModel& m, int bit) {
  const double p0 = m.p0 / 65536.0;
  return -std::log2(bit ? 1 - p0 : p0);
}

struct Source {
  std::vector<int> model;  // which model codes each bit
  std::vector<int> bit;
};

// Bits drawn from `probabilities.size()` stationary Bernoulli sources, the
// source of each bit chosen at random.
Source make_source(const std::vector<double>& probabilities, size_t count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> pick(0, static_cast<int>(probabilities.size()) - 1);
  std::uniform_real_distribution<double> u(0, 1);
  Source s;
  for (size_t i = 0; i < count; ++i) {
    const int m = pick(rng);
    s.model.push_back(m);
    s.bit.push_back(u(rng) < probabilities[m] ? 1 : 0);
  }
  return s;
}

// Encodes the source; returns the bytes and the models' ideal code length.
std::vector<uint8_t> encode_source(const Source& s, size_t models, double* ideal_bits) {
  std::vector<BitModel> m(models);
  RangeEncoder enc;
  *ideal_bits = 0;
  for (size_t i = 0; i < s.bit.size(); ++i) {
    *ideal_bits += model_cost(m[s.model[i]], s.bit[i]);
    enc.encode(&m[s.model[i]], s.bit[i]);
  }
  return enc.finish();
}

void expect_decodes(const Source& s, size_t models, const std::vector<uint8_t>& bytes) {
  std::vector<BitModel> m(models);
  RangeDecoder dec(bytes.data(), bytes.size());
  for (size_t i = 0; i < s.bit.size(); ++i) {
    ASSERT_EQ(dec.decode(&m[s.model[i]]), s.bit[i]) << "bit " << i;
  }
  EXPECT_FALSE(dec.overrun());
  EXPECT_EQ(dec.bytes_consumed(), bytes.size());  // the decoder reads exactly the stream
}

TEST(RangeCoder, EmptyStreamIsTheFlush) {
  RangeEncoder enc;
  const std::vector<uint8_t> bytes = enc.finish();
  EXPECT_EQ(bytes.size(), 4u);
  RangeDecoder dec(bytes.data(), bytes.size());
  EXPECT_FALSE(dec.overrun());
  EXPECT_EQ(dec.bytes_consumed(), 4u);
}

TEST(RangeCoder, RoundTripsSkewedBitsOverManyModels) {
  std::vector<double> p;
  for (int i = 0; i < 64; ++i) p.push_back((i + 0.5) / 64.0 * (i % 2 ? 1.0 : 0.05));  // many near 0
  p.push_back(0.0);
  p.push_back(1.0);  // deterministic sources drive p0 to its bounds
  const Source s = make_source(p, 200000, 1);
  double ideal = 0;
  const std::vector<uint8_t> bytes = encode_source(s, p.size(), &ideal);
  expect_decodes(s, p.size(), bytes);
}

TEST(RangeCoder, SizeWithinOnePercentOfTheModelsCodeLength) {
  for (double p : {0.5, 0.2, 0.05, 0.01, 0.001}) {
    const Source s = make_source({p}, 400000, 2);
    double ideal = 0;
    const std::vector<uint8_t> bytes = encode_source(s, 1, &ideal);
    const double bits = 8.0 * bytes.size();
    EXPECT_LE(bits, ideal * 1.01 + 48) << "p = " << p;
    expect_decodes(s, 1, bytes);
  }
}

// Against the empirical entropy, an adaptive model also pays for tracking
// its probability: about 2^-s / (2 ln 2 (2 - 2^-s)) bits per coded bit for
// adaptation shift s (0.0115 at s = 5), whatever the probability.
TEST(RangeCoder, SizeNearEmpiricalEntropyForStationarySources) {
  const double a = std::ldexp(1.0, -BitModel::kAdaptShift);
  const double adaptation = a / (2 * std::log(2.0) * (2 - a));
  for (double p : {0.5, 0.3, 0.1, 0.02}) {
    const size_t n = 400000;
    const Source s = make_source({p}, n, 3);
    size_t ones = 0;
    for (int b : s.bit) ones += b;
    const double entropy = n * binary_entropy(static_cast<double>(ones) / n);
    double ideal = 0;
    const std::vector<uint8_t> bytes = encode_source(s, 1, &ideal);
    const double bits = 8.0 * bytes.size();
    std::printf("[ measure  ] p=%.2f: %.4f bits/bit, entropy %.4f (+%.2f%%)\n", p, bits / n, entropy / n,
                100.0 * (bits / entropy - 1));
    EXPECT_LE(bits, entropy * 1.01 + 1.25 * adaptation * n + 64) << "p = " << p;
  }
}

TEST(RangeCoder, LongRunsCostAlmostNothing) {
  BitModel zeros, ones;
  RangeEncoder enc;
  for (int i = 0; i < 100000; ++i) enc.encode(&zeros, 0);
  for (int i = 0; i < 100000; ++i) enc.encode(&ones, 1);
  const std::vector<uint8_t> bytes = enc.finish();
  // The model settles within 2^kAdaptShift of its bound (32 / 65536 short
  // of certainty): 200000 bits at P >= 1 - 95/65536 cost at most 420 bits.
  EXPECT_LT(bytes.size(), 4u + 420 / 8);
  BitModel z, o;
  RangeDecoder dec(bytes.data(), bytes.size());
  for (int i = 0; i < 100000; ++i) ASSERT_EQ(dec.decode(&z), 0);
  for (int i = 0; i < 100000; ++i) ASSERT_EQ(dec.decode(&o), 1);
  EXPECT_FALSE(dec.overrun());
}

TEST(RangeCoder, ProbabilityStaysInsideItsBounds) {
  BitModel m;
  RangeEncoder enc;
  for (int i = 0; i < 10000; ++i) enc.encode(&m, 0);
  EXPECT_LE(m.p0, BitModel::kMax);
  EXPECT_GT(m.p0, BitModel::kMax - (1u << BitModel::kAdaptShift));
  for (int i = 0; i < 10000; ++i) enc.encode(&m, 1);
  EXPECT_GE(m.p0, BitModel::kMin);
  EXPECT_LT(m.p0, BitModel::kMin + (1u << BitModel::kAdaptShift));
}

TEST(RangeCoder, RawBitsRoundTripForEveryWidth) {
  std::mt19937 rng(4);
  std::vector<uint32_t> values;
  std::vector<int> widths;
  BitModel m;
  RangeEncoder enc;
  size_t raw_bits = 0;
  for (int round = 0; round < 50; ++round) {
    for (int nbits = 0; nbits <= 32; ++nbits) {
      uint32_t v = rng();
      if (round == 0) v = ~0u;  // all ones, every width
      if (round == 1) v = 0;
      values.push_back(v);
      widths.push_back(nbits);
      enc.encode_raw(v, nbits);
      enc.encode(&m, round & 1);  // interleaved with adaptive bits
      raw_bits += nbits;
    }
  }
  const std::vector<uint8_t> bytes = enc.finish();
  EXPECT_LE(bytes.size(), raw_bits / 8 + 1650 / 8 + 8);  // raw bits cost exactly 1 bit each
  BitModel d;
  RangeDecoder dec(bytes.data(), bytes.size());
  for (size_t i = 0; i < values.size(); ++i) {
    const int nbits = widths[i];
    const uint32_t mask = nbits == 32 ? ~0u : (1u << nbits) - 1;
    ASSERT_EQ(dec.decode_raw(nbits), values[i] & mask) << "width " << nbits;
    ASSERT_EQ(dec.decode(&d), static_cast<int>((i / 33) & 1));
  }
  EXPECT_FALSE(dec.overrun());
  EXPECT_EQ(dec.bytes_consumed(), bytes.size());
}

// Cutting any number of bytes off a stream makes the full decode overrun:
// the decoder asks for exactly the bytes the encoder wrote.
TEST(RangeCoder, EveryTruncationOverruns) {
  const Source s = make_source({0.1, 0.5, 0.9}, 3000, 5);
  double ideal = 0;
  const std::vector<uint8_t> bytes = encode_source(s, 3, &ideal);
  for (size_t cut = 0; cut < bytes.size(); ++cut) {
    std::vector<uint8_t> prefix(bytes.begin(), bytes.begin() + cut);  // exact size, so ASan sees overreads
    std::vector<BitModel> m(3);
    RangeDecoder dec(prefix.data(), prefix.size());
    for (size_t i = 0; i < s.bit.size(); ++i) dec.decode(&m[s.model[i]]);
    dec.decode_raw(32);
    ASSERT_TRUE(dec.overrun()) << "cut at " << cut << " of " << bytes.size();
    ASSERT_EQ(dec.bytes_consumed(), cut);
  }
}

TEST(RangeCoder, GarbageNeverBreaksTheDecoder) {
  std::mt19937 rng(6);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<uint8_t> garbage(rng() % 64);
    for (auto& b : garbage) b = static_cast<uint8_t>(trial % 3 == 0 ? 0xFF : rng());
    std::vector<BitModel> m(8);
    RangeDecoder dec(garbage.data(), garbage.size());
    for (int i = 0; i < 2000; ++i) {
      if (i % 7 == 0) {
        dec.decode_raw(static_cast<int>(rng() % 34));
      } else {
        const int bit = dec.decode(&m[i % 8]);
        ASSERT_TRUE(bit == 0 || bit == 1);
      }
    }
    for (const BitModel& model : m) {
      ASSERT_GE(model.p0, BitModel::kMin);
      ASSERT_LE(model.p0, BitModel::kMax);
    }
    EXPECT_LE(dec.bytes_consumed(), garbage.size());
  }
}

}  // namespace
}  // namespace gab
