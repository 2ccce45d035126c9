// The host's opt-in to heap trimming (heap_release.h), and the trim itself.
#include "gab/sparse/heap_release.h"

#include <atomic>
#include <cstdint>
#include <string>
#if defined(__GLIBC__)  // defined once <string> has included <features.h>
#include <malloc.h>
#endif

#include "analysis/heap_release_internal.h"

namespace gab {
namespace {

std::atomic<bool> g_release_after_ordering{false};

}  // namespace

void set_heap_release_after_ordering(bool enabled) { g_release_after_ordering.store(enabled); }

bool heap_release_after_ordering() { return g_release_after_ordering.load(); }

// Measured with the trim inside every analysis: a 2.4M-vertex decode's peak
// 5.56 -> 5.31 GB; below the threshold the analysis re-faults what was
// returned (igea: 0.1 s of a 1.2 s decode), hence the size floor.
void release_heap_after_ordering(int64_t matrix_entries) {
  constexpr int64_t kTrimFromEntries = int64_t{1} << 23;
#if defined(__GLIBC__)
  if (matrix_entries >= kTrimFromEntries && heap_release_after_ordering()) malloc_trim(0);
#else
  (void)matrix_entries;
  (void)kTrimFromEntries;
#endif
}

}  // namespace gab
