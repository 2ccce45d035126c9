// A second thread for the anchor updates (internal). An update is a run of
// Givens rotations along the elimination-tree path, bound by memory
// bandwidth on one core (igea: ~70 MB of factor read and written per
// update), and a second core nearly doubles the bandwidth here. In a large
// supernode of the path the calling thread (the leader) computes each run
// of rotations on the run's small triangle and publishes it; both threads
// then rotate their own rows of the block below. Rows are independent and
// every row gets the same rotations in the same order as on one thread, so
// the factor is bit-identical.
//
// Rows split at `split` (leader: [below, split), helper: [split, m)); the
// split only moves down, and only when the runs' triangles reach it
// (split_rows), so a row changes hands only from the helper to the leader,
// a few times per supernode, and the leader waits for the helper's
// previous run before it takes such rows.
//
// The helper spins for a while after each job (updates come in streams),
// then sleeps on a condition variable: a Cholesky that stops updating does
// not keep a core busy.
#pragma once

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>

#include "update_kernels.h"

namespace gab {
namespace update_detail {

// One supernode's shared rotation pass: runs of `run` columns from c0 to
// k over the m x k block (column-major, ld = m). Rotations by column:
// run r's are at c[(cb - c0) * nvec ...] with cb = c0 + r * run, nvec
// per column (single update: nvec = 1 and the single kernel).
struct RowJob {
  const UpdateKernels* kern = nullptr;
  double* block = nullptr;
  int32_t m = 0, k = 0, c0 = 0, run = 0;
  int32_t nvec = 0;     // 0: single update (rotate_rows), else the batch kernel
  const double* c = nullptr;
  const double* s = nullptr;
  double* x = nullptr;  // x gathered on the block's rows (nvec vectors ldx apart)
  int32_t ldx = 0;
};

// Runs in the job, and the first row below run r's triangle.
inline int32_t run_count(const RowJob& job) { return (job.k - job.c0 + job.run - 1) / job.run; }
inline int32_t run_below(const RowJob& job, int32_t r) {
  const int32_t end = job.c0 + (r + 1) * job.run;
  return end < job.k ? end : job.k;
}

// First helper row for the run whose rows below its triangle start at
// `below`, with runs_left runs to go (this one included), given the
// previous run's split (0 before the first): unchanged while the leader
// still holds the next run's triangle, else moved down so both threads do
// the same work until it must move again; all rows to the leader when few
// are left. Never moves up.
int32_t split_rows(int32_t m, int32_t below, int32_t run, int32_t runs_left, int32_t previous);

// Rotates rows [begin, end) of the block by run r of the job.
void apply_run(const RowJob& job, int32_t r, int32_t begin, int32_t end);

class RowTeam {
 public:
  RowTeam();
  ~RowTeam();
  RowTeam(const RowTeam&) = delete;
  RowTeam& operator=(const RowTeam&) = delete;

  // Whether a supernode pass is worth sharing (measured: below about 32K
  // entries the hand-offs cost more than the second core brings).
  static bool worth_sharing(int32_t m, int32_t k, int32_t c0);

  // Rows times runs the helper has rotated so far (read by the leader
  // between passes).
  int64_t helper_row_runs() const { return helper_row_runs_.load(std::memory_order_relaxed); }

  // Leader, before each pass: false while the leader works alone after the
  // helper kept it waiting long (its core busy with something else: on an
  // oversubscribed machine each wait could cost a time slice).
  bool available() {
    if (solo_passes_ == 0) return true;
    --solo_passes_;
    return false;
  }

  // Leader: runs the whole pass of `job`, computing run r's rotations with
  // compute(r) (which must write them where the job says) and rotating the
  // leader's rows, while the helper rotates the others. Returns when both
  // are done.
  template <class Compute>
  void run(const RowJob& job, Compute&& compute);

 private:
  void post(const RowJob& job);
  void publish(int32_t runs) { published_.store(base_ + runs, std::memory_order_release); }
  void wait_helper(int32_t runs);
  void serve();

  // Each counter on its own cache line: the side that spins on one must
  // not be slowed by the other side writing its neighbour.
  alignas(64) RowJob job_;
  uint64_t base_ = 0;                                // runs of the jobs before this one
  int32_t solo_passes_ = 0;                          // passes the leader still does alone
  alignas(64) std::atomic<uint64_t> jobs_{0};        // jobs posted
  alignas(64) std::atomic<uint64_t> published_{0};   // runs whose rotations are ready
  alignas(64) std::atomic<uint64_t> helper_done_{0}; // runs the helper has applied
  std::atomic<int64_t> helper_row_runs_{0};
  alignas(64) std::atomic<bool> sleeping_{false};
  std::atomic<bool> stopping_{false};
  std::mutex mutex_;
  std::condition_variable wake_;
  std::thread thread_;
};

template <class Compute>
void RowTeam::run(const RowJob& job, Compute&& compute) {
  post(job);
  const int32_t runs = run_count(job);
  compute(0);
  publish(1);
  int32_t split = 0;
  for (int32_t r = 0; r < runs; ++r) {
    const int32_t below = run_below(job, r);
    const int32_t previous = split;
    split = split_rows(job.m, below, job.run, runs - r, previous);
    // Rows the leader already held (all of them in the first run); the
    // others were the helper's, whose previous run must be done first.
    const int32_t held = r == 0 ? split : previous;
    bool waited = false;
    auto take = [&](int32_t end) {
      if (end > held && !waited) {
        wait_helper(r);
        waited = true;
      }
    };
    // Run r on the next run's triangle first, so the next run's rotations
    // reach the helper while the leader rotates the rest of its rows.
    const int32_t next_end = r + 1 < runs ? std::min(run_below(job, r + 1), split) : below;
    take(next_end);
    apply_run(job, r, below, next_end);
    if (r + 1 < runs) {
      compute(r + 1);
      publish(r + 2);
    }
    take(split);
    apply_run(job, r, next_end, split);
  }
  wait_helper(runs);
}

}  // namespace update_detail
}  // namespace gab
