// Every dense-kernel level the CPU supports against naive triple-loop
// references: shapes around the register-tile and vector widths (0, 1, 2, 3,
// 7, 8, 9, 15, 16, 17, 31, 33), padded leading dimensions whose padding must
// survive untouched, shapes large enough to take the packed and cache-blocked
// paths, and POTRF's failure contract.
#include "gab/sparse/dense_kernels.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace gab {
namespace {

constexpr int32_t kEdgeSizes[] = {0, 1, 2, 3, 7, 8, 9, 15, 16, 17, 31, 33};
constexpr double kEps = std::numeric_limits<double>::epsilon();
// Distinctive value for entries no kernel may write.
constexpr double kCanary = -7.0e77;

// A column-major rows x cols matrix inside a buffer with leading dimension
// ld >= rows; the padding rows start as kCanary. The buffer ends right after
// the last column's last row, the least a BLAS-style caller passes, so any
// access past it is an error the sanitizer build reports.
struct Padded {
  int32_t rows = 0;
  int32_t cols = 0;
  int32_t ld = 1;
  std::vector<double> data;

  Padded(int32_t r, int32_t c, int32_t extra_ld) : rows(r), cols(c), ld(std::max(1, r + extra_ld)) {
    data.assign(c == 0 ? 0 : static_cast<size_t>(ld) * (c - 1) + r, kCanary);
  }
  double& at(int32_t i, int32_t j) { return data[i + static_cast<size_t>(j) * ld]; }
  const double& at(int32_t i, int32_t j) const { return data[i + static_cast<size_t>(j) * ld]; }
  double* ptr() { return data.data(); }
  const double* ptr() const { return data.data(); }
  void fill_random(std::mt19937_64* rng) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int32_t j = 0; j < cols; ++j) {
      for (int32_t i = 0; i < rows; ++i) at(i, j) = u(*rng);
    }
  }
};

// Number of buffer entries outside the rows x cols block that changed.
int64_t padding_changes(const Padded& before, const Padded& after) {
  int64_t changed = 0;
  for (size_t t = 0; t < after.data.size(); ++t) {
    const int64_t i = static_cast<int64_t>(t % after.ld);
    const int64_t j = static_cast<int64_t>(t / after.ld);
    const bool inside = i < after.rows && j < after.cols;
    if (!inside && std::memcmp(&before.data[t], &after.data[t], sizeof(double)) != 0) ++changed;
  }
  return changed;
}

int32_t extra_ld(int32_t salt) {
  constexpr int32_t kExtras[] = {0, 1, 3, 5, 2};
  return kExtras[salt % 5];
}

// The level under test, or a skip if this CPU lacks it.
class DenseKernelLevels : public ::testing::TestWithParam<SimdLevel> {
 protected:
  void SetUp() override {
    if (dense_kernels(GetParam()).level != GetParam()) {
      GTEST_SKIP() << "CPU lacks " << simd_level_name(GetParam());
    }
  }
  const DenseKernels& k() const { return dense_kernels(GetParam()); }
};

// C -= A B^T on (m, n, k); checks every entry against the reference with a
// componentwise bound and the padding of C for untouched entries.
void check_gemm(const DenseKernels& kern, int32_t m, int32_t n, int32_t k, int32_t salt) {
  std::mt19937_64 rng(1000003u * m + 1009u * n + k);
  Padded a(m, k, extra_ld(salt)), b(n, k, extra_ld(salt + 1)), c(m, n, extra_ld(salt + 2));
  a.fill_random(&rng);
  b.fill_random(&rng);
  c.fill_random(&rng);
  const Padded c0 = c;
  kern.gemm_nt_sub(m, n, k, a.ptr(), a.ld, b.ptr(), b.ld, c.ptr(), c.ld);
  // Reference column by column in axpy order (plain loops, but fast enough
  // for the large shapes); mag bounds the rounding error of any order.
  double worst = 0.0;
  std::vector<double> ref(m), mag(m);
  for (int32_t j = 0; j < n; ++j) {
    for (int32_t i = 0; i < m; ++i) {
      ref[i] = c0.at(i, j);
      mag[i] = std::abs(ref[i]);
    }
    for (int32_t p = 0; p < k; ++p) {
      const double bjp = b.at(j, p);
      const double* ap = a.ptr() + static_cast<size_t>(p) * a.ld;
      for (int32_t i = 0; i < m; ++i) {
        ref[i] -= ap[i] * bjp;
        mag[i] += std::abs(ap[i] * bjp);
      }
    }
    for (int32_t i = 0; i < m; ++i) {
      worst = std::max(worst, std::abs(c.at(i, j) - ref[i]) / (mag[i] * kEps * (k + 2)));
    }
  }
  EXPECT_LE(worst, 2.0) << "gemm m=" << m << " n=" << n << " k=" << k;
  EXPECT_EQ(padding_changes(c0, c), 0) << "gemm m=" << m << " n=" << n << " k=" << k;
}

// Lower(C) -= A A^T; the strict upper triangle and the padding must keep
// their bits.
void check_syrk(const DenseKernels& kern, int32_t n, int32_t k, int32_t salt) {
  std::mt19937_64 rng(7919u * n + k);
  Padded a(n, k, extra_ld(salt)), c(n, n, extra_ld(salt + 3));
  a.fill_random(&rng);
  c.fill_random(&rng);
  const Padded c0 = c;
  kern.syrk_lower_sub(n, k, a.ptr(), a.ld, c.ptr(), c.ld);
  double worst = 0.0;
  int64_t upper_changed = 0;
  std::vector<double> ref(n), mag(n);
  for (int32_t j = 0; j < n; ++j) {
    for (int32_t i = 0; i < j; ++i) {
      if (std::memcmp(&c.at(i, j), &c0.at(i, j), sizeof(double)) != 0) ++upper_changed;
    }
    for (int32_t i = j; i < n; ++i) {
      ref[i] = c0.at(i, j);
      mag[i] = std::abs(ref[i]);
    }
    for (int32_t p = 0; p < k; ++p) {
      const double ajp = a.at(j, p);
      const double* ap = a.ptr() + static_cast<size_t>(p) * a.ld;
      for (int32_t i = j; i < n; ++i) {
        ref[i] -= ap[i] * ajp;
        mag[i] += std::abs(ap[i] * ajp);
      }
    }
    for (int32_t i = j; i < n; ++i) {
      worst = std::max(worst, std::abs(c.at(i, j) - ref[i]) / (mag[i] * kEps * (k + 2)));
    }
  }
  EXPECT_LE(worst, 2.0) << "syrk n=" << n << " k=" << k;
  EXPECT_EQ(upper_changed, 0) << "syrk n=" << n << " k=" << k;
  EXPECT_EQ(padding_changes(c0, c), 0) << "syrk n=" << n << " k=" << k;
}

// A well-conditioned lower triangular n x n L (diagonal in [1, 2],
// off-diagonal entries of size 1/n) in a padded buffer whose strict upper
// triangle holds canaries.
Padded well_conditioned_lower(int32_t n, int32_t salt, std::mt19937_64* rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Padded l(n, n, extra_ld(salt));
  for (int32_t j = 0; j < n; ++j) {
    l.at(j, j) = 1.5 + 0.5 * u(*rng);
    for (int32_t i = j + 1; i < n; ++i) l.at(i, j) = u(*rng) / n;
  }
  return l;
}

// B := B L^{-T} against column-by-column forward substitution.
void check_trsm(const DenseKernels& kern, int32_t m, int32_t n, int32_t salt) {
  std::mt19937_64 rng(104729u * m + n);
  const Padded l = well_conditioned_lower(n, salt, &rng);
  Padded b(m, n, extra_ld(salt + 1));
  b.fill_random(&rng);
  const Padded b0 = b;
  const Padded l0 = l;
  kern.trsm_right_lower_trans(m, n, l.ptr(), l.ld, b.ptr(), b.ld);
  // Reference: x_j = (b_j - sum_{p<j} x_p l_jp) / l_jj.
  Padded x = b0;
  for (int32_t j = 0; j < n; ++j) {
    for (int32_t i = 0; i < m; ++i) {
      double s = x.at(i, j);
      for (int32_t p = 0; p < j; ++p) s -= x.at(i, p) * l.at(j, p);
      x.at(i, j) = s / l.at(j, j);
    }
  }
  double worst = 0.0;
  double scale = 1.0;
  for (int32_t j = 0; j < n; ++j) {
    for (int32_t i = 0; i < m; ++i) {
      scale = std::max(scale, std::abs(x.at(i, j)));
      worst = std::max(worst, std::abs(b.at(i, j) - x.at(i, j)));
    }
  }
  EXPECT_LE(worst / scale, 1e-13) << "trsm m=" << m << " n=" << n;
  EXPECT_EQ(padding_changes(b0, b), 0) << "trsm m=" << m << " n=" << n;
  EXPECT_EQ(l.data, l0.data);
}

// A = B B^T + n I in the lower triangle of a padded buffer; the strict upper
// triangle and the padding hold canaries.
Padded spd_matrix(int32_t n, int32_t salt) {
  std::mt19937_64 rng(15485863u * n + salt);
  Padded b(n, n, 0);
  b.fill_random(&rng);
  Padded a(n, n, extra_ld(salt));
  for (int32_t j = 0; j < n; ++j) {
    for (int32_t i = j; i < n; ++i) {
      double s = i == j ? n : 0.0;
      for (int32_t p = 0; p < n; ++p) s += b.at(i, p) * b.at(j, p);
      a.at(i, j) = s;
    }
  }
  return a;
}

// max |L L^T - A| / max |A| over the lower triangle.
double factor_residual(const Padded& a, const Padded& l) {
  double worst = 0.0;
  double scale = 0.0;
  for (int32_t j = 0; j < a.cols; ++j) {
    for (int32_t i = j; i < a.rows; ++i) {
      double s = 0.0;
      for (int32_t p = 0; p <= j; ++p) s += l.at(i, p) * l.at(j, p);
      worst = std::max(worst, std::abs(s - a.at(i, j)));
      scale = std::max(scale, std::abs(a.at(i, j)));
    }
  }
  return scale > 0.0 ? worst / scale : worst;
}

void check_potrf_spd(const DenseKernels& kern, int32_t n, int32_t salt) {
  const Padded a = spd_matrix(n, salt);
  Padded l = a;
  EXPECT_EQ(kern.potrf(n, l.ptr(), l.ld), -1) << "potrf n=" << n;
  EXPECT_LE(factor_residual(a, l), 1e-12) << "potrf n=" << n;
  // Canaries in the strict upper triangle and the padding must survive.
  EXPECT_EQ(padding_changes(a, l), 0) << "potrf n=" << n;
  int64_t upper_changed = 0;
  for (int32_t j = 0; j < n; ++j) {
    for (int32_t i = 0; i < j; ++i) upper_changed += l.at(i, j) != kCanary;
  }
  EXPECT_EQ(upper_changed, 0) << "potrf n=" << n;
}

TEST(DenseSimd, LevelNames) {
  EXPECT_STREQ(simd_level_name(SimdLevel::kScalar), "scalar");
  EXPECT_STREQ(simd_level_name(SimdLevel::kAvx2), "avx2");
  EXPECT_STREQ(simd_level_name(SimdLevel::kAvx512), "avx512");
}

TEST(DenseSimd, RequestedLevelFallsBackToSupported) {
  const SimdLevel cpu = cpu_simd_level();
  for (SimdLevel want : {SimdLevel::kScalar, SimdLevel::kAvx2, SimdLevel::kAvx512}) {
    const SimdLevel expect = static_cast<int>(want) <= static_cast<int>(cpu) ? want : cpu;
    EXPECT_EQ(dense_kernels(want).level, expect) << simd_level_name(want);
  }
  EXPECT_EQ(dense_kernels(SimdLevel::kScalar).level, SimdLevel::kScalar);
}

TEST(DenseSimd, CapNamesParse) {
  const SimdLevel cpu = cpu_simd_level();
  auto capped = [cpu](SimdLevel want) {
    return static_cast<int>(want) <= static_cast<int>(cpu) ? want : cpu;
  };
  EXPECT_EQ(simd_level_for_cap(nullptr), cpu);
  EXPECT_EQ(simd_level_for_cap(""), cpu);
  EXPECT_EQ(simd_level_for_cap("sse9"), cpu);
  EXPECT_EQ(simd_level_for_cap("scalar"), SimdLevel::kScalar);
  EXPECT_EQ(simd_level_for_cap("avx2"), capped(SimdLevel::kAvx2));
  EXPECT_EQ(simd_level_for_cap("avx512"), capped(SimdLevel::kAvx512));
  // A level the CPU lacks falls back to the best below it.
  for (SimdLevel level : {SimdLevel::kScalar, SimdLevel::kAvx2, SimdLevel::kAvx512}) {
    EXPECT_EQ(dense_kernels(level).level, capped(level)) << simd_level_name(level);
  }
}

// dense_kernels() reads GAB_SIMD once, so the variable is tested in a fresh
// process: the "threadsafe" death-test style re-executes this binary.
TEST(DenseSimdDeathTest, EnvironmentCapAppliesInFreshProcess) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
      {
        setenv("GAB_SIMD", "scalar", 1);
        std::exit(dense_kernels().level == SimdLevel::kScalar ? 0 : 1);
      },
      ::testing::ExitedWithCode(0), "");
  const SimdLevel avx2 = simd_level_for_cap("avx2");
  EXPECT_EXIT(
      {
        setenv("GAB_SIMD", "avx2", 1);
        std::exit(dense_kernels().level == avx2 ? 0 : 1);
      },
      ::testing::ExitedWithCode(0), "");
}

TEST_P(DenseKernelLevels, GemmEdgeShapes) {
  int32_t salt = 0;
  for (int32_t m : kEdgeSizes) {
    for (int32_t n : kEdgeSizes) {
      for (int32_t kk : kEdgeSizes) check_gemm(k(), m, n, kk, salt++);
    }
  }
}

TEST_P(DenseKernelLevels, GemmPackedAndBlockedShapes) {
  // A of 300 x 250 overflows the unpacked threshold; k = 700 crosses the
  // inner-dimension block; n = 1601 the column block; odd sizes everywhere
  // leave partial tiles at every level.
  check_gemm(k(), 300, 250, 260, 1);
  check_gemm(k(), 97, 401, 700, 2);
  check_gemm(k(), 40, 1601, 1650, 3);
  check_gemm(k(), 1000, 17, 100, 4);
  check_gemm(k(), 450, 23, 160, 0);
}

TEST_P(DenseKernelLevels, SyrkEdgeShapes) {
  int32_t salt = 0;
  for (int32_t n : kEdgeSizes) {
    for (int32_t kk : kEdgeSizes) check_syrk(k(), n, kk, salt++);
  }
  for (int32_t n : {40, 57, 64, 100}) check_syrk(k(), n, 16, salt++);
}

TEST_P(DenseKernelLevels, SyrkPackedAndBlockedShapes) {
  check_syrk(k(), 400, 200, 1);  // packed, several row blocks
  check_syrk(k(), 333, 701, 2);  // several inner-dimension blocks
  check_syrk(k(), 1601, 45, 3);  // several column blocks
  check_syrk(k(), 217, 317, 4);
}

// The packed form of SYRK (update matrices, packed_lower_column) against
// the square form: the same bits on every lower entry, and nothing else in
// the packed buffer written (the slack above the diagonal in each panel).
void check_syrk_packed(const DenseKernels& kern, int32_t n, int32_t k) {
  std::mt19937_64 rng(104729u * n + k);
  Padded a(n, k, 1), c(n, n, 0);
  a.fill_random(&rng);
  c.fill_random(&rng);
  std::vector<double> packed(static_cast<size_t>(packed_lower_size(n)), kCanary);
  for (int32_t j = 0; j < n; ++j) {
    for (int32_t i = j; i < n; ++i) packed_lower_column(packed.data(), n, j)[i] = c.at(i, j);
  }
  kern.syrk_lower_sub(n, k, a.ptr(), a.ld, c.ptr(), c.ld);
  kern.syrk_lower_sub_packed(n, k, a.ptr(), a.ld, packed.data());
  int64_t differ = 0, lower = 0;
  for (int32_t j = 0; j < n; ++j) {
    for (int32_t i = j; i < n; ++i) {
      differ += std::memcmp(&packed_lower_column(packed.data(), n, j)[i], &c.at(i, j), sizeof(double)) != 0;
      packed_lower_column(packed.data(), n, j)[i] = kCanary;  // then every entry must be the canary
      ++lower;
    }
  }
  EXPECT_EQ(differ, 0) << "n=" << n << " k=" << k;
  EXPECT_EQ(std::count(packed.begin(), packed.end(), kCanary), static_cast<int64_t>(packed.size()))
      << "n=" << n << " k=" << k << ": written outside the lower triangle";
  EXPECT_LE(static_cast<int64_t>(packed.size()), lower + static_cast<int64_t>(n) * kPackedLowerPanel / 2)
      << "n=" << n;
}

TEST(PackedLower, EveryLowerEntryHasItsOwnSlot) {
  for (int32_t n : {0, 1, 2, 15, 16, 17, 31, 32, 33, 100, 257}) {
    std::vector<int32_t> hits(static_cast<size_t>(packed_lower_size(n)), 0);
    std::vector<double> storage(hits.size() + 1);
    double* base = storage.data();
    for (int32_t j = 0; j < n; ++j) {
      double* column = packed_lower_column(base, n, j);
      for (int32_t i = j; i < n; ++i) {
        const ptrdiff_t at = column + i - base;
        ASSERT_GE(at, 0) << n << " " << i << " " << j;
        ASSERT_LT(at, static_cast<ptrdiff_t>(hits.size())) << n << " " << i << " " << j;
        ++hits[at];
      }
      EXPECT_EQ(packed_lower_ld(n, j), n - j / kPackedLowerPanel * kPackedLowerPanel);
      // A panel's columns are ld apart.
      if (j % kPackedLowerPanel != 0) {
        EXPECT_EQ(column - packed_lower_column(base, n, j - 1), packed_lower_ld(n, j));
      }
    }
    EXPECT_EQ(std::count(hits.begin(), hits.end(), 1), static_cast<int64_t>(n) * (n + 1) / 2) << n;
    EXPECT_EQ(std::count(hits.begin(), hits.end(), 2), 0) << n;
  }
  EXPECT_EQ(packed_lower_size(0), 0);
  EXPECT_EQ(packed_lower_size(kPackedLowerPanel), int64_t{kPackedLowerPanel} * kPackedLowerPanel);
}

TEST_P(DenseKernelLevels, SyrkPackedMatchesSquareBitForBit) {
  for (int32_t n : kEdgeSizes) {
    for (int32_t kk : {1, 5, 16}) check_syrk_packed(k(), n, kk);
  }
  check_syrk_packed(k(), 100, 40);
  check_syrk_packed(k(), 400, 200);  // packed operands, several row blocks
  check_syrk_packed(k(), 333, 701);  // several inner-dimension blocks
  check_syrk_packed(k(), 1601, 45);  // several column blocks
}

TEST_P(DenseKernelLevels, TrsmEdgeShapes) {
  int32_t salt = 0;
  for (int32_t m : kEdgeSizes) {
    for (int32_t n : kEdgeSizes) check_trsm(k(), m, n, salt++);
  }
}

TEST_P(DenseKernelLevels, TrsmRecursiveShapes) {
  check_trsm(k(), 500, 300, 1);  // recursion reaches the packed GEMM
  check_trsm(k(), 1, 100, 2);
  check_trsm(k(), 37, 65, 3);
  check_trsm(k(), 250, 129, 4);
}

TEST_P(DenseKernelLevels, PotrfFactorsSpd) {
  int32_t salt = 0;
  for (int32_t n : kEdgeSizes) check_potrf_spd(k(), n, salt++);
  for (int32_t n : {4, 5, 6, 24, 25, 64, 100, 130, 301}) check_potrf_spd(k(), n, salt++);
}

TEST_P(DenseKernelLevels, PotrfReportsFirstFailingColumn) {
  for (int32_t n : {1, 2, 5, 8, 9, 17, 33, 64, 200}) {
    const Padded a = spd_matrix(n, 11);
    // The pivot of column j is a_jj - sum_{p<j} l_jp^2 = l_jj^2; lowering
    // a_jj by l_jj^2 + 1 turns it into -1 and leaves every earlier column
    // as it was.
    Padded l = a;
    ASSERT_EQ(k().potrf(n, l.ptr(), l.ld), -1);
    for (int32_t j : {0, n / 2, n - 1}) {
      Padded bad = a;
      bad.at(j, j) -= l.at(j, j) * l.at(j, j) + 1.0;
      EXPECT_EQ(k().potrf(n, bad.ptr(), bad.ld), j) << "n=" << n << " j=" << j;
      // Columns before j hold their factor.
      double worst = 0.0;
      for (int32_t c = 0; c < j; ++c) {
        for (int32_t i = c; i < n; ++i)
          worst = std::max(worst, std::abs(bad.at(i, c) - l.at(i, c)));
      }
      EXPECT_LE(worst, 1e-10 * n) << "n=" << n << " j=" << j;
      int64_t upper_changed = 0;
      for (int32_t c = 0; c < n; ++c) {
        for (int32_t i = 0; i < c; ++i) upper_changed += bad.at(i, c) != kCanary;
      }
      EXPECT_EQ(upper_changed, 0);
      EXPECT_EQ(padding_changes(a, bad), 0);

      // A zero pivot fails the same way as a negative one.
      Padded zero = a;
      zero.at(j, j) -= l.at(j, j) * l.at(j, j);
      const int32_t at = k().potrf(n, zero.ptr(), zero.ld);
      // Rounding may leave the pivot a hair above zero; it must not pass
      // silently at an earlier column.
      EXPECT_TRUE(at == j || at == -1 || at > j) << "n=" << n << " j=" << j << " got " << at;

      // NaN or infinity on the diagonal fails at that column.
      Padded nan = a;
      nan.at(j, j) = std::numeric_limits<double>::quiet_NaN();
      EXPECT_EQ(k().potrf(n, nan.ptr(), nan.ld), j) << "NaN n=" << n << " j=" << j;
      Padded inf = a;
      inf.at(j, j) = std::numeric_limits<double>::infinity();
      EXPECT_EQ(k().potrf(n, inf.ptr(), inf.ld), j) << "inf n=" << n << " j=" << j;

      // A NaN below the diagonal at (i, j) first reaches a pivot at column i.
      if (j + 1 < n) {
        const int32_t i = std::min(n - 1, j + 1 + n / 3);
        Padded off = a;
        off.at(i, j) = std::numeric_limits<double>::quiet_NaN();
        EXPECT_EQ(k().potrf(n, off.ptr(), off.ld), i) << "NaN at (" << i << ", " << j << ")";
      }
    }
  }
  // An all-zero matrix fails at once; n = 0 succeeds.
  Padded zeros(7, 7, 2);
  for (int32_t j = 0; j < 7; ++j) {
    for (int32_t i = j; i < 7; ++i) zeros.at(i, j) = 0.0;
  }
  EXPECT_EQ(k().potrf(7, zeros.ptr(), zeros.ld), 0);
  EXPECT_EQ(k().potrf(0, zeros.ptr(), zeros.ld), -1);
}

TEST_P(DenseKernelLevels, ZeroInnerDimensionIsANoOp) {
  Padded c(9, 9, 3);
  std::mt19937_64 rng(5);
  c.fill_random(&rng);
  const Padded c0 = c;
  const double unused[1] = {1.0};
  k().gemm_nt_sub(9, 9, 0, unused, 9, unused, 9, c.ptr(), c.ld);
  k().syrk_lower_sub(9, 0, unused, 9, c.ptr(), c.ld);
  k().trsm_right_lower_trans(0, 9, unused, 9, c.ptr(), c.ld);
  EXPECT_EQ(c.data, c0.data);
}

std::string level_name(const ::testing::TestParamInfo<SimdLevel>& info) {
  return simd_level_name(info.param);
}

INSTANTIATE_TEST_SUITE_P(Dense, DenseKernelLevels,
                         ::testing::Values(SimdLevel::kScalar, SimdLevel::kAvx2,
                                           SimdLevel::kAvx512),
                         level_name);

}  // namespace
}  // namespace gab
