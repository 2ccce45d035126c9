// Storage for the factor and its workspaces: large, uninitialized,
// grow-only, and backed by transparent huge pages where the OS offers them.
//
// Why: the first factorization touches hundreds of MB; with 4 KiB pages that
// is ~10^5 page faults, which on virtual machines cost as much as the
// factorization itself. 2 MiB-aligned blocks advised MADV_HUGEPAGE fault
// 512x less often. Nothing is zero-filled: every user writes before reading.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <thread>
#include <vector>

namespace gab {

// Returns `bytes` of 64-byte-aligned storage (2 MiB-aligned and advised for
// huge pages when large), or nullptr when it cannot be had. O(1).
void* allocate_large(size_t bytes);
// Releases storage from allocate_large (nullptr is fine).
void free_large(void* p);
// The alignment of large blocks, the huge-page size.
constexpr size_t kLargeAlignment = size_t{2} << 20;
// Advises the whole huge pages inside [p, p + bytes) for transparent huge
// pages where the system offers them (advisory; nothing happens elsewhere).
void advise_huge_pages(void* p, size_t bytes);
// Gives the whole pages inside [p, p + bytes) back to the OS but keeps them
// allocated: on Linux they read as zeros and fault in again when touched;
// elsewhere nothing happens.
void release_pages(void* p, size_t bytes);

// A typed grow-only array on top of allocate_large. Not copyable.
template <typename T>
class LargeBuffer {
 public:
  LargeBuffer() = default;
  LargeBuffer(const LargeBuffer&) = delete;
  LargeBuffer& operator=(const LargeBuffer&) = delete;
  LargeBuffer(LargeBuffer&& other) noexcept : data_(other.data_), capacity_(other.capacity_) {
    other.data_ = nullptr;
    other.capacity_ = 0;
  }
  LargeBuffer& operator=(LargeBuffer&& other) noexcept {
    if (this != &other) {
      free_large(data_);
      data_ = other.data_;
      capacity_ = other.capacity_;
      other.data_ = nullptr;
      other.capacity_ = 0;
    }
    return *this;
  }
  ~LargeBuffer() { free_large(data_); }

  // Ensures room for n elements (contents are lost when it grows). False
  // when the memory cannot be had; the buffer is then empty.
  bool reserve(int64_t n) {
    if (n <= capacity_) return true;
    free_large(data_);
    data_ = static_cast<T*>(allocate_large(static_cast<size_t>(n) * sizeof(T)));
    capacity_ = data_ != nullptr ? n : 0;
    return data_ != nullptr;
  }
  T* data() const { return data_; }
  int64_t capacity() const { return capacity_; }
  // release_pages() over the whole buffer: its contents are lost, its
  // capacity stays.
  void release_pages() { gab::release_pages(data_, static_cast<size_t>(capacity_) * sizeof(T)); }

 private:
  T* data_ = nullptr;
  int64_t capacity_ = 0;
};

// Faults in fresh storage before its first use, on a helper thread while
// the caller does other work; finish() lends the calling thread to what is
// left and joins. The contents are left as they are (MADV_POPULATE_WRITE,
// Linux 5.14+; elsewhere nothing is done and pages fault on first use).
//
// Why: on a virtual machine the first touch of memory the host has taken
// back costs ~2 ms per MiB (the host provisions and zeroes it), so igea's
// first factorization spent 0.3-0.5 s on 345 MiB of factor and stacks, most
// of it on one thread while the other core sat idle in the serial analysis.
// Population runs ~1.7x faster on two threads than on one here.
class PagePopulator {
 public:
  PagePopulator();
  ~PagePopulator();
  PagePopulator(const PagePopulator&) = delete;
  PagePopulator& operator=(const PagePopulator&) = delete;

  // Finishes any earlier run, then starts populating the whole pages
  // inside [begin, begin + bytes) of each range on a helper thread (not
  // when they add up to less than a few MiB). No one may read or write the
  // ranges until finish() returns.
  void start(const std::vector<std::pair<void*, size_t>>& ranges);
  // Populates what the helper has not reached, on this thread as well,
  // and waits for the helper. Cheap when nothing is running.
  void finish();

 private:
  struct Work;
  std::unique_ptr<Work> work_;
  std::thread helper_;
};

}  // namespace gab
