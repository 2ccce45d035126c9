#include "ordering/fork_join.h"

#include "factor/start_thread.h"

namespace gab {
namespace nd {

ForkJoinPool::ForkJoinPool(int32_t size) : size_(size < 1 ? 1 : size) {
  for (int32_t w = 1; w < size_; ++w) {
    std::thread helper;
    if (!try_start_thread(&helper, [this, w] { serve(w); })) break;  // fewer helpers: joins run the tasks
    helpers_.push_back(std::move(helper));
  }
}

ForkJoinPool::~ForkJoinPool() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  for (std::thread& t : helpers_) t.join();
}

void ForkJoinPool::fork(Task* task) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    queue_.push_back(task);
  }
  changed_.notify_one();
}

void ForkJoinPool::fail(std::exception_ptr error) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!first_error_) first_error_ = error;
  failed_ = true;
}

void ForkJoinPool::fork_run_join(Task* task, const std::function<void()>& here, int32_t worker) {
  fork(task);
  std::exception_ptr error;
#if defined(__cpp_exceptions)
  try {
    here();
  } catch (...) {
    error = std::current_exception();
    fail(error);
  }
#else
  here();
#endif
  join(task, worker);
  if (error) std::rethrow_exception(error);
  if (task->error) std::rethrow_exception(task->error);
}

void ForkJoinPool::run(Task* task, int32_t worker) {
  // After a failure no task body runs: the failed one may have left its
  // worker's workspace half grown, and the caller is unwinding anyway.
  // A skipped task carries the first failure to its joiner.
  if (failed_.load()) {
    std::lock_guard<std::mutex> lock(mutex_);
    task->error = first_error_;
  } else {
#if defined(__cpp_exceptions)
    try {
      task->fn(worker);
    } catch (...) {
      task->error = std::current_exception();
      fail(task->error);
    }
#else
    task->fn(worker);
#endif
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    task->done = true;
  }
  changed_.notify_all();
}

void ForkJoinPool::join(Task* task, int32_t worker) {
  for (;;) {
    Task* next = nullptr;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      changed_.wait(lock, [&] { return task->done || !queue_.empty(); });
      if (task->done) return;
      next = queue_.back();
      queue_.pop_back();
    }
    run(next, worker);
  }
}

void ForkJoinPool::serve(int32_t worker) {
  for (;;) {
    Task* next = nullptr;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      changed_.wait(lock, [&] { return stopping_ || !queue_.empty(); });
      if (queue_.empty()) return;  // stopping
      next = queue_.front();
      queue_.pop_front();
    }
    run(next, worker);
  }
}

}  // namespace nd
}  // namespace gab
