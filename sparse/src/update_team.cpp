// The updater's helper thread: jobs and runs are published through
// monotone counters (release) that the other side reads (acquire), so each
// thread sees the rows, rotations and x the other wrote before.
#include "update_team.h"

#include <chrono>

namespace gab {
namespace update_detail {

namespace {

// Rows each thread must at least get for sharing a run to pay.
constexpr int32_t kMinRows = 64;
// The leader's work computing a run's rotations, in rows rotated.
constexpr int64_t kTriangleRows = 48;
// Entries of a supernode's pass below which one thread does it alone.
constexpr int64_t kMinSharedEntries = 32 * 1024;
// How long the helper spins for the next job before it sleeps: long enough
// for the gaps between the supernodes of one update and between updates
// that come in a stream, short against anything else the caller does.
constexpr std::chrono::microseconds kSpinBeforeSleep(100);

// A helper that keeps the leader waiting longer than this (it was not
// running) sends the leader alone through the next kSoloPasses passes.
constexpr std::chrono::microseconds kSlowHelper(100);
constexpr int32_t kSoloPasses = 256;
constexpr int32_t kSpinsBeforeYield = 4096;

// Busy-wait step: a pause, and after a while a yield, so an oversubscribed
// machine still makes progress.
inline void relax(int32_t* spins) {
  if (++*spins < kSpinsBeforeYield) {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#endif
  } else {
    std::this_thread::yield();
  }
}

}  // namespace

int32_t split_rows(int32_t m, int32_t below, int32_t run, int32_t runs_left, int32_t previous) {
  // Keep the split while the leader still holds the next run's triangle:
  // each move hands rows over, and the leader must wait for the helper's
  // previous run first (a handful of waits per supernode, not one per run).
  if (previous == m || previous >= below + run) return previous;
  const int64_t left = m - below;
  if (left < 2 * kMinRows) return m;
  // Leader rows a = split - below, over the R runs until they run out or
  // the supernode ends: the leader's region shrinks by `run` rows a run,
  // the helper's does not, and the leader also computes each run's
  // rotations (about kTriangleRows rows' worth of work, measured).
  // Balanced: a R - run R^2 / 2 + T R = R (left - a).
  const int64_t r_end = runs_left, half_run = run / 2;
  int64_t a = (left - kTriangleRows + half_run * r_end) / 2;  // the supernode ends first
  if (a < run * r_end) a = 2 * (left - kTriangleRows) / 3;      // the leader's rows run out first
  if (a < run) a = run;
  return static_cast<int32_t>(below + a < m ? below + a : m);
}

void apply_run(const RowJob& job, int32_t r, int32_t begin, int32_t end) {
  if (end <= begin) return;
  const int32_t cb = job.c0 + r * job.run;
  const int32_t nb = run_below(job, r) - cb;
  const int64_t first = static_cast<int64_t>(cb - job.c0) * (job.nvec == 0 ? 1 : job.nvec);
  double* l = job.block + static_cast<int64_t>(cb) * job.m + begin;
  if (job.nvec == 0) {
    job.kern->rotate_rows(end - begin, nb, job.c + first, job.s + first, l, job.m, job.x + begin);
  } else {
    job.kern->rotate_rows_batch(end - begin, nb, job.nvec, job.c + first, job.s + first, l, job.m,
                                job.x + begin, job.ldx);
  }
}

bool RowTeam::worth_sharing(int32_t m, int32_t k, int32_t c0) {
  return m - c0 >= 2 * kMinRows &&
         static_cast<int64_t>(m - c0) * (k - c0) >= kMinSharedEntries;
}

RowTeam::RowTeam() { thread_ = std::thread([this] { serve(); }); }

RowTeam::~RowTeam() {
  stopping_.store(true, std::memory_order_seq_cst);
  { std::lock_guard<std::mutex> lock(mutex_); }
  wake_.notify_one();
  thread_.join();
}

void RowTeam::post(const RowJob& job) {
  job_ = job;
  base_ = published_.load(std::memory_order_relaxed);  // only this thread writes it
  jobs_.fetch_add(1, std::memory_order_seq_cst);
  // A helper that went to sleep set sleeping_ before it last looked at
  // jobs_ (both seq_cst): either it sees the new job or we see it asleep.
  if (sleeping_.load(std::memory_order_seq_cst)) {
    { std::lock_guard<std::mutex> lock(mutex_); }
    wake_.notify_one();
  }
}

void RowTeam::wait_helper(int32_t runs) {
  const uint64_t target = base_ + static_cast<uint64_t>(runs);
  int32_t spins = 0;
  std::chrono::steady_clock::time_point start;
  while (helper_done_.load(std::memory_order_acquire) < target) {
    relax(&spins);
    if (spins == kSpinsBeforeYield) start = std::chrono::steady_clock::now();
  }
  if (spins > kSpinsBeforeYield && std::chrono::steady_clock::now() - start > kSlowHelper) {
    solo_passes_ = kSoloPasses;
  }
}

void RowTeam::serve() {
  uint64_t seen = 0;
  for (;;) {
    // The next job: spin a while, then sleep.
    const auto spin_until = std::chrono::steady_clock::now() + kSpinBeforeSleep;
    int32_t spins = 0;
    while (jobs_.load(std::memory_order_acquire) == seen) {
      if (stopping_.load(std::memory_order_acquire)) return;
      if ((++spins & 255) == 0 && std::chrono::steady_clock::now() > spin_until) {
        std::unique_lock<std::mutex> lock(mutex_);
        sleeping_.store(true, std::memory_order_seq_cst);
        while (jobs_.load(std::memory_order_seq_cst) == seen &&
               !stopping_.load(std::memory_order_seq_cst)) {
          wake_.wait(lock);
        }
        sleeping_.store(false, std::memory_order_relaxed);
      }
#if defined(__x86_64__) || defined(__i386__)
      __builtin_ia32_pause();
#endif
    }
    ++seen;  // the leader posts one job at a time and waits for it
    const RowJob job = job_;
    const uint64_t base = base_;
    const int32_t runs = run_count(job);
    int32_t split = 0;
    for (int32_t r = 0; r < runs; ++r) {
      int32_t wait_spins = 0;
      while (published_.load(std::memory_order_acquire) < base + r + 1) relax(&wait_spins);
      split = split_rows(job.m, run_below(job, r), job.run, runs - r, split);
      apply_run(job, r, split, job.m);
      helper_row_runs_.fetch_add(job.m - split, std::memory_order_relaxed);
      helper_done_.store(base + r + 1, std::memory_order_release);
    }
  }
}

}  // namespace update_detail
}  // namespace gab
