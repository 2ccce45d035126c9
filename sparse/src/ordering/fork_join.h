// A small fork-join pool for the nested-dissection recursion: a piece's two
// sides are independent, and their sizes are not (a separator may split
// 60/40, and the split below it again): a thread that forks one side and
// works on the other, then joins, runs queued tasks while it waits, and
// idle helpers take the oldest (largest) queued task. Which thread runs a
// task never changes what it computes. An exception a task raises (an
// allocation failing) reaches the thread that joins it, and no task body
// runs after it (the failed task's worker may hold a half-grown workspace);
// a helper the system will not start leaves fewer threads to do the work.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace gab {
namespace nd {

class ForkJoinPool {
 public:
  // A task runs fn(worker), worker being the index (0 .. size - 1) of the
  // thread that runs it.
  struct Task {
    std::function<void(int32_t)> fn;
    bool done = false;         // guarded by the pool's mutex
    std::exception_ptr error;  // what fn raised, rethrown by join
  };

  // `size` workers: the calling thread (worker 0) and size - 1 helpers.
  explicit ForkJoinPool(int32_t size);
  ~ForkJoinPool();
  ForkJoinPool(const ForkJoinPool&) = delete;
  ForkJoinPool& operator=(const ForkJoinPool&) = delete;

  int32_t size() const { return size_; }
  // Queues *task, runs here() on this thread (as `worker`), then joins
  // *task: returns once it has run, running queued tasks meanwhile (the
  // newest first, most often task itself). Rethrows what here() raised,
  // else what the task raised, but only after the join: a task never
  // outlives the frame that made it.
  void fork_run_join(Task* task, const std::function<void()>& here, int32_t worker);

 private:
  // Records the first failure; from then on run() skips task bodies.
  void fail(std::exception_ptr error);
  void fork(Task* task);
  void join(Task* task, int32_t worker);
  void run(Task* task, int32_t worker);
  void serve(int32_t worker);

  const int32_t size_;
  std::mutex mutex_;
  std::condition_variable changed_;  // a task queued or finished, or stopping
  std::deque<Task*> queue_;
  bool stopping_ = false;
  std::atomic<bool> failed_{false};
  std::exception_ptr first_error_;  // guarded by mutex_
  std::vector<std::thread> helpers_;
};

}  // namespace nd
}  // namespace gab
