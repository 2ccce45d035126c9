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
  constexpr int kTrimThreshold = 256 << 20;
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  const auto user_set = [tunables](const char* name) {
    return tunables != nullptr && std::strstr(tunables, name) != nullptr;
  };
  // Advisory: a refusal leaves glibc's defaults, which work too.
  if (!user_set("glibc.malloc.mmap_threshold")) (void)mallopt(M_MMAP_THRESHOLD, kMmapThreshold);
  if (!user_set("glibc.malloc.trim_threshold")) (void)mallopt(M_TRIM_THRESHOLD, kTrimThreshold);
#endif
  set_heap_release_after_ordering(true);
}

}  // namespace cli
}  // namespace gab
