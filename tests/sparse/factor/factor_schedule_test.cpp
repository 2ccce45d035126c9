// The tree-parallel factorization: the schedule's invariants (groups are
// whole subtrees, the top part is closed upwards, no two live update
// matrices share memory) and a factor bit-identical to the serial one for
// every thread count, SIMD level and failure.
#include "gab/sparse/factor_schedule.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <vector>

#include "gab/sparse/cholesky.h"
#include "sparse/test_matrices.h"

namespace gab {
namespace {

using testing_util::grid_laplacian;
using testing_util::random_spd;
using testing_util::supported_levels;

std::vector<CscMatrix> test_matrices() {
  std::vector<CscMatrix> out;
  out.push_back(grid_laplacian(40, 40));
  out.push_back(grid_laplacian(7, 90));
  out.push_back(random_spd(600, 3.0, 11));
  out.push_back(random_spd(900, 2.0, 12, /*dense_rows=*/2));
  out.push_back(random_spd(800, 2.5, 13, 0, /*blocks=*/5));
  out.push_back(random_spd(1, 0.0, 14));
  out.push_back(random_spd(30, 8.0, 15));
  return out;
}

SymbolicFactor analysis(const CscMatrix& a) {
  SymbolicFactor f;
  EXPECT_TRUE(analyze(a, AnalyzeOptions(), &f).ok());
  return f;
}

TEST(FactorScheduleTest, OneThreadIsTheSerialOrderAndStack) {
  for (const CscMatrix& a : test_matrices()) {
    const SymbolicFactor f = analysis(a);
    const FactorSchedule plan = plan_factor_schedule(f, 1);
    EXPECT_EQ(plan.threads, 1);
    ASSERT_EQ(static_cast<int32_t>(plan.order.size()), f.num_supernodes);
    for (int32_t i = 0; i < f.num_supernodes; ++i) EXPECT_EQ(plan.order[i], i);
    EXPECT_EQ(plan.stack_doubles(), f.stack_peak);
    EXPECT_EQ(plan.group_ptr[2] - plan.group_ptr[1], 0) << "no top part with one thread";
  }
}

// Which group factors each supernode.
std::vector<int32_t> owners(const FactorSchedule& plan, int32_t ns) {
  std::vector<int32_t> owner(ns, -1);
  for (int32_t g = 0; g + 1 < static_cast<int32_t>(plan.group_ptr.size()); ++g) {
    for (int32_t i = plan.group_ptr[g]; i < plan.group_ptr[g + 1]; ++i) {
      EXPECT_EQ(owner[plan.order[i]], -1) << "supernode in two groups";
      owner[plan.order[i]] = g;
      if (i > plan.group_ptr[g]) {
        EXPECT_LT(plan.order[i - 1], plan.order[i]) << "group not in order";
      }
    }
  }
  return owner;
}

TEST(FactorScheduleTest, GroupsAreWholeSubtreesBelowAnUpwardClosedTop) {
  for (const CscMatrix& a : test_matrices()) {
    const SymbolicFactor f = analysis(a);
    for (ScheduleBalance balance : {ScheduleBalance::kFactorFlops, ScheduleBalance::kSolveEntries}) {
      for (int32_t threads = 2; threads <= 4; ++threads) {
        const FactorSchedule plan = plan_factor_schedule(f, threads, balance);
        const int32_t t = plan.threads, ns = f.num_supernodes;
        EXPECT_EQ(t, std::min(threads, ns));
        const std::vector<int32_t> owner = owners(plan, ns);
        ASSERT_EQ(plan.top_rows_ptr.size(), static_cast<size_t>(ns) + 1);
        EXPECT_EQ(plan.top_rows_ptr[0], 0);
        for (int32_t s = 0; s < ns; ++s) {
          ASSERT_NE(owner[s], -1);
          // own_rows splits s's rows below into its group's and the top's
          // (ancestors come after descendants in the rows).
          const int32_t k = f.cols(s), p = f.rows(s) - k;
          const int32_t* below = f.row_ind.data() + f.row_ptr[s] + k;
          for (int32_t i = 0; i < p; ++i) {
            const bool in_top = owner[f.supernode_of[below[i]]] == t;
            EXPECT_EQ(in_top && owner[s] != t, i >= plan.own_rows[s]) << "supernode " << s;
          }
          EXPECT_EQ(plan.top_rows_ptr[s + 1] - plan.top_rows_ptr[s], p - plan.own_rows[s]);
          const int32_t parent = f.supernode_parent[s];
          if (parent == -1) continue;
          // A subtree group's supernode has its parent in the same group or
          // in the top part; the top part's parents are in the top part.
          if (owner[s] == t) {
            EXPECT_EQ(owner[parent], t);
          } else {
            EXPECT_TRUE(owner[parent] == owner[s] || owner[parent] == t);
          }
        }
      }
    }
  }
}

TEST(FactorScheduleTest, LiveUpdateMatricesNeverShareMemory) {
  for (const CscMatrix& a : test_matrices()) {
    const SymbolicFactor f = analysis(a);
    for (int32_t threads = 1; threads <= 3; ++threads) {
      const FactorSchedule plan = plan_factor_schedule(f, threads);
      const int32_t ns = f.num_supernodes;
      const std::vector<int32_t> owner = owners(plan, ns);
      std::vector<int32_t> position(ns);
      for (int32_t i = 0; i < ns; ++i) position[plan.order[i]] = i;
      // An update lives from its front's turn to its parent's (inclusive)
      // if the parent is in the same group, else to the group's end. A
      // chain of panels is one front, its last panel's turn: only that
      // panel has an update.
      std::vector<int64_t> begin(ns), end(ns);
      std::vector<int32_t> born(ns), dies(ns);
      for (int32_t s = 0; s < ns; ++s) {
        begin[s] = plan.update_offset[s];
        end[s] = begin[s] + (f.continues(s) ? 0 : packed_lower_size(f.rows(s) - f.cols(s)));
        int32_t parent = f.supernode_parent[s];
        while (parent != -1 && f.continues(parent)) ++parent;
        const int32_t g = owner[s];
        EXPECT_GE(begin[s], plan.stack_ptr[g]);
        EXPECT_LE(end[s], plan.stack_ptr[g + 1]);
        born[s] = position[s];
        dies[s] = parent != -1 && owner[parent] == g ? position[parent] : plan.group_ptr[g + 1];
      }
      for (int32_t x = 0; x < ns; ++x) {
        for (int32_t y = x + 1; y < ns; ++y) {
          if (owner[x] != owner[y] || begin[x] == end[x] || begin[y] == end[y]) continue;
          const bool live_together = born[x] <= dies[y] && born[y] <= dies[x];
          const bool overlap = begin[x] < end[y] && begin[y] < end[x];
          EXPECT_FALSE(live_together && overlap) << "updates of " << x << " and " << y;
        }
      }
    }
  }
}

TEST(FactorScheduleTest, TwoThreadsShortenTheCriticalPathOfAGrid) {
  // A 2D grid's tree splits under its top separator into halves of equal
  // work: the longer thread plus the top part is well under the whole.
  // Likewise for the solves' balance, whose top part is lighter still.
  const SymbolicFactor f = analysis(grid_laplacian(120, 120));
  for (ScheduleBalance balance : {ScheduleBalance::kFactorFlops, ScheduleBalance::kSolveEntries}) {
    const FactorSchedule plan = plan_factor_schedule(f, 2, balance);
    const double total = plan.group_work[0] + plan.group_work[1] + plan.group_work[2];
    const double critical = std::max(plan.group_work[0], plan.group_work[1]) + plan.group_work[2];
    EXPECT_LT(critical, 0.75 * total);
    EXPECT_GT(plan.group_ptr[1] - plan.group_ptr[0], 0);
    EXPECT_GT(plan.group_ptr[2] - plan.group_ptr[1], 0);
  }
}

// The factor's values with `threads` threads and the kernels of `level`.
std::vector<double> factor_values(const CscMatrix& a, int32_t threads, SimdLevel level,
                                  Status* status) {
  Cholesky chol;
  chol.set_kernels(dense_kernels(level));
  AnalyzeOptions options;
  options.threads = threads;
  EXPECT_TRUE(chol.analyze(a, options).ok());
  *status = chol.factorize(a);
  const int64_t size = chol.symbolic().value_ptr.back();
  std::vector<double> values(chol.values(), chol.values() + size);
  // The strict upper triangles of the diagonal blocks are unspecified.
  const SymbolicFactor& f = chol.symbolic();
  for (int32_t s = 0; s < f.num_supernodes; ++s) {
    for (int32_t j = 0; j < f.cols(s); ++j) {
      for (int32_t i = 0; i < j; ++i) values[f.value_ptr[s] + static_cast<int64_t>(j) * f.rows(s) + i] = 0.0;
    }
  }
  return values;
}

TEST(FactorScheduleTest, FactorIsBitIdenticalForEveryThreadCount) {
  // A 150 x 150 grid's top separators are fronts large enough for the
  // threads to share their kernel calls (kernel_team.h).
  std::vector<CscMatrix> matrices = test_matrices();
  matrices.push_back(grid_laplacian(150, 150));
  for (const SimdLevel level : supported_levels()) {
    for (const CscMatrix& a : matrices) {
      Status status;
      const std::vector<double> serial = factor_values(a, 1, level, &status);
      ASSERT_TRUE(status.ok()) << status.message();
      for (int32_t threads = 2; threads <= 4; ++threads) {
        const std::vector<double> parallel = factor_values(a, threads, level, &status);
        ASSERT_TRUE(status.ok()) << status.message();
        ASSERT_EQ(serial.size(), parallel.size());
        EXPECT_EQ(std::memcmp(serial.data(), parallel.data(), serial.size() * sizeof(double)), 0)
            << "n = " << a.ncols << ", threads = " << threads << ", " << simd_level_name(level);
      }
    }
  }
}

// x = A^{-1} b for three right-hand sides, factored and solved on `threads`.
std::vector<double> solution(const CscMatrix& a, int32_t threads, SimdLevel level) {
  Cholesky chol;
  chol.set_kernels(dense_kernels(level));
  AnalyzeOptions options;
  options.threads = threads;
  EXPECT_TRUE(chol.analyze(a, options).ok());
  EXPECT_TRUE(chol.factorize(a).ok());
  const int32_t n = a.ncols;
  std::vector<double> x(3 * static_cast<size_t>(n));
  for (size_t i = 0; i < x.size(); ++i) x[i] = std::sin(0.37 * static_cast<double>(i)) + 0.1;
  EXPECT_TRUE(chol.solve(x.data(), 3, n).ok());
  return x;
}

TEST(FactorScheduleTest, SolvesAreBitIdenticalForEveryThreadCount) {
  // The parallel forward solve defers each group's additions into the top
  // part to one in-order pass; the sums must still come out bit for bit.
  std::vector<CscMatrix> matrices = test_matrices();
  matrices.push_back(grid_laplacian(150, 150));
  for (const SimdLevel level : supported_levels()) {
    for (const CscMatrix& a : matrices) {
      const std::vector<double> serial = solution(a, 1, level);
      for (int32_t threads = 2; threads <= 4; ++threads) {
        const std::vector<double> parallel = solution(a, threads, level);
        EXPECT_TRUE(parallel == serial)
            << "n = " << a.ncols << ", threads = " << threads << ", " << simd_level_name(level);
      }
      // And it is the solution: A x = b to rounding (first right-hand side).
      const int32_t n = a.ncols;
      std::vector<double> ax(n);
      symmetric_lower_matvec(a, serial.data(), ax.data());
      double worst = 0.0;
      for (int32_t i = 0; i < n; ++i) {
        worst = std::max(worst, std::abs(ax[i] - (std::sin(0.37 * i) + 0.1)));
      }
      EXPECT_LT(worst, 1e-9) << "n = " << n;
    }
  }
}

TEST(FactorScheduleTest, TheFirstFailingPivotIsReportedWhicheverThreadMeetsIt) {
  // Five disconnected blocks (so several subtrees), two of them indefinite:
  // every thread count names the pivot the serial factorization names.
  CscMatrix a = random_spd(500, 2.5, 21, 0, /*blocks=*/5);
  for (const int32_t bad : {60, 430}) {
    for (int32_t p = a.colptr[bad]; p < a.colptr[bad + 1]; ++p) {
      if (a.rowind[p] == bad) a.values[p] = -1.0;
    }
  }
  Status serial;
  factor_values(a, 1, cpu_simd_level(), &serial);
  ASSERT_EQ(serial.code(), StatusCode::kNotPositiveDefinite);
  for (int32_t threads = 2; threads <= 5; ++threads) {
    Status parallel;
    factor_values(a, threads, cpu_simd_level(), &parallel);
    EXPECT_EQ(parallel.message(), serial.message()) << threads << " threads";
  }
}

}  // namespace
}  // namespace gab
