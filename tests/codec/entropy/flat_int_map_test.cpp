#include "entropy/flat_int_map.h"

#include <gtest/gtest.h>

#include <random>
#include <unordered_map>

namespace gab {
namespace {

// Random inserts, lookups and erases against std::unordered_map, over a
// small key range (many collisions, long probe runs, runs wrapping around
// the table's end) and a wide one (growth), checking every lookup.
TEST(FlatIntMapTest, AgreesWithUnorderedMapUnderRandomOperations) {
  for (const uint64_t range : {uint64_t{40}, uint64_t{60}, uint64_t{300}, uint64_t{1} << 40}) {
    std::mt19937_64 rng(static_cast<uint64_t>(range) * 7 + 1);
    FlatIntMap map;
    std::unordered_map<uint64_t, int32_t> oracle;
    for (int step = 0; step < 200000; ++step) {
      const uint64_t key = rng() % range;
      const int op = static_cast<int>(rng() % 3);
      if (op == 0) {
        const int32_t value = static_cast<int32_t>(rng() % 1000);
        const int32_t got = map.insert(key, value);
        const int32_t want = oracle.emplace(key, value).first->second;  // keeps an existing value
        ASSERT_EQ(got, want) << "insert " << key;
      } else if (op == 1) {
        map.erase(key);
        oracle.erase(key);
      } else {
        int32_t* got = map.find(key);
        const auto want = oracle.find(key);
        ASSERT_EQ(got != nullptr, want != oracle.end()) << "find " << key << " at step " << step;
        if (got != nullptr) {
          ASSERT_EQ(*got, want->second);
          *got += 1;  // the pointer writes through
          want->second += 1;
        }
      }
      ASSERT_EQ(map.size(), oracle.size());
    }
    for (const auto& kv : oracle) {
      const int32_t* got = map.find(kv.first);
      ASSERT_NE(got, nullptr);
      EXPECT_EQ(*got, kv.second);
    }
  }
}

TEST(FlatIntMapTest, EmptyMapFindsAndErasesNothing) {
  FlatIntMap map;
  EXPECT_EQ(map.find(0), nullptr);
  map.erase(5);
  EXPECT_EQ(map.size(), 0u);
  map.insert(5, 1);
  map.erase(5);
  EXPECT_EQ(map.find(5), nullptr);
  EXPECT_EQ(map.size(), 0u);
}

}  // namespace
}  // namespace gab
