#include "malloc_tuning.h"

#include <cstdlib>
#include <cstring>
#include <string>
#if defined(__GLIBC__)  // defined once <string> has included <features.h>
#include <malloc.h>
#endif

#include "gab/sparse/heap_release.h"

namespace gab {
namespace cli {

void tune_malloc() {
#if defined(__GLIBC__)
  constexpr int kMmapThreshold = 32 << 20;
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  if (tunables == nullptr || std::strstr(tunables, "glibc.malloc.mmap_threshold") == nullptr) {
    // Advisory: a refusal leaves glibc's defaults, which work too.
    (void)mallopt(M_MMAP_THRESHOLD, kMmapThreshold);
  }
#endif
  set_heap_release_after_ordering(true);
}

}  // namespace cli
}  // namespace gab
