// The nested dissection's fork-join pool: every task runs exactly once, on a
// worker index in range, joins return only after their task ran, and
// nested forks (tasks forking tasks, joins running other queued tasks)
// neither deadlock nor lose work; an exception raised on either side reaches
// the joining thread after the join, and no task body runs after it.
#include "ordering/fork_join.h"

#include <gtest/gtest.h>

#include <atomic>
#include <new>
#include <cstdint>
#include <vector>

namespace gab {
namespace {

// Sums 1..n by splitting the range in halves, forking the left half: the
// recursion the dissection makes, with a result per task to check.
int64_t range_sum(nd::ForkJoinPool* pool, int64_t lo, int64_t hi, int32_t worker, std::atomic<int32_t>* bad_worker,
                  std::vector<std::atomic<int32_t>>* runs) {
  if (worker < 0 || worker >= pool->size()) bad_worker->fetch_add(1);
  if (hi - lo <= 64) {
    int64_t s = 0;
    for (int64_t v = lo; v < hi; ++v) {
      s += v;
      (*runs)[static_cast<size_t>(v)].fetch_add(1);
    }
    return s;
  }
  const int64_t mid = lo + (hi - lo) / 3;  // uneven, as separators split
  int64_t left = -1;
  nd::ForkJoinPool::Task task;
  task.fn = [&](int32_t w) { left = range_sum(pool, lo, mid, w, bad_worker, runs); };
  int64_t right = -1;
  pool->fork_run_join(&task, [&] { right = range_sum(pool, mid, hi, worker, bad_worker, runs); }, worker);
  EXPECT_GE(left, 0);  // the task ran before join returned
  return left + right;
}

TEST(ForkJoinPool, NestedForksRunEveryTaskOnceAndJoinAfterIt) {
  for (int32_t size : {1, 2, 4}) {
    nd::ForkJoinPool pool(size);
    const int64_t n = 20000;
    std::vector<std::atomic<int32_t>> runs(static_cast<size_t>(n));
    for (auto& r : runs) r = 0;
    std::atomic<int32_t> bad_worker{0};
    EXPECT_EQ(range_sum(&pool, 0, n, 0, &bad_worker, &runs), n * (n - 1) / 2) << size << " workers";
    EXPECT_EQ(bad_worker.load(), 0);
    int32_t wrong = 0;
    for (auto& r : runs) wrong += r.load() != 1;
    EXPECT_EQ(wrong, 0) << size << " workers";
  }
}

TEST(ForkJoinPool, ExceptionsReachTheJoinerAfterTheJoinAndStopThePool) {
  for (int32_t size : {1, 2}) {
    for (bool in_task : {true, false}) {
      nd::ForkJoinPool pool(size);
      nd::ForkJoinPool::Task task;
      task.fn = [&](int32_t) {
        if (in_task) throw std::bad_alloc();
      };
      bool caught = false;
      try {
        pool.fork_run_join(&task, [&] {
          if (!in_task) throw std::bad_alloc();
        }, 0);
      } catch (const std::bad_alloc&) {
        caught = true;
      }
      EXPECT_TRUE(caught) << size << (in_task ? " in the task" : " here");
      EXPECT_TRUE(task.done) << size;  // joined (run or skipped) before the rethrow
      // After a failure no task body runs; its joiner gets the failure.
      bool ran = false;
      nd::ForkJoinPool::Task later;
      later.fn = [&](int32_t) { ran = true; };
      caught = false;
      try {
        pool.fork_run_join(&later, [] {}, 0);
      } catch (const std::bad_alloc&) {
        caught = true;
      }
      EXPECT_TRUE(caught) << size;
      EXPECT_FALSE(ran) << size;
    }
  }
}

}  // namespace
}  // namespace gab
