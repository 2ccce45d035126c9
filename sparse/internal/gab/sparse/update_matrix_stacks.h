// Where the multifrontal factorization keeps its update matrices (see
// supernodal_factor.cpp). Supernode s's update matrix, a packed lower
// triangle of order rows(s) - cols(s), lives from the moment s is factored
// until its parent assembles it. A group of supernodes, run in increasing
// (post)order, keeps them on two stacks at the two ends of its own buffer:
// updates of even-depth supernodes grow up from the low end, odd-depth ones
// down from the high end. A front's children then sit on top of the stack
// its own update does not use, so it writes its update while still reading
// theirs, pops them after, and nothing is ever moved. A chain of panels
// (SymbolicFactor::continued) is one front: only its last panel has an
// update matrix, and the children of all its panels are that front's.
#pragma once

#include <cstdint>
#include <vector>

#include "gab/sparse/symbolic.h"

namespace gab {

// Depth of every node of a forest whose parents come after their children
// (parent[s] > s, or -1 for a root): 0 for roots. O(n).
std::vector<int32_t> tree_depths(const std::vector<int32_t>& parent);

// Lays out the update stacks of the groups of a schedule: group g runs the
// supernodes order[group_ptr[g] .. group_ptr[g + 1]) in increasing order and
// pops only its own children's updates (a child in another group leaves its
// update where that group put it). Writes stack_ptr (groups + 1 offsets:
// group g's pair of stacks spans [stack_ptr[g], stack_ptr[g + 1]), as large
// as its peak) and, unless update_offset is null, where each supernode's
// update starts in that buffer (ns entries). O(ns).
void lay_out_update_stacks(const SymbolicFactor& f, const std::vector<int32_t>& order,
                           const std::vector<int32_t>& group_ptr, std::vector<int64_t>* stack_ptr,
                           std::vector<int64_t>* update_offset);

// Doubles of update stacks the serial factorization needs: every supernode
// in one group, in order (SymbolicFactor::stack_peak). Reads supernode_parent,
// row_ptr and first_col. O(ns).
int64_t update_stack_size(const SymbolicFactor& f);

}  // namespace gab
