// The updater's helper thread: updates on two threads must give the factor
// one thread gives, bit for bit, whatever the helper was doing (spinning,
// asleep, just started), and the row split must keep its invariants.
#include "update_team.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>
#include <thread>
#include <vector>

#include "gab/sparse/cholesky.h"
#include "test_matrices.h"

namespace gab {
namespace {

using update_detail::RowTeam;

// 7-point Laplacian of an n^3 grid plus a shift: its separator supernodes
// (n^2 columns at the root) are large enough for the helper to share.
CscMatrix grid3d_laplacian(int32_t n) {
  std::vector<Triplet> t;
  auto id = [n](int32_t x, int32_t y, int32_t z) { return (z * n + y) * n + x; };
  for (int32_t z = 0; z < n; ++z)
    for (int32_t y = 0; y < n; ++y)
      for (int32_t x = 0; x < n; ++x) {
        if (x + 1 < n) t.push_back({id(x + 1, y, z), id(x, y, z), -1.0});
        if (y + 1 < n) t.push_back({id(x, y + 1, z), id(x, y, z), -1.0});
        if (z + 1 < n) t.push_back({id(x, y, z + 1), id(x, y, z), -1.0});
        t.push_back({id(x, y, z), id(x, y, z), 6.01});
      }
  CscMatrix a;
  csc_from_triplets(n * n * n, n * n * n, t, &a);
  return a;
}

// Anchors whose paths start at the first column of every supernode the
// helper shares (so those passes run whole), then a spread of others.
std::vector<int32_t> anchors_through_shared_supernodes(const SymbolicFactor& f) {
  std::vector<int32_t> js;
  for (int32_t s = 0; s < f.num_supernodes; ++s) {
    if (RowTeam::worth_sharing(f.rows(s), f.cols(s), 0)) js.push_back(f.perm[f.first_col[s]]);
  }
  for (int32_t j = 0; j < f.n; j += 97) js.push_back(j);
  return js;
}

std::vector<double> lower_trapezoids(const Cholesky& chol) {
  const SymbolicFactor& f = chol.symbolic();
  std::vector<double> out;
  for (int32_t s = 0; s < f.num_supernodes; ++s) {
    const int32_t m = f.rows(s);
    for (int32_t c = 0; c < f.cols(s); ++c)
      for (int32_t t = c; t < m; ++t) out.push_back(chol.values()[f.value_ptr[s] + int64_t{c} * m + t]);
  }
  return out;
}

// Single updates (with pauses that let the helper fall asleep), then
// batches, on `threads` threads.
std::vector<double> updated_factor(const CscMatrix& a, int32_t threads, SimdLevel level,
                                   int32_t* shared_supernodes) {
  Cholesky chol;
  AnalyzeOptions options;
  options.threads = threads;
  chol.set_kernels(dense_kernels(level));
  EXPECT_TRUE(chol.analyze(a, options).ok());
  EXPECT_TRUE(chol.factorize(a).ok());
  const std::vector<int32_t> js = anchors_through_shared_supernodes(chol.symbolic());
  *shared_supernodes = static_cast<int32_t>(js.size()) - (a.ncols + 96) / 97;
  for (size_t i = 0; i < js.size(); ++i) {
    EXPECT_TRUE(chol.add_anchor(js[i], 1.0 + 0.25 * (i % 3)).ok());
    if (i % 7 == 3) std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  EXPECT_TRUE(chol.add_anchors(js.data(), static_cast<int32_t>(js.size()), 0.5).ok());
  // A moved Cholesky keeps its helper.
  Cholesky moved = std::move(chol);
  EXPECT_TRUE(moved.add_anchors(js.data(), 5, 2.0).ok());
  return lower_trapezoids(moved);
}

TEST(UpdateTeamTest, TwoThreadsGiveTheOneThreadFactorBitForBit) {
  const CscMatrix a = grid3d_laplacian(20);
  for (SimdLevel level : testing_util::supported_levels()) {
    int32_t shared = 0;
    const std::vector<double> one = updated_factor(a, 1, level, &shared);
    ASSERT_GE(shared, 3);  // the test reaches the shared path
    const std::vector<double> two = updated_factor(a, 2, level, &shared);
    ASSERT_EQ(one.size(), two.size());
    for (size_t i = 0; i < one.size(); ++i) ASSERT_EQ(one[i], two[i]) << simd_level_name(level) << " entry " << i;
  }
}

TEST(UpdateTeamTest, TwoThreadUpdatesMatchAFreshFactorization) {
  CscMatrix a = grid3d_laplacian(18);
  Cholesky chol;
  AnalyzeOptions options;
  options.threads = 2;
  ASSERT_TRUE(chol.analyze(a, options).ok());
  ASSERT_TRUE(chol.factorize(a).ok());
  const std::vector<int32_t> js = anchors_through_shared_supernodes(chol.symbolic());
  ASSERT_GT(js.size(), static_cast<size_t>((a.ncols + 96) / 97));  // some pass is shared
  for (int32_t j : js) ASSERT_TRUE(chol.add_anchor(j, 2.0).ok());
  for (int32_t j : js) {
    for (int32_t p = a.colptr[j]; p < a.colptr[j + 1]; ++p) {
      if (a.rowind[p] == j) a.values[p] += 4.0;
    }
  }
  Cholesky fresh;
  AnalyzeOptions same;
  same.ordering = Ordering::kGiven;
  same.given_perm = chol.symbolic().perm;
  ASSERT_TRUE(fresh.analyze(a, same).ok());
  ASSERT_TRUE(fresh.factorize(a).ok());
  const std::vector<double> updated = lower_trapezoids(chol), expected = lower_trapezoids(fresh);
  double diff = 0.0, scale = 0.0;
  for (size_t i = 0; i < updated.size(); ++i) {
    diff = std::max(diff, std::abs(updated[i] - expected[i]));
    scale = std::max(scale, std::abs(expected[i]));
  }
  EXPECT_LT(diff / scale, 1e-12);
}

TEST(UpdateTeamTest, SplitKeepsTheNextTriangleMovesRarelyAndBalances) {
  for (int32_t m : {1, 100, 128, 129, 300, 2049}) {
    for (int32_t k : {1, 16, 100, m}) {
      if (k > m) continue;
      const int32_t runs = (k + 15) / 16;
      int32_t split = 0, moves = 0;
      int64_t leader = 0, helper = 0;
      for (int32_t r = 0; r < runs; ++r) {
        const int32_t below = std::min(16 * (r + 1), k);
        const int32_t next = update_detail::split_rows(m, below, 16, runs - r, split);
        EXPECT_GE(next, split);
        EXPECT_LE(next, m);
        // The next run's triangle (up to 16 rows below) is the leader's.
        EXPECT_TRUE(next == m || next >= below + 16) << m << " " << k << " " << below;
        moves += r > 0 && next != split;
        split = next;
        leader += split - below;
        helper += m - split;
      }
      EXPECT_LE(moves, 8) << m << " " << k;
      // Where the helper takes part, neither thread gets twice the other's rows.
      if (helper > 0) {
        EXPECT_LE(leader, 2 * helper + 64 * runs) << m << " " << k;
        EXPECT_LE(helper, 2 * leader + 64 * runs) << m << " " << k;
      }
    }
  }
}

// A pass through the team against the same runs on one thread, on random
// blocks and rotations (the rotations are ready before the pass, so the
// leader's compute step has nothing to do).
TEST(UpdateTeamTest, SharedPassEqualsTheSerialPass) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  RowTeam team;
  for (SimdLevel level : testing_util::supported_levels()) {
    for (int32_t trial = 0; trial < 12; ++trial) {
      const int32_t m = 130 + trial * 97, k = std::min(m, 20 + trial * 41), c0 = trial % 7;
      const int32_t nvec = trial % 3 == 0 ? 0 : 1 + trial % 8;
      const int32_t vecs = std::max(nvec, 1);
      std::vector<double> block(static_cast<size_t>(m) * k), x(static_cast<size_t>(m) * vecs);
      std::vector<double> c(static_cast<size_t>(k) * vecs), s(c.size());
      for (double& v : block) v = u(rng);
      for (double& v : x) v = u(rng);
      for (size_t i = 0; i < c.size(); ++i) {
        const double angle = 3.0 * u(rng);
        c[i] = std::cos(angle);
        s[i] = std::sin(angle);
      }
      std::vector<double> block2 = block, x2 = x;
      update_detail::RowJob job{&update_detail::update_kernels(level), block.data(), m, k, c0, 16, nvec,
                                c.data(), s.data(), x.data(), m};
      const int64_t before = team.helper_row_runs();
      team.run(job, [](int32_t) {});
      if (RowTeam::worth_sharing(m, k, c0)) {
        EXPECT_GT(team.helper_row_runs(), before) << m << " " << k;
      }
      job.block = block2.data();
      job.x = x2.data();
      for (int32_t r = 0; r < update_detail::run_count(job); ++r) {
        update_detail::apply_run(job, r, update_detail::run_below(job, r), m);
      }
      ASSERT_EQ(block, block2) << simd_level_name(level) << " trial " << trial;
      ASSERT_EQ(x, x2) << simd_level_name(level) << " trial " << trial;
    }
  }
}

TEST(UpdateTeamTest, StartsAndStopsCleanly) {
  { RowTeam idle; }  // destroyed while spinning
  RowTeam team;
  std::this_thread::sleep_for(std::chrono::milliseconds(5));  // asleep by now
}

}  // namespace
}  // namespace gab
