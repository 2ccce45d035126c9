// The subtree-to-thread split and the update-stack layout of each group.
#include "gab/sparse/factor_schedule.h"

#include <algorithm>

#include "gab/sparse/update_matrix_stacks.h"

namespace gab {
namespace {

// Flops of supernode s's partial factorization: about the square of each
// of its columns' counts (the figure SymbolicFactor::flops sums).
double node_flops(const SymbolicFactor& f, int32_t s) {
  const double m = f.rows(s);
  double sum = 0.0;
  for (int32_t j = 0; j < f.cols(s); ++j) sum += (m - j) * (m - j);
  return sum;
}

// Deals subtrees (largest first) to the least loaded of `threads` bins;
// returns the largest bin's load and writes each subtree's bin.
double deal(const std::vector<int32_t>& roots, const std::vector<double>& subtree_work,
            int32_t threads, std::vector<int32_t>* sorted, std::vector<int32_t>* bin) {
  *sorted = roots;
  std::sort(sorted->begin(), sorted->end(), [&](int32_t a, int32_t b) {
    return subtree_work[a] != subtree_work[b] ? subtree_work[a] > subtree_work[b] : a < b;
  });
  std::vector<double> load(threads, 0.0);
  bin->resize(sorted->size());
  for (size_t i = 0; i < sorted->size(); ++i) {
    const int32_t least =
        static_cast<int32_t>(std::min_element(load.begin(), load.end()) - load.begin());
    (*bin)[i] = least;
    load[least] += subtree_work[(*sorted)[i]];
  }
  return *std::max_element(load.begin(), load.end());
}

}  // namespace

FactorSchedule plan_factor_schedule(const SymbolicFactor& f, int32_t threads,
                                    ScheduleBalance balance) {
  const int32_t ns = f.num_supernodes;
  FactorSchedule plan;
  plan.threads = std::max(1, std::min({threads, ns, kMaxFactorThreads}));
  const int32_t t = plan.threads;

  std::vector<int32_t>& child_head = plan.child_head;
  std::vector<int32_t>& child_next = plan.child_next;
  child_head.assign(ns, -1);
  child_next.assign(ns, -1);
  for (int32_t s = ns - 1; s >= 0; --s) {
    const int32_t parent = f.supernode_parent[s];
    if (parent == -1) continue;
    child_next[s] = child_head[parent];
    child_head[parent] = s;
  }
  std::vector<double> work(ns), subtree_work(ns);
  std::vector<int32_t> first_desc(ns);  // subtree of s = supernodes [first_desc[s], s]
  for (int32_t s = 0; s < ns; ++s) {
    work[s] = balance == ScheduleBalance::kFactorFlops
                   ? node_flops(f, s)
                   : static_cast<double>(f.cols(s)) * f.rows(s);
    subtree_work[s] = work[s];
    first_desc[s] = s;
  }
  for (int32_t s = 0; s < ns; ++s) {
    const int32_t parent = f.supernode_parent[s];
    if (parent == -1) continue;
    subtree_work[parent] += subtree_work[s];
    first_desc[parent] = std::min(first_desc[parent], first_desc[s]);
  }

  // owner[s]: the group that factors s. Split the heaviest subtree until the
  // deal is balanced, keeping the split with the least critical path (top
  // part + largest bin); a few hundred splits are plenty for trees whose
  // top is a handful of separators.
  std::vector<int32_t> owner(ns, t == 1 ? 0 : t);
  if (t > 1) {
    std::vector<int32_t> roots, sorted, bin, best_sorted, best_bin;
    for (int32_t s = 0; s < ns; ++s) {
      if (f.supernode_parent[s] == -1) roots.push_back(s);
    }
    double top = 0.0, best = -1.0;
    for (int split = 0; split < 512 && !roots.empty(); ++split) {
      const double cost = top + deal(roots, subtree_work, t, &sorted, &bin);
      if (best < 0.0 || cost < best) {
        best = cost;
        best_sorted = sorted;
        best_bin = bin;
      }
      const int32_t heaviest = sorted.front();
      if (child_head[heaviest] == -1) break;
      roots.erase(std::find(roots.begin(), roots.end(), heaviest));
      // A chain of panels is factored as one front, by one group: the
      // panels below a split one join the top part with it.
      for (int32_t h = heaviest; h != -1;) {
        top += work[h];
        int32_t panel_below = -1;
        for (int32_t c = child_head[h]; c != -1; c = child_next[c]) {
          if (f.continues(c)) {
            panel_below = c;
          } else {
            roots.push_back(c);
          }
        }
        h = panel_below;
      }
    }
    for (size_t i = 0; i < best_sorted.size(); ++i) {
      const int32_t r = best_sorted[i];
      for (int32_t s = first_desc[r]; s <= r; ++s) owner[s] = best_bin[i];
    }
  }

  plan.group_ptr.assign(t + 2, 0);
  plan.group_work.assign(t + 1, 0.0);
  for (int32_t s = 0; s < ns; ++s) {
    ++plan.group_ptr[owner[s] + 1];
    plan.group_work[owner[s]] += work[s];
  }
  for (int32_t g = 0; g <= t; ++g) plan.group_ptr[g + 1] += plan.group_ptr[g];
  plan.order.resize(ns);
  {
    std::vector<int32_t> next(plan.group_ptr.begin(), plan.group_ptr.end() - 1);
    for (int32_t s = 0; s < ns; ++s) plan.order[next[owner[s]]++] = s;
  }

  plan.own_rows.resize(ns);
  for (int32_t s = 0; s < ns; ++s) {
    const int32_t k = f.cols(s), p = f.rows(s) - k;
    int32_t own = p;
    if (owner[s] != t) {
      const int32_t* below = f.row_ind.data() + f.row_ptr[s] + k;
      while (own > 0 && owner[f.supernode_of[below[own - 1]]] == t) --own;
    }
    plan.own_rows[s] = own;
  }
  plan.top_rows_ptr.assign(ns + 1, 0);
  for (int32_t s = 0; s < ns; ++s) {
    plan.top_rows_ptr[s + 1] = plan.top_rows_ptr[s] + f.rows(s) - f.cols(s) - plan.own_rows[s];
  }

  // Each group runs on its own pair of update stacks; a front pops its
  // children of the same group, children of other groups stay where their
  // group left them (update_matrix_stacks.h).
  lay_out_update_stacks(f, plan.order, plan.group_ptr, &plan.stack_ptr, &plan.update_offset);
  return plan;
}

}  // namespace gab
