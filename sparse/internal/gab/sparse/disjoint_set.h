// Disjoint-set forests (internal): parent links where a root points at
// itself. Used by the column counts (the etree's "ancestor" forest) and by
// relaxed amalgamation (groups of merged supernodes).
#pragma once

#include <cstdint>
#include <vector>

namespace gab {

// Root of j's set, pointing every node on the way straight at it (path
// compression). Amortized near O(1).
inline int32_t find_set_root(std::vector<int32_t>* link, int32_t j) {
  int32_t root = j;
  while ((*link)[root] != root) root = (*link)[root];
  while ((*link)[j] != root) {
    const int32_t next = (*link)[j];
    (*link)[j] = root;
    j = next;
  }
  return root;
}

}  // namespace gab
