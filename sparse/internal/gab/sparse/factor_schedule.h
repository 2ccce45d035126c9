// Where each supernode's multifrontal work runs, and where its update matrix
// lives: the plan that lets independent subtrees of the elimination tree be
// factored by different threads.
//
// Subtree-to-thread mapping (Geist & Ng, "Task scheduling for parallel sparse
// Cholesky factorization", 1989): starting from the roots, the heaviest
// subtree is split into its children (its root joining the "top" part) until
// the subtrees can be dealt to the threads in balance (largest first, each to
// the least loaded thread). Each thread then factors whole subtrees on its own
// update stacks, with nothing shared but read-only analysis; the top part runs
// after them. Every front is assembled from the same children in the same
// order and factored by the same kernels whatever the thread count, so the
// factor is bit-identical for every schedule (encoder and decoder of the codec
// rely on this).
#pragma once

#include <cstdint>
#include <vector>

#include "gab/sparse/symbolic.h"

namespace gab {

struct FactorSchedule {
  int32_t threads = 1;  // subtree groups that run concurrently
  // Supernodes by group, each group in increasing (post)order: groups
  // 0..threads-1 are the threads' subtrees, group `threads` the top part (the
  // supernodes above them, run after the subtrees; empty when threads == 1).
  std::vector<int32_t> order;
  std::vector<int32_t> group_ptr;  // threads + 2 offsets into order
  // Offset, in the update-stack buffer, of supernode s's update matrix
  // (a packed lower triangle of order rows - cols: packed_lower_size
  // doubles, dense_kernels.h). Each group has its own pair of stacks (see
  // supernodal_factor.cpp) in [stack_ptr[g], stack_ptr[g + 1]).
  std::vector<int64_t> update_offset;
  std::vector<int64_t> stack_ptr;  // threads + 2
  // Rows below supernode s's columns that are not in the top part: its
  // rows in the top part (if any) are the last rows - cols - own_rows[s]
  // (the top part holds ancestors only). The parallel forward solve adds
  // those after the groups, in order. rows - cols for top supernodes.
  std::vector<int32_t> own_rows;
  // Prefix sums over supernodes of those top-part rows (rows - cols -
  // own_rows[s], 0 for top supernodes): ns + 1 entries. The parallel forward
  // solve keeps each group supernode's contribution to them at
  // top_rows_ptr[s] * nrhs in its workspace until the in-order pass adds it.
  std::vector<int64_t> top_rows_ptr;
  // Children of each supernode in increasing order (the serial assembly
  // order every schedule keeps): child_head[s], then child_next[c]; -1 ends.
  std::vector<int32_t> child_head, child_next;
  // Estimated work of each group in the units of the balance (ScheduleBalance
  // below) the split achieved.
  std::vector<double> group_work;  // threads + 1

  int64_t stack_doubles() const { return stack_ptr.empty() ? 0 : stack_ptr.back(); }
};

// What the split balances: the factorization's flops (about the square of
// each column's count), or the solves' work (the stored entries, each read
// once per direction). The two differ most in the top part, where the
// flops concentrate.
enum class ScheduleBalance { kFactorFlops, kSolveEntries };

// The schedule for `threads` threads (clamped to [1, kMaxFactorThreads] and
// to the number of supernodes). With one thread: every supernode in one
// group, in order, and the stack of SymbolicFactor::stack_peak doubles.
// Time O(ns log ns).
FactorSchedule plan_factor_schedule(const SymbolicFactor& f, int32_t threads,
                                    ScheduleBalance balance = ScheduleBalance::kFactorFlops);

}  // namespace gab
