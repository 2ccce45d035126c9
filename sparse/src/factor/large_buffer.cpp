#include "gab/sparse/large_buffer.h"

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <utility>

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

#include "factor/start_thread.h"

namespace gab {

namespace {
constexpr size_t kHugePage = kLargeAlignment;

// The whole `page`-byte pages inside [p, p + bytes): [first, last), empty
// when last <= first.
[[maybe_unused]] std::pair<uintptr_t, uintptr_t> whole_pages(const void* p, size_t bytes, uintptr_t page) {
  const uintptr_t begin = reinterpret_cast<uintptr_t>(p);
  return {(begin + page - 1) / page * page, (begin + bytes) / page * page};
}
}  // namespace

void* allocate_large(size_t bytes) {
  if (bytes == 0) bytes = 64;
  const size_t align = bytes >= kHugePage ? kHugePage : 64;
  const size_t rounded = (bytes + align - 1) / align * align;  // aligned_alloc's rule
  void* p = std::aligned_alloc(align, rounded);
  if (p != nullptr && align == kHugePage) advise_huge_pages(p, rounded);
  return p;
}

void advise_huge_pages(void* p, size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  const auto pages = whole_pages(p, bytes, kHugePage);
  if (p != nullptr && pages.second > pages.first) {
    madvise(reinterpret_cast<void*>(pages.first), pages.second - pages.first, MADV_HUGEPAGE);
  }
#else
  (void)p;
  (void)bytes;
#endif
}

void free_large(void* p) { std::free(p); }

void release_pages(void* p, size_t bytes) {
#if defined(__linux__)
  const auto pages = whole_pages(p, bytes, static_cast<uintptr_t>(sysconf(_SC_PAGESIZE)));
  if (p != nullptr && pages.second > pages.first) {
    madvise(reinterpret_cast<void*>(pages.first), pages.second - pages.first, MADV_DONTNEED);
  }
#else
  (void)p;
  (void)bytes;
#endif
}

// The ranges cut into pieces that both threads take in turn.
struct PagePopulator::Work {
  std::vector<std::pair<char*, size_t>> pieces;
  std::atomic<size_t> next{0};

  void run() {
    for (size_t i = next.fetch_add(1); i < pieces.size(); i = next.fetch_add(1)) {
#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
      // Fails on kernels before 5.14 (EINVAL): the pages then fault on use.
      if (madvise(pieces[i].first, pieces[i].second, MADV_POPULATE_WRITE) != 0) next = pieces.size();
#endif
    }
  }
};

PagePopulator::PagePopulator() = default;

PagePopulator::~PagePopulator() { finish(); }

void PagePopulator::start(const std::vector<std::pair<void*, size_t>>& ranges) {
  finish();
#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
  constexpr size_t kPage = 4096, kPiece = size_t{4} << 20, kWorthAThread = size_t{16} << 20;
  auto work = std::make_unique<Work>();
  size_t total = 0;
  for (const auto& range : ranges) {
    const auto pages = whole_pages(range.first, range.second, kPage);
    const uintptr_t last = pages.second;
    for (uintptr_t p = pages.first; p < last; p += kPiece) {
      const size_t size = static_cast<size_t>(std::min<uintptr_t>(kPiece, last - p));
      work->pieces.emplace_back(reinterpret_cast<char*>(p), size);
      total += size;
    }
  }
  if (total < kWorthAThread) return;
  work_ = std::move(work);
  // A helper the system refuses (start_thread.h) leaves finish() the work.
  try_start_thread(&helper_, [w = work_.get()] { w->run(); });
#else
  (void)ranges;
#endif
}

void PagePopulator::finish() {
  if (!work_) return;
  work_->run();
  if (helper_.joinable()) helper_.join();
  work_.reset();
}

}  // namespace gab
