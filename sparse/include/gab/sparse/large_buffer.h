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

namespace gab {

// Returns `bytes` of 64-byte-aligned storage (2 MiB-aligned and advised for
// huge pages when large), or nullptr when it cannot be had. O(1).
void* allocate_large(size_t bytes);
// Releases storage from allocate_large (nullptr is fine).
void free_large(void* p);

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

 private:
  T* data_ = nullptr;
  int64_t capacity_ = 0;
};

}  // namespace gab
