// Sorted subsets: exact round trips over the whole range of sizes and
// densities, size within 2% + 16 bits of log2 C(u, b), and decoders that
// stay inside [0, u) on garbage.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>
#include <set>
#include <vector>

#include "entropy/subset_coder.h"

namespace gab {
namespace {

double log2_binomial(double u, double b) {
  return (std::lgamma(u + 1) - std::lgamma(b + 1) - std::lgamma(u - b + 1)) / std::log(2.0);
}

// b distinct positions of [0, u), sorted (Floyd's sampling: O(b)).
std::vector<uint32_t> random_subset(uint32_t u, uint32_t b, std::mt19937_64* rng) {
  std::set<uint32_t> chosen;
  for (uint64_t j = uint64_t{u} - b; j < u; ++j) {
    const uint32_t t = static_cast<uint32_t>(std::uniform_int_distribution<uint64_t>(0, j)(*rng));
    if (!chosen.insert(t).second) chosen.insert(static_cast<uint32_t>(j));
  }
  return std::vector<uint32_t>(chosen.begin(), chosen.end());
}

std::vector<uint8_t> encode(const std::vector<uint32_t>& subset, uint32_t universe) {
  RangeEncoder enc;
  encode_subset(&enc, subset, universe);
  return enc.finish();
}

void expect_round_trip(const std::vector<uint32_t>& subset, uint32_t universe) {
  const std::vector<uint8_t> bytes = encode(subset, universe);
  RangeDecoder dec(bytes.data(), bytes.size());
  std::vector<uint32_t> decoded = {12345};  // cleared by the decoder
  ASSERT_TRUE(decode_subset(&dec, static_cast<uint32_t>(subset.size()), universe, &decoded));
  ASSERT_EQ(decoded, subset) << "b = " << subset.size() << ", u = " << universe;
  EXPECT_FALSE(dec.overrun());
  EXPECT_EQ(dec.bytes_consumed(), bytes.size());
}

TEST(SubsetCoder, RoundTripsSmallAndEdgeCases) {
  expect_round_trip({}, 0);
  expect_round_trip({}, 1);
  expect_round_trip({0}, 1);
  expect_round_trip({}, 100);
  expect_round_trip({0}, 100);
  expect_round_trip({99}, 100);
  expect_round_trip({0, 99}, 100);
  expect_round_trip({98, 99}, 100);
  expect_round_trip({0, 1, 2}, 3);
  const uint32_t big = 0x7FFFFFFFu;
  expect_round_trip({0}, big);
  expect_round_trip({big - 1}, big);
  expect_round_trip({0, 1, big - 2, big - 1}, big);
  expect_round_trip({0xFFFFFFFEu}, 0xFFFFFFFFu);  // the whole uint32 range works too
}

TEST(SubsetCoder, RoundTripsRandomSubsetsOfEveryDensity) {
  std::mt19937_64 rng(1);
  for (uint32_t u : {2u, 7u, 64u, 1000u, 100000u}) {
    for (double density : {0.0, 0.001, 0.01, 0.1, 0.3, 0.5, 0.7, 0.9, 0.99, 1.0}) {
      const uint32_t b = static_cast<uint32_t>(density * u);
      expect_round_trip(random_subset(u, b, &rng), u);
    }
  }
  expect_round_trip(random_subset(0x7FFFFFFFu, 1000, &rng), 0x7FFFFFFFu);
}

TEST(SubsetCoder, FullSetCostsNothing) {
  std::vector<uint32_t> all(100000);
  for (uint32_t i = 0; i < all.size(); ++i) all[i] = i;
  EXPECT_EQ(encode(all, 100000).size(), 4u);  // the range coder's flush alone
  expect_round_trip(all, 100000);
}

TEST(SubsetCoder, SizeNearLog2Binomial) {
  std::mt19937_64 rng(2);
  struct Case {
    uint32_t u, b;
  };
  const Case cases[] = {{1000000, 10},    {1000000, 100},   {1000000, 1000},  {1000000, 10000},
                        {1000000, 100000}, {100000, 30000},  {100000, 50000},  {100000, 70000},
                        {100000, 90000},   {0x7FFFFFFFu, 1000}, {134345, 2000}, {100000, 99000}};
  for (const Case& c : cases) {
    const std::vector<uint32_t> subset = random_subset(c.u, c.b, &rng);
    const double bits = 8.0 * encode(subset, c.u).size();
    const double bound = log2_binomial(c.u, c.b);
    std::printf("[ measure  ] u=%u b=%u: %.0f bits, log2 C(u,b) = %.0f (+%.2f%%)\n", c.u, c.b, bits, bound,
                100 * (bits / bound - 1));
    EXPECT_LE(bits, bound * 1.02 + 16 + 32) << "u = " << c.u << ", b = " << c.b;  // + the 4-byte flush
  }
}

TEST(SubsetCoder, CountAboveUniverseIsRejected) {
  const std::vector<uint8_t> bytes(16, 0);
  RangeDecoder dec(bytes.data(), bytes.size());
  std::vector<uint32_t> out;
  EXPECT_FALSE(decode_subset(&dec, 11, 10, &out));
}

TEST(SubsetCoder, GarbageStaysInRangeOrFails) {
  std::mt19937_64 rng(3);
  int accepted = 0;
  for (int trial = 0; trial < 500; ++trial) {
    std::vector<uint8_t> garbage(rng() % 200);
    for (auto& b : garbage) b = static_cast<uint8_t>(trial % 5 == 0 ? 0xFF : rng());
    const uint32_t universe = trial % 2 ? 1 + static_cast<uint32_t>(rng() % 5000) : static_cast<uint32_t>(rng() >> 33);
    const uint32_t count = static_cast<uint32_t>(rng() % (std::min<uint32_t>(universe, 4000) + 1));
    RangeDecoder dec(garbage.data(), garbage.size());
    std::vector<uint32_t> out;
    if (decode_subset(&dec, count, universe, &out)) {
      ++accepted;
      ASSERT_EQ(out.size(), count);
      for (size_t i = 0; i < out.size(); ++i) {
        ASSERT_LT(out[i], universe);
        if (i > 0) {
          ASSERT_LT(out[i - 1], out[i]);
        }
      }
    } else {
      ASSERT_LE(out.size(), count);
    }
  }
  std::printf("[ measure  ] garbage subsets accepted: %d of 500 (each one valid)\n", accepted);
}

TEST(SubsetCoder, TruncatedStreamFails) {
  std::mt19937_64 rng(4);
  const std::vector<uint32_t> subset = random_subset(5000, 300, &rng);
  const std::vector<uint8_t> bytes = encode(subset, 5000);
  for (size_t cut = 0; cut < bytes.size(); ++cut) {
    std::vector<uint8_t> prefix(bytes.begin(), bytes.begin() + cut);
    RangeDecoder dec(prefix.data(), prefix.size());
    std::vector<uint32_t> out;
    ASSERT_FALSE(decode_subset(&dec, 300, 5000, &out)) << cut;
  }
}

}  // namespace
}  // namespace gab
