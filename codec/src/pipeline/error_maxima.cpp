#include "pipeline/error_maxima.h"

#include <algorithm>
#include <utility>

namespace gab {

namespace {

// Largest key first, ties to the smaller vertex.
bool ranks_before(const std::pair<double, int32_t>& a, const std::pair<double, int32_t>& b) {
  return a.first > b.first || (a.first == b.first && a.second < b.second);
}

// The ranked candidates taken in order, each unless within `separation`
// hops of one taken before: around each pick a breadth-first ball, its
// vertices stamped with the pick's number (a ball walks on through the
// balls before it: the hops count from this pick alone).
std::vector<int32_t> separated(const EdgeGraph& graph, std::vector<std::pair<double, int32_t>>* candidates,
                               int32_t count, int32_t separation) {
  std::sort(candidates->begin(), candidates->end(), ranks_before);
  std::vector<int32_t> ball_of(graph.num_vertices(), -1);
  std::vector<int32_t> picked, ball;
  for (const std::pair<double, int32_t>& candidate : *candidates) {
    if (static_cast<int32_t>(picked.size()) == count) break;
    const int32_t v = candidate.second;
    if (ball_of[v] >= 0) continue;
    const int32_t id = static_cast<int32_t>(picked.size());
    picked.push_back(v);
    ball_of[v] = id;
    ball.assign(1, v);
    size_t layer = 0;
    for (int32_t hop = 0; hop < separation && layer < ball.size(); ++hop) {
      const size_t layer_end = ball.size();
      for (size_t i = layer; i < layer_end; ++i) {
        const int32_t u = ball[i];
        for (int32_t p = graph.offsets[u]; p < graph.offsets[u + 1]; ++p) {
          const int32_t w = graph.neighbors[p];
          if (ball_of[w] == id) continue;
          ball_of[w] = id;
          ball.push_back(w);
        }
      }
      layer = layer_end;
    }
  }
  return picked;
}

}  // namespace

std::vector<int32_t> pick_error_maxima(const EdgeGraph& graph, const std::vector<double>& error,
                                       const ShapeOperator& rec, int32_t count, int32_t separation) {
  const int32_t n = graph.num_vertices();
  // Batches rank the maxima by the error's mean over the closed 1-ring: an
  // anchor pulls a neighbourhood into place, so a broad bump gains more than
  // a one-vertex spike of the same height. Against ranking by the peak, at
  // equal anchors (w = 100, 2% batches, exact positions): camel-head 466 /
  // 1,138: -7% / -2% RMS, horse 1,312 / 4,848: -9% / -4%, feline 1,339 /
  // 4,986: -6% / -5%; the max error rises a little.
  auto ring_mean = [&](int32_t v) {
    double sum = error[v];
    for (int32_t p = graph.offsets[v]; p < graph.offsets[v + 1]; ++p) sum += error[graph.neighbors[p]];
    return sum / (1 + graph.offsets[v + 1] - graph.offsets[v]);
  };
  std::vector<std::pair<double, int32_t>> candidates;  // (rank key, vertex)
  for (int32_t v = 0; v < n; ++v) {
    if (rec.is_anchor(v)) continue;
    bool local_max = true;
    for (int32_t p = graph.offsets[v]; p < graph.offsets[v + 1] && local_max && count > 1; ++p) {
      local_max = error[v] >= error[graph.neighbors[p]];
    }
    if (local_max) candidates.emplace_back(count > 1 ? ring_mean(v) : error[v], v);
  }
  if (candidates.empty()) {
    // Every free vertex has an anchored neighbour with a larger error: fall
    // back to the worst free vertex so the loop always makes progress.
    for (int32_t v = 0; v < n; ++v) {
      if (!rec.is_anchor(v) && (candidates.empty() || error[v] > candidates[0].first)) candidates.assign(1, {error[v], v});
    }
  }
  if (separation > 0 && count > 1) return separated(graph, &candidates, count, separation);
  const size_t keep = std::min<size_t>(static_cast<size_t>(count), candidates.size());
  std::partial_sort(candidates.begin(), candidates.begin() + keep, candidates.end(), ranks_before);
  std::vector<int32_t> picked(keep);
  for (size_t i = 0; i < keep; ++i) picked[i] = candidates[i].second;
  return picked;
}

}  // namespace gab
