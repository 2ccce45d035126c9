#include "anchors/anchor_levels.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <system_error>

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
  LevelPicks picks;
  GAB_RETURN_IF_ERROR(picks.start(graph, spread, rest, count, false));
  *order = picks.order();
  return Status::Ok();
}

LevelPicks::~LevelPicks() {
  stopping_ = true;
  if (thread_.joinable()) thread_.join();
}

Status LevelPicks::start(const EdgeGraph& graph, const std::vector<int32_t>& spread, const std::vector<int32_t>& rest,
                         int32_t count, bool background) {
  order_.clear();
  if (count <= 0) return Status::Ok();
  if (static_cast<size_t>(count) > rest.size()) {
    return Status::Error(StatusCode::kInvalidArgument, "level order: more picks than vertices to pick from");
  }
  const Status s = sampler_.start(graph, spread, &rest);
  if (!s.ok()) return Status::Error(StatusCode::kInvalidArgument, "level order: " + s.message());
  // Both checked in range and distinct: a rest vertex in the spread set
  // would leave the picks short.
  std::vector<char> in_spread(static_cast<size_t>(graph.num_vertices()), 0);
  for (int32_t v : spread) in_spread[v] = 1;
  for (int32_t v : rest) {
    if (in_spread[v]) return Status::Error(StatusCode::kInvalidArgument, "level order: the rest overlaps the spread set");
  }
  std::vector<int32_t> seeds;
  sampler_.next(static_cast<int32_t>(spread.size()), &seeds);
  order_.assign(static_cast<size_t>(count), -1);
  if (!background) {
    pick_all();  // here, before returning
    return Status::Ok();
  }
#if defined(__cpp_exceptions)
  try {
    thread_ = std::thread([this] { pick_all(); });
  } catch (const std::system_error&) {
    pick_all();  // no thread to be had: all picks here
  }
#else
  thread_ = std::thread([this] { pick_all(); });  // built without exceptions: a refusal ends the process
#endif
  return Status::Ok();
}

void LevelPicks::pick_all() {
  const int32_t count = static_cast<int32_t>(order_.size());
  // Pieces small at first, where each pick costs the most and the first
  // level waits for them, larger later.
  const int32_t piece = std::max<int32_t>(16, count / 64);
  std::vector<int32_t> picks;
  int32_t made = 0;
  while (made < count && !stopping_) {
    picks.clear();
    sampler_.next(std::min(piece, count - made), &picks);
    std::copy(picks.begin(), picks.end(), order_.begin() + made);
    made += static_cast<int32_t>(picks.size());
    {
      std::lock_guard<std::mutex> lock(mutex_);
      made_ = made;
    }
    progress_.notify_all();
    if (picks.empty()) break;  // start() checked the candidates suffice
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    done_ = true;
  }
  progress_.notify_all();
}

bool LevelPicks::wait(int32_t count) {
  if (made_ >= count) return true;
  std::unique_lock<std::mutex> lock(mutex_);
  progress_.wait(lock, [&] { return made_ >= count || done_; });
  return made_ >= count;
}

LevelMembers::LevelMembers(const std::vector<int32_t>& order, const std::vector<int32_t>& rest, int32_t num_vertices)
    : order_(order), rest_(rest), picked_(static_cast<size_t>(num_vertices), 0) {}

std::vector<int32_t> LevelMembers::next(const std::vector<int32_t>& sizes, size_t k) {
  std::vector<int32_t> level;
  if (k + 1 < sizes.size()) {
    level.assign(order_.begin() + start_, order_.begin() + start_ + sizes[k]);
    for (int32_t v : level) picked_[v] = 1;
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
