#include "malloc_tuning.h"

#include <cstdlib>
#include <cstring>
#include <string>
#if defined(__GLIBC__)  // defined once <string> has included <features.h>
#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>
#endif

#include "gab/sparse/heap_release.h"

namespace gab {
namespace cli {

#if defined(__GLIBC__) && defined(MADV_HUGEPAGE)
namespace {

// The heap's next kHugeHeap bytes, reserved now (address space only) and
// advised as transparent huge pages; later growth past them is as usual.
void advise_huge_heap() {
  constexpr size_t kHugeHeap = size_t{64} << 20;
  constexpr uintptr_t kHugePage = uintptr_t{2} << 20;
  // One extension of the heap by the block and the top pad: a single region
  // to advise (growth after it makes regions of its own, not advised).
  (void)mallopt(M_TOP_PAD, static_cast<int>(kHugeHeap));
  void* block = std::malloc(size_t{1} << 20);
  const uintptr_t end = reinterpret_cast<uintptr_t>(sbrk(0));
  const uintptr_t begin = (reinterpret_cast<uintptr_t>(block) + kHugePage - 1) & ~(kHugePage - 1);
  // Advisory: where the system has no transparent huge pages (or the
  // block came from elsewhere than the heap), pages stay small.
  if (block != nullptr && end > begin) (void)madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
  std::free(block);  // kept by the heap (the trim threshold is above it)
  (void)mallopt(M_TOP_PAD, 128 << 10);  // glibc's default
}

}  // namespace
#endif

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
#if defined(MADV_HUGEPAGE)
  if (!user_set("glibc.malloc.hugetlb") && !user_set("glibc.malloc.top_pad")) advise_huge_heap();
#endif
#endif
  set_heap_release_after_ordering(true);
}

}  // namespace cli
}  // namespace gab
