// A hash map from non-negative 63-bit keys to int32 values: open addressing
// with linear probing in one flat array, deletion by backward shift (no
// tombstones), at most half full.
//
// Why not std::unordered_map: the connectivity coder's open-edge index does
// a few lookups, inserts and erases per triangle, and the node-based map's
// allocation and pointer chasing were 40% of decoding igea's triangles.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace gab {

class FlatIntMap {
 public:
  // The value of `key`, or nullptr. Valid until the next insert.
  int32_t* find(uint64_t key) {
    if (size_ == 0) return nullptr;
    for (size_t i = home(key); slots_[i].key != kEmpty; i = (i + 1) & mask_) {
      if (slots_[i].key == key) return &slots_[i].value;
    }
    return nullptr;
  }
  const int32_t* find(uint64_t key) const { return const_cast<FlatIntMap*>(this)->find(key); }

  // The value of `key`, inserted as `value` if absent (an existing value is
  // kept). Valid until the next insert. key < 2^63.
  int32_t& insert(uint64_t key, int32_t value) {
    if (2 * (size_ + 1) > slots_.size()) grow();
    size_t i = home(key);
    for (; slots_[i].key != kEmpty; i = (i + 1) & mask_) {
      if (slots_[i].key == key) return slots_[i].value;
    }
    slots_[i] = Slot{key, value};
    ++size_;
    return slots_[i].value;
  }

  // Removes `key` if present.
  void erase(uint64_t key) {
    if (size_ == 0) return;
    size_t i = home(key);
    for (; slots_[i].key != key; i = (i + 1) & mask_) {
      if (slots_[i].key == kEmpty) return;
    }
    // Backward shift: pull later entries of the probe run into the hole
    // unless their home lies cyclically in (hole, their slot].
    for (size_t j = (i + 1) & mask_; slots_[j].key != kEmpty; j = (j + 1) & mask_) {
      const size_t h = home(slots_[j].key);
      const bool stays = i <= j ? (i < h && h <= j) : (i < h || h <= j);
      if (!stays) {
        slots_[i] = slots_[j];
        i = j;
      }
    }
    slots_[i].key = kEmpty;
    --size_;
  }

  size_t size() const { return size_; }

 private:
  static constexpr uint64_t kEmpty = ~uint64_t{0};
  struct Slot {
    uint64_t key;
    int32_t value;
  };

  size_t home(uint64_t key) const { return static_cast<size_t>((key * 0x9E3779B97F4A7C15ull) >> shift_) & mask_; }

  void grow() {
    std::vector<Slot> old;
    old.swap(slots_);
    const size_t capacity = old.empty() ? 64 : 2 * old.size();
    slots_.assign(capacity, Slot{kEmpty, 0});
    mask_ = capacity - 1;
    shift_ = 64;
    for (size_t c = capacity; c > 1; c >>= 1) --shift_;
    size_ = 0;
    for (const Slot& s : old) {
      if (s.key != kEmpty) insert(s.key, s.value);
    }
  }

  std::vector<Slot> slots_;
  size_t mask_ = 0;
  int shift_ = 64;
  size_t size_ = 0;
};

}  // namespace gab
