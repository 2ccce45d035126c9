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
  GAB_RETURN_IF_ERROR(picks.start(graph, spread, rest, {std::max(count, 0)}, false));
  if (count > 0) picks.wait(0);  // all `count`: start() checked the rest suffices
  *order = picks.order();
  return Status::Ok();
}

LevelPicks::~LevelPicks() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  room_.notify_all();
  if (thread_.joinable()) thread_.join();
}

Status LevelPicks::start(const EdgeGraph& graph, const std::vector<int32_t>& spread, const std::vector<int32_t>& rest,
                         const std::vector<int32_t>& levels, bool background) {
  order_.clear();
  levels_.clear();
  ends_.clear();
  size_t count = 0;
  for (int32_t size : levels) {
    if (size < 0) return Status::Error(StatusCode::kInvalidArgument, "level order: a level of negative size");
    if (size == 0) continue;
    count += static_cast<size_t>(size);
    if (count > rest.size()) {
      return Status::Error(StatusCode::kInvalidArgument, "level order: more picks than vertices to pick from");
    }
    levels_.push_back(size);
    ends_.push_back(count);
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
  order_.assign(count, -1);
  if (!background || levels_.empty()) return Status::Ok();
  maps_.assign(levels_.size() + 1, {});
  maps_[0] = sampler_.nearest();  // before the thread: no lock needed
  maps_made_ = 1;
  background_ = true;
#if defined(__cpp_exceptions)
  try {
    thread_ = std::thread([this] { pick_all(); });
  } catch (const std::system_error&) {
    background_ = false;  // no thread to be had: picks here as asked
    maps_.clear();
    maps_made_ = 0;
  }
#else
  thread_ = std::thread([this] { pick_all(); });  // built without exceptions: a refusal ends the process
#endif
  return Status::Ok();
}

bool LevelPicks::pick_level(size_t level) {
  const size_t begin = level == 0 ? 0 : ends_[level - 1];
  std::vector<int32_t> picks;
  picks.reserve(static_cast<size_t>(levels_[level]));
  // Pieces, so that a stop is seen within one.
  while (begin + picks.size() < ends_[level] && !stopping_) {
    const size_t piece = std::min<size_t>(1024, ends_[level] - begin - picks.size());
    if (sampler_.next(static_cast<int32_t>(piece), &picks) == 0) break;  // start() checked the candidates suffice
  }
  std::copy(picks.begin(), picks.end(), order_.begin() + static_cast<std::ptrdiff_t>(begin));
  return begin + picks.size() == ends_[level];
}

void LevelPicks::pick_all() {
  for (size_t level = 0; level < levels_.size(); ++level) {
    if (!pick_level(level)) break;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      levels_made_ = level + 1;
      progress_.notify_all();
      if (maps_off_) continue;
      // The map after this level waits for room, unless the decoder asks
      // for later picks without taking the maps: then no more maps (it
      // searches for them), the picks go on.
      room_.wait(lock, [&] { return stopping_ || maps_made_ - maps_given_ < kPendingMaps || waiting_for_ > level; });
      if (stopping_) break;
      if (maps_made_ - maps_given_ >= kPendingMaps) {
        maps_off_ = true;
        progress_.notify_all();
        continue;
      }
    }
    std::vector<uint64_t> map = sampler_.nearest();
    {
      std::lock_guard<std::mutex> lock(mutex_);
      maps_[level + 1] = std::move(map);
      maps_made_ = level + 2;
    }
    progress_.notify_all();
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    done_ = true;
  }
  progress_.notify_all();
}

bool LevelPicks::wait(size_t level) {
  if (level >= levels_.size()) return false;
  if (!background_) {
    while (levels_made_ <= level) {
      if (!pick_level(levels_made_)) return false;
      ++levels_made_;
    }
    return true;
  }
  if (levels_made_ > level) return true;
  std::unique_lock<std::mutex> lock(mutex_);
  waiting_for_ = std::max(waiting_for_, level);
  room_.notify_all();
  progress_.wait(lock, [&] { return levels_made_ > level || done_; });
  return levels_made_ > level;
}

bool LevelPicks::nearest_before(size_t level, std::vector<uint64_t>* nearest) {
  if (level != maps_given_ || level > levels_.size()) return false;
  if (!background_) {
    if (levels_made_ != level) return false;  // the sampler stands elsewhere
    *nearest = sampler_.nearest();
    ++maps_given_;
    return true;
  }
  {
    std::unique_lock<std::mutex> lock(mutex_);
    progress_.wait(lock, [&] { return maps_made_ > level || maps_off_ || done_; });
    if (maps_made_ <= level) return false;
    *nearest = std::move(maps_[level]);
    ++maps_given_;
  }
  room_.notify_all();
  return true;
}

LevelMembers::LevelMembers(const std::vector<int32_t>& order, const std::vector<int32_t>& rest, int32_t num_vertices)
    : order_(order), rest_(rest), picked_(static_cast<size_t>(num_vertices), 0) {}

std::vector<int32_t> LevelMembers::next(const std::vector<int32_t>& sizes, size_t k) {
  std::vector<int32_t> level;
  if (k + 1 < sizes.size()) {
    level.assign(order_.begin() + start_, order_.begin() + start_ + sizes[k]);
    // In vertex order: a large level read off the rest (in vertex order)
    // costs less than sorting it; a small one is sorted (a scan per level
    // would cost a file of many small levels the rest's size each).
    const size_t size = level.size();
    if (size * 16 < rest_.size()) {
      for (int32_t v : level) picked_[v] = 1;
      std::sort(level.begin(), level.end());
    } else {
      for (int32_t v : level) picked_[v] = 2;
      level.clear();
      for (int32_t v : rest_) {
        if (picked_[v] != 2) continue;
        picked_[v] = 1;
        level.push_back(v);
      }
    }
  } else {
    for (int32_t v : rest_) {
      if (!picked_[v]) level.push_back(v);
    }
  }
  start_ += sizes[k];
  return level;
}

}  // namespace gab
