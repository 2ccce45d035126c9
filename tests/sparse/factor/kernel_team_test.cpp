// The dense kernels led by a thread with a team (kernel_team.h) give the
// same bits as alone, on the packed and the unpacked paths of every SIMD
// level: the tree-parallel factorization relies on it.
#include "factor/kernel_team.h"

#include <gtest/gtest.h>

#include <random>
#include <thread>
#include <vector>

#include "gab/sparse/dense_kernels.h"
#include "sparse/test_matrices.h"

namespace gab {
namespace {

using dense_detail::KernelTeam;
using dense_detail::LeadTeam;
using testing_util::supported_levels;

std::vector<double> random_matrix(int32_t rows, int32_t cols, uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> val(-1.0, 1.0);
  std::vector<double> m(static_cast<size_t>(rows) * cols);
  for (double& x : m) x = val(rng);
  return m;
}

// Runs `call` led by this thread with a team of `size` (1: no team).
template <class F>
void with_team(int32_t size, F&& call) {
  if (size == 1) {
    call();
    return;
  }
  KernelTeam team(size);
  std::vector<std::thread> helpers;
  for (int32_t m = 1; m < size; ++m) helpers.emplace_back([&team, m] { team.serve(m); });
  {
    LeadTeam lead(&team);
    EXPECT_EQ(dense_detail::current_team(), &team);
    call();
  }
  EXPECT_EQ(dense_detail::current_team(), nullptr);
  team.stop();
  for (std::thread& t : helpers) t.join();
}

// Every kernel on shapes that take the packed path (large operands) and the
// unpacked one (a short A), each large enough to be shared with a team.
std::vector<std::vector<double>> run_all(const DenseKernels& k, int32_t team) {
  std::vector<std::vector<double>> out;
  {
    const int32_t n = 650;
    std::vector<double> a = random_matrix(n, n, 1);
    std::vector<double> spd(static_cast<size_t>(n) * n, 0.0);
    // spd = a a^T + n I, lower triangle
    k.syrk_lower_sub(n, n, a.data(), n, spd.data(), n);
    for (int32_t j = 0; j < n; ++j) {
      for (int32_t i = j; i < n; ++i) spd[i + static_cast<size_t>(j) * n] *= -1.0;
      spd[j + static_cast<size_t>(j) * n] += n;
    }
    with_team(team, [&] { EXPECT_EQ(k.potrf(n, spd.data(), n), -1); });
    out.push_back(spd);
    std::vector<double> b = random_matrix(900, n, 2);
    with_team(team, [&] { k.trsm_right_lower_trans(900, n, spd.data(), n, b.data(), 900); });
    out.push_back(b);
  }
  for (const int32_t rows : {700, 90}) {  // 90 x 600 of A fits the unpacked rule
    std::vector<double> a = random_matrix(rows, 600, 3), b = random_matrix(1700, 600, 4);
    std::vector<double> c = random_matrix(rows, 1700, 5);
    with_team(team, [&] { k.gemm_nt_sub(rows, 1700, 600, a.data(), rows, b.data(), 1700, c.data(), rows); });
    out.push_back(c);
    std::vector<double> s = random_matrix(rows, rows, 6);
    with_team(team, [&] { k.syrk_lower_sub(rows, 600, a.data(), rows, s.data(), rows); });
    out.push_back(s);
    std::vector<double> packed = random_matrix(static_cast<int32_t>(packed_lower_size(rows)), 1, 7);
    with_team(team, [&] { k.syrk_lower_sub_packed(rows, 600, a.data(), rows, packed.data()); });
    out.push_back(packed);
  }
  return out;
}

TEST(KernelTeamTest, KernelsWithATeamGiveTheSameBitsAsAlone) {
  for (const SimdLevel level : supported_levels()) {
    const DenseKernels& k = dense_kernels(level);
    const std::vector<std::vector<double>> alone = run_all(k, 1);
    for (const int32_t team : {2, 3}) {
      const std::vector<std::vector<double>> shared = run_all(k, team);
      ASSERT_EQ(shared.size(), alone.size());
      for (size_t i = 0; i < alone.size(); ++i) {
        EXPECT_TRUE(shared[i] == alone[i]) << "kernel call " << i << ", team of " << team << ", "
                                           << simd_level_name(level);
      }
    }
  }
}

TEST(KernelTeamTest, EveryItemRunsOnceOnSomeMember) {
  KernelTeam team(3);
  std::vector<std::thread> helpers;
  for (int32_t m = 1; m < 3; ++m) helpers.emplace_back([&team, m] { team.serve(m); });
  std::vector<int> hits(1000, 0);
  for (int round = 0; round < 50; ++round) {
    dense_detail::for_each_item(&team, 1000, [&](int32_t i) { ++hits[i]; });
  }
  team.stop();
  for (std::thread& t : helpers) t.join();
  for (int h : hits) EXPECT_EQ(h, 50);
}

}  // namespace
}  // namespace gab
