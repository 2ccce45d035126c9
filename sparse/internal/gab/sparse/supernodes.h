// Supernode partitions of a postordered elimination tree (Liu, Ng & Peyton,
// "On finding supernodes for sparse matrix computations", SIMAX 1993;
// relaxed amalgamation as in Ashcraft & Grimes 1989 and CHOLMOD).
#pragma once

#include <cstdint>
#include <vector>

#include "gab/sparse/etree.h"

namespace gab {

// Fundamental supernodes: column j+1 joins j's supernode when parent(j) =
// j+1, j+1 has no other child, and count(j) = count(j+1) + 1. The tree must
// be postordered (parent[j] > j). Returns the first column of each supernode
// plus n at the end. O(n).
std::vector<int32_t> fundamental_supernodes(const std::vector<int32_t>& parent,
                                            const std::vector<int32_t>& counts);

struct RelaxOptions {
  int32_t cols[3] = {4, 16, 48};
  double zeros[3] = {0.8, 0.1, 0.05};
};

// Relaxed amalgamation: merges a supernode into its parent when they are
// contiguous (the child is the parent's last child) and the merged block is
// small or adds few explicit zeros (see RelaxOptions). The merged row
// structure is the parent's plus the child's columns. Returns the new
// partition (first columns plus n). O(number of supernodes * alpha).
std::vector<int32_t> relax_supernodes(const std::vector<int32_t>& first_col,
                                      const std::vector<int32_t>& parent,
                                      const std::vector<int32_t>& counts,
                                      const RelaxOptions& options);

}  // namespace gab
