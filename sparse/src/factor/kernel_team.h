// Fork-join helpers for the dense kernels: the threads that finished their
// subtrees of the factorization help the thread running the top of the tree
// (whose few fronts are the largest) inside its GEMM/SYRK calls.
//
// A kernel asks current_team(); when the calling thread leads a team and the
// call is large, it hands the team independent register-tile work (row
// blocks of C over a shared packed B^T, or column tiles) — exactly the tile
// calls, packings and inner-dimension slices it would have made alone, so
// the result is bit-identical to the single-threaded kernel.
//
// Helpers spin (then yield) while they wait: the team exists only for the
// top part of one factorization, on cores that would otherwise be idle.
#pragma once

#include <atomic>
#include <cstdint>

namespace gab {
namespace dense_detail {

class KernelTeam {
 public:
  // A team of `size` members: the leader (member 0, the thread that calls
  // run) and size - 1 helpers, each of which must call serve().
  explicit KernelTeam(int32_t size) : size_(size) {}
  KernelTeam(const KernelTeam&) = delete;
  KernelTeam& operator=(const KernelTeam&) = delete;

  int32_t size() const { return size_; }

  // Leader: runs fn(ctx, m) for every member m (0 on this thread) and
  // returns when all are done.
  void run(void (*fn)(void*, int32_t), void* ctx);
  // Helper `member` (1..size-1): runs every job of the leader's, including
  // those published before it got here, until stop(). Call once per team.
  void serve(int32_t member);
  // Leader: releases the helpers from serve().
  void stop();

 private:
  const int32_t size_;
  void (*fn_)(void*, int32_t) = nullptr;
  void* ctx_ = nullptr;
  std::atomic<uint64_t> generation_{0};  // bumped per job
  std::atomic<int32_t> pending_{0};      // helpers still on the current job
  std::atomic<bool> stopping_{false};
};

// The team the calling thread leads, or nullptr.
KernelTeam* current_team();

// Makes the calling thread lead `team` in its kernels until destroyed.
class LeadTeam {
 public:
  explicit LeadTeam(KernelTeam* team);
  ~LeadTeam();
  LeadTeam(const LeadTeam&) = delete;
  LeadTeam& operator=(const LeadTeam&) = delete;

 private:
  KernelTeam* previous_;
};

// Splits `count` independent work items among the team (item i to member
// i % size): fn(ctx, item) for each, returning when all are done. Without a
// team, or with fewer than two items, runs them here in order.
template <class F>
void for_each_item(KernelTeam* team, int32_t count, F&& f) {
  if (team == nullptr || team->size() < 2 || count < 2) {
    for (int32_t i = 0; i < count; ++i) f(i);
    return;
  }
  struct Job {
    F* f;
    int32_t count, size;
  } job{&f, count, team->size()};
  team->run(
      [](void* ctx, int32_t member) {
        const Job& j = *static_cast<const Job*>(ctx);
        for (int32_t i = member; i < j.count; i += j.size) (*j.f)(i);
      },
      &job);
}

}  // namespace dense_detail
}  // namespace gab
