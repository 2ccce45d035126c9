// The kernels' fork-join team: one job at a time, published through an
// atomic generation counter (release) and completed through a countdown
// (acquire), so the helpers see the leader's data and the leader theirs.
#include "factor/kernel_team.h"

#include <thread>

namespace gab {
namespace dense_detail {
namespace {

thread_local KernelTeam* tls_team = nullptr;

// Busy-wait step: a pause, and after a while a yield, so an oversubscribed
// machine still makes progress.
inline void relax(int32_t* spins) {
  if (++*spins < 4096) {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#endif
  } else {
    std::this_thread::yield();
  }
}

}  // namespace

void KernelTeam::run(void (*fn)(void*, int32_t), void* ctx) {
  fn_ = fn;
  ctx_ = ctx;
  pending_.store(size_ - 1, std::memory_order_relaxed);
  generation_.fetch_add(1, std::memory_order_release);
  fn(ctx, 0);
  int32_t spins = 0;
  while (pending_.load(std::memory_order_acquire) != 0) relax(&spins);
}

void KernelTeam::serve(int32_t member) {
  // From generation 0, not the current one: the leader may have published
  // jobs before this helper got here, and every job needs every member.
  uint64_t seen = 0;
  for (;;) {
    int32_t spins = 0;
    uint64_t now;
    while ((now = generation_.load(std::memory_order_acquire)) == seen) {
      if (stopping_.load(std::memory_order_acquire)) return;
      relax(&spins);
    }
    seen = now;
    fn_(ctx_, member);
    pending_.fetch_sub(1, std::memory_order_release);
  }
}

void KernelTeam::stop() { stopping_.store(true, std::memory_order_release); }

KernelTeam* current_team() { return tls_team; }

LeadTeam::LeadTeam(KernelTeam* team) : previous_(tls_team) { tls_team = team; }

LeadTeam::~LeadTeam() { tls_team = previous_; }

}  // namespace dense_detail
}  // namespace gab
