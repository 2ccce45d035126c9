#include "anchors/anchor_levels.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "gab/mesh/graph_distance.h"

namespace gab {

std::vector<int32_t> LevelPlan::level_sizes() const {
  std::vector<int32_t> sizes;
  uint64_t total = static_cast<uint64_t>(std::max(spread, 0));
  uint64_t remaining = static_cast<uint64_t>(std::max(rest, 0));
  while (remaining > 0) {
    const uint64_t end = std::max(total + kMinLevelAnchors, total * growth16 / 16);
    const uint64_t size = std::min(end - total, remaining);
    sizes.push_back(static_cast<int32_t>(size));
    total += size;
    remaining -= size;
  }
  return sizes;
}

uint32_t level_growth16(double growth) {
  if (!(growth * 16 < kMaxLevelGrowth16)) return kMaxLevelGrowth16;  // also NaN
  const double g = std::floor(growth * 16 + 0.5);
  return static_cast<uint32_t>(std::max(g, static_cast<double>(kMinLevelGrowth16)));
}

Status level_order(const EdgeGraph& graph, const std::vector<int32_t>& spread, const std::vector<int32_t>& rest,
                   int32_t count, std::vector<int32_t>* order) {
  order->clear();
  if (count <= 0) return Status::Ok();
  if (static_cast<size_t>(count) > rest.size()) {
    return Status::Error(StatusCode::kInvalidArgument, "level order: more picks than vertices to pick from");
  }
  std::vector<int32_t> picked;
  const Status s = farthest_point_sampling(graph, static_cast<int32_t>(spread.size()) + count, spread, &rest, &picked);
  if (!s.ok()) return Status::Error(StatusCode::kInvalidArgument, "level order: " + s.message());
  if (picked.size() != spread.size() + static_cast<size_t>(count)) {  // a rest vertex in the spread set
    return Status::Error(StatusCode::kInvalidArgument, "level order: the rest overlaps the spread set");
  }
  order->assign(picked.begin() + static_cast<std::ptrdiff_t>(spread.size()), picked.end());
  return Status::Ok();
}

LevelMembers::LevelMembers(const std::vector<int32_t>& order, const std::vector<int32_t>& rest, int32_t num_vertices)
    : order_(order), rest_(rest), picked_(static_cast<size_t>(num_vertices), 0) {
  for (int32_t v : order) picked_[v] = 1;
}

std::vector<int32_t> LevelMembers::next(const std::vector<int32_t>& sizes, size_t k) {
  std::vector<int32_t> level;
  if (k + 1 < sizes.size()) {
    level.assign(order_.begin() + start_, order_.begin() + start_ + sizes[k]);
    std::sort(level.begin(), level.end());
  } else {
    for (int32_t v : rest_) {
      if (!picked_[v]) level.push_back(v);
    }
  }
  start_ += sizes[k];
  return level;
}

}  // namespace gab
