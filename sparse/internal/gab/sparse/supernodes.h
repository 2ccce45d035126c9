// Supernode partitions of a postordered elimination tree (Liu, Ng & Peyton,
// "On finding supernodes for sparse matrix computations", SIMAX 1993;
// relaxed amalgamation as in Ashcraft & Grimes 1989 and CHOLMOD).
#pragma once

#include <cstdint>
#include <vector>

#include "gab/sparse/symbolic.h"  // RelaxOptions

namespace gab {

// Fundamental supernodes: column j+1 joins j's supernode when parent(j) =
// j+1, j+1 has no other child, and count(j) = count(j+1) + 1. The tree must
// be postordered (parent[j] > j). Returns the first column of each supernode
// plus n at the end. O(n).
std::vector<int32_t> fundamental_supernodes(const std::vector<int32_t>& parent,
                                            const std::vector<int32_t>& counts);

// Relaxed amalgamation of a partition (first columns plus n) of a
// postordered tree. Supernodes are visited from the last down; a child s
// merges into the group holding its parent column only when that group
// begins with supernode s + 1 (the columns stay contiguous), and then when the merged
// block of k columns and m rows (the child's columns plus the group's rows)
// meets options (RelaxOptions, symbolic.h) with z / (k m - k (k - 1) / 2)
// as its fraction of explicit zeros, z counting the zeros of both parts plus
// the child's columns lengthened to m rows. Top-down, a group that absorbed
// its last child can go on absorbing that child's last child. counts are
// read at each supernode's first column only. options.enabled is not read.
// Returns the new partition. O(number of supernodes * alpha).
std::vector<int32_t> relax_supernodes(const std::vector<int32_t>& first_col,
                                      const std::vector<int32_t>& parent,
                                      const std::vector<int32_t>& counts,
                                      const RelaxOptions& options);

// Cuts every supernode of a partition (first columns plus n) wider than
// panel_cols into ceil(k / panel_cols) panels, at most max_panels, of
// near-equal widths (the wider first). Returns the new partition; when
// `continued` is given, (*continued)[s] = 1 for each panel s but the last of
// its supernode. panel_cols <= 0 cuts nothing. O(number of supernodes).
std::vector<int32_t> split_wide_supernodes(const std::vector<int32_t>& first_col, int32_t panel_cols,
                                           int32_t max_panels, std::vector<uint8_t>* continued);

}  // namespace gab
