#include "gab/sparse/large_buffer.h"

#include <gtest/gtest.h>

#include <cstring>

#if defined(__linux__)
#include <unistd.h>
#endif

#include "gab/sparse/cholesky.h"
#include "sparse/test_matrices.h"

namespace gab {
namespace {

// Fills n doubles with a pattern that depends on the position.
void fill_pattern(double* p, int64_t n) {
  for (int64_t i = 0; i < n; ++i) p[i] = static_cast<double>(i % 1000003) + 0.25;
}

bool has_pattern(const double* p, int64_t n) {
  for (int64_t i = 0; i < n; ++i) {
    if (p[i] != static_cast<double>(i % 1000003) + 0.25) return false;
  }
  return true;
}

TEST(LargeBufferTest, ReleasedPagesReadAsZerosAndTakeWritesAgain) {
  constexpr int64_t kCount = int64_t{1} << 20;  // 8 MiB: huge-page aligned
  LargeBuffer<double> a;
  ASSERT_TRUE(a.reserve(kCount));
  double* const data = a.data();
  fill_pattern(data, kCount);
  a.release_pages();
  EXPECT_EQ(a.data(), data);
  EXPECT_EQ(a.capacity(), kCount);
#if defined(__linux__)
  for (int64_t i = 0; i < kCount; i += 511) ASSERT_EQ(data[i], 0.0) << i;
#endif
  fill_pattern(data, kCount);
  EXPECT_TRUE(has_pattern(data, kCount));
  // Only whole pages inside a ragged range go (doubles 512 .. 4607 of
  // [100, 5100) on 4 KiB pages): the bytes around them stay.
  fill_pattern(data, kCount);
  release_pages(data + 100, sizeof(double) * 5000);
#if defined(__linux__)
  const int64_t page = sysconf(_SC_PAGESIZE) / static_cast<int64_t>(sizeof(double));
  const int64_t first = (100 + page - 1) / page * page, last = 5100 / page * page;
#else
  const int64_t first = 0, last = 0;
#endif
  for (int64_t i = 0; i < kCount; ++i) {
    const double expected = i >= first && i < last ? 0.0 : static_cast<double>(i % 1000003) + 0.25;
    ASSERT_EQ(data[i], expected) << i;
  }
}

TEST(PagePopulatorTest, KeepsWhatTheRangesHold) {
  // 40 MiB in two ranges, one not page-aligned at either end: above the
  // size that starts a helper thread.
  constexpr int64_t kBig = int64_t{4} << 20, kOdd = 1000001;
  LargeBuffer<double> a, b;
  ASSERT_TRUE(a.reserve(kBig));
  ASSERT_TRUE(b.reserve(kOdd + 8));
  fill_pattern(a.data(), kBig);
  fill_pattern(b.data() + 3, kOdd);
  PagePopulator populator;
  populator.start({{a.data(), sizeof(double) * kBig}, {b.data() + 3, sizeof(double) * kOdd}});
  populator.finish();
  EXPECT_TRUE(has_pattern(a.data(), kBig));
  EXPECT_TRUE(has_pattern(b.data() + 3, kOdd));
}

TEST(PagePopulatorTest, RestartsFinishesTwiceAndStopsWhenDestroyed) {
  constexpr int64_t kBig = int64_t{3} << 20;  // 24 MiB
  LargeBuffer<double> a;
  ASSERT_TRUE(a.reserve(kBig));
  fill_pattern(a.data(), kBig);
  {
    PagePopulator populator;
    populator.finish();  // nothing running
    populator.start({{a.data(), sizeof(double) * kBig}});
    populator.start({{a.data(), sizeof(double) * kBig}, {nullptr, 0}});  // finishes the first run
    populator.finish();
    populator.finish();
    populator.start({{a.data(), sizeof(double) * kBig}});
  }  // destroyed while (maybe) running: joins
  EXPECT_TRUE(has_pattern(a.data(), kBig));
}

TEST(PagePopulatorTest, TwoThreadCholeskyOnALargeFactorMatchesOneThread) {
  // A 300 x 300 grid: ~40 MiB of factor, so analyze() populates it on a
  // helper thread while it builds the assembly map; the factor and a solve
  // must not notice.
  const CscMatrix a = testing_util::grid_laplacian(300, 300);
  std::vector<double> x[2];
  for (int32_t threads : {1, 2}) {
    Cholesky chol;
    AnalyzeOptions options;
    options.threads = threads;
    ASSERT_TRUE(chol.analyze(a, options).ok());
    ASSERT_GT(chol.symbolic().value_ptr.back() * 8, int64_t{16} << 20);
    ASSERT_TRUE(chol.factorize(a).ok());
    std::vector<double> b(a.ncols);
    for (int32_t i = 0; i < a.ncols; ++i) b[i] = 1.0 + (i % 7);
    ASSERT_TRUE(chol.solve(b.data(), 1, a.ncols).ok());
    x[threads - 1] = b;
  }
  EXPECT_EQ(std::memcmp(x[0].data(), x[1].data(), x[0].size() * sizeof(double)), 0);
}

}  // namespace
}  // namespace gab
