// The two-stack layout of the multifrontal update matrices: one simulation
// that both the symbolic analysis (the serial stack size) and the factor
// schedule (each group's stacks and every update's place) use.
#include "gab/sparse/update_matrix_stacks.h"

#include <algorithm>
#include <numeric>

#include "gab/sparse/dense_kernels.h"

namespace gab {

std::vector<int32_t> tree_depths(const std::vector<int32_t>& parent) {
  const int32_t n = static_cast<int32_t>(parent.size());
  std::vector<int32_t> depth(n, 0);
  // Parents come after their children: walking down, a parent's depth is set.
  for (int32_t s = n - 1; s >= 0; --s) {
    if (parent[s] != -1) depth[s] = depth[parent[s]] + 1;
  }
  return depth;
}

void lay_out_update_stacks(const SymbolicFactor& f, const std::vector<int32_t>& order,
                           const std::vector<int32_t>& group_ptr, std::vector<int64_t>* stack_ptr,
                           std::vector<int64_t>* update_offset) {
  const int32_t ns = f.num_supernodes;
  const int32_t groups = static_cast<int32_t>(group_ptr.size()) - 1;
  // A chain of panels is one front (supernodal_factor.cpp): its last panel
  // alone has an update matrix, and the children of all its panels are the
  // front's children. front[s]: the last panel of s's chain (s if none).
  std::vector<int32_t> front(ns);
  for (int32_t s = ns - 1; s >= 0; --s) front[s] = f.continues(s) ? front[s + 1] : s;
  std::vector<int32_t> front_parent(ns);
  for (int32_t s = 0; s < ns; ++s) {
    front_parent[s] = f.supernode_parent[s] == -1 ? -1 : front[f.supernode_parent[s]];
  }
  const std::vector<int32_t> depth = tree_depths(front_parent);
  std::vector<int32_t> group_of(ns, -1);
  for (int32_t g = 0; g < groups; ++g) {
    for (int32_t i = group_ptr[g]; i < group_ptr[g + 1]; ++i) group_of[order[i]] = g;
  }
  // pending[s]: doubles of the updates of s's children in s's group, which
  // s pops once it has written its own.
  std::vector<int64_t> pending(ns, 0);
  stack_ptr->assign(groups + 1, 0);
  if (update_offset != nullptr) update_offset->assign(ns, 0);
  for (int32_t g = 0; g < groups; ++g) {
    const int64_t base = (*stack_ptr)[g];
    int64_t top[2] = {0, 0}, peak = 0;
    for (int32_t i = group_ptr[g]; i < group_ptr[g + 1]; ++i) {
      const int32_t s = order[i];
      if (f.continues(s)) continue;  // no update matrix of its own
      const int64_t size = packed_lower_size(f.rows(s) - f.cols(s));
      const int side = depth[s] & 1;
      // The high end is known only with the peak: until then an odd-depth
      // update is placed by its distance from that end.
      if (update_offset != nullptr) (*update_offset)[s] = side == 0 ? top[0] : top[1] + size;
      top[side] += size;
      peak = std::max(peak, top[0] + top[1]);
      top[1 - side] -= pending[s];
      const int32_t parent = front_parent[s];
      if (parent != -1 && group_of[parent] == g) pending[parent] += size;
    }
    (*stack_ptr)[g + 1] = base + peak;
    if (update_offset == nullptr) continue;
    for (int32_t i = group_ptr[g]; i < group_ptr[g + 1]; ++i) {
      const int32_t s = order[i];
      int64_t& offset = (*update_offset)[s];
      if (f.continues(s)) {  // an empty update, in the group's buffer
        offset = base;
        continue;
      }
      offset = (depth[s] & 1) == 0 ? base + offset : base + peak - offset;
    }
  }
}

int64_t update_stack_size(const SymbolicFactor& f) {
  std::vector<int32_t> order(f.num_supernodes);
  std::iota(order.begin(), order.end(), 0);
  std::vector<int64_t> stack_ptr;
  lay_out_update_stacks(f, order, {0, f.num_supernodes}, &stack_ptr, nullptr);
  return stack_ptr[1];
}

}  // namespace gab
