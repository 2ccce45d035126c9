#include "anchors/anchor_levels.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

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
  const int32_t n = graph.num_vertices();
  if (count <= 0) return Status::Ok();
  if (static_cast<size_t>(count) > rest.size()) {
    return Status::Error(StatusCode::kInvalidArgument, "level order: more picks than vertices to pick from");
  }
  std::vector<int32_t> distance;
  GAB_RETURN_IF_ERROR(bfs_distances(graph, spread, &distance));
  constexpr int32_t kFar = std::numeric_limits<int32_t>::max();
  for (int32_t& d : distance) d = d < 0 ? kFar : d;
  std::vector<char> candidate(n, 0);
  for (int32_t v : rest) {
    if (v < 0 || v >= n || candidate[v]) {
      return Status::Error(StatusCode::kInvalidArgument, "level order: vertices out of range or repeated");
    }
    candidate[v] = 1;
  }
  // A bucket per distance, and one for the unreached (infinitely far: taken
  // first), each taken in increasing vertex index once it is the farthest
  // left: the farthest first, ties to the smaller index. After the
  // unreached, a pick only brings vertices closer than the farthest, so a
  // bucket being taken gets no new entries. An entry goes stale when its
  // vertex comes closer (a fresh one is put in a lower bucket) or is picked,
  // and is skipped. Sorting a bucket once costs far less than a heap's work
  // per entry.
  std::vector<std::vector<int32_t>> buckets;
  std::vector<int32_t> unreached;
  auto put = [&](int32_t v, int32_t d) {
    if (d == kFar) {
      unreached.push_back(v);
      return;
    }
    if (static_cast<size_t>(d) >= buckets.size()) buckets.resize(static_cast<size_t>(d) + 1);
    buckets[d].push_back(v);
  };
  for (int32_t v : rest) put(v, distance[v]);
  order->reserve(count);
  std::vector<int32_t> queue;
  auto take = [&](std::vector<int32_t>* bucket, int32_t d) {
    std::sort(bucket->begin(), bucket->end());
    for (size_t i = 0; i < bucket->size() && static_cast<int32_t>(order->size()) < count; ++i) {
      const int32_t v = (*bucket)[i];
      if (!candidate[v] || distance[v] != d) continue;
      candidate[v] = 0;
      order->push_back(v);
      // BFS from v, only where it brings a vertex closer; first-in first-out
      // from one source visits in order of distance, so each vertex settles
      // at its new distance when first reached.
      distance[v] = 0;
      queue.assign(1, v);
      for (size_t head = 0; head < queue.size(); ++head) {
        const int32_t x = queue[head];
        const int32_t next = distance[x] + 1;
        for (int32_t p = graph.offsets[x]; p < graph.offsets[x + 1]; ++p) {
          const int32_t u = graph.neighbors[p];
          if (next >= distance[u]) continue;
          distance[u] = next;
          queue.push_back(u);
          if (candidate[u]) put(u, next);
        }
      }
    }
    std::vector<int32_t>().swap(*bucket);
  };
  take(&unreached, kFar);
  for (size_t d = buckets.size(); d-- > 0 && static_cast<int32_t>(order->size()) < count;) {
    take(&buckets[d], static_cast<int32_t>(d));  // puts go to buckets below d: no reallocation under it
  }
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
