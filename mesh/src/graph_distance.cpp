// BFS hop distances and farthest-point sampling on the edge graph.
// Farthest-point sampling is the greedy k-center heuristic (Gonzalez 1985)
// with hop distance: after each pick a BFS from the new vertex lowers the
// distance field only where it shrinks (unit edge lengths make a FIFO order
// from one source exact), and a bucket per distance finds the farthest.
#include "gab/mesh/graph_distance.h"

#include <algorithm>
#include <cstdint>
#include <string>
#include <utility>

namespace gab {

namespace {

// Keys: (hops << 32) | the nearest chosen vertex (graph_distance.h).
constexpr uint64_t kUnreached = FarthestPointSampler::kUnreached;
constexpr uint64_t kOneHop = uint64_t{1} << 32;

Status check_vertices(const EdgeGraph& graph, const std::vector<int32_t>& vertices, const char* what, bool distinct) {
  const int32_t n = graph.num_vertices();
  std::vector<char> seen(distinct ? n : 0, 0);
  for (int32_t v : vertices) {
    if (v < 0 || v >= n) {
      return Status::Error(StatusCode::kInvalidArgument, std::string(what) + " " + std::to_string(v) +
                                                             " is not a vertex (n = " + std::to_string(n) + ")");
    }
    if (distinct) {
      if (seen[v]) return Status::Error(StatusCode::kInvalidArgument, std::string(what) + " " + std::to_string(v) + " given twice");
      seen[v] = 1;
    }
  }
  return Status::Ok();
}

}  // namespace

Status bfs_distances(const EdgeGraph& graph, const std::vector<int32_t>& sources, std::vector<int32_t>* distance) {
  GAB_RETURN_IF_ERROR(check_vertices(graph, sources, "source", false));
  const int32_t n = graph.num_vertices();
  std::vector<int32_t> dist(n, -1), queue;
  queue.reserve(n);
  for (int32_t s : sources) {
    if (dist[s] == -1) {
      dist[s] = 0;
      queue.push_back(s);
    }
  }
  for (size_t q = 0; q < queue.size(); ++q) {
    const int32_t v = queue[q];
    for (int32_t p = graph.offsets[v]; p < graph.offsets[v + 1]; ++p) {
      const int32_t u = graph.neighbors[p];
      if (dist[u] == -1) {
        dist[u] = dist[v] + 1;
        queue.push_back(u);
      }
    }
  }
  *distance = std::move(dist);
  return Status::Ok();
}

Status farthest_point_sampling(const EdgeGraph& graph, int32_t count, const std::vector<int32_t>& seeds,
                               std::vector<int32_t>* picked) {
  return farthest_point_sampling(graph, count, seeds, nullptr, picked);
}

Status farthest_point_sampling(const EdgeGraph& graph, int32_t count, const std::vector<int32_t>& seeds,
                               const std::vector<int32_t>* candidates, std::vector<int32_t>* picked) {
  FarthestPointSampler sampler;
  GAB_RETURN_IF_ERROR(sampler.start(graph, seeds, candidates));
  if (count < 0) return Status::Error(StatusCode::kInvalidArgument, "negative sample count " + std::to_string(count));
  std::vector<int32_t> out;
  out.reserve(std::min(count, graph.num_vertices()));
  sampler.next(count, &out);
  *picked = std::move(out);
  return Status::Ok();
}

// A bucket per distance, and the unreached (every candidate at first, in
// increasing index: taken first), each taken in increasing vertex index
// once it is the farthest left: the farthest first, ties to the smaller
// index. Past the unreached a pick only brings vertices closer than the
// farthest, so a bucket being taken gets no new entries. An entry goes
// stale when its vertex comes closer (a fresh one is put in a lower
// bucket); stale ones are skipped. Sorting a bucket once costs far less
// than a heap's work per entry.
Status FarthestPointSampler::start(const EdgeGraph& graph, const std::vector<int32_t>& seeds,
                                   const std::vector<int32_t>* candidates) {
  GAB_RETURN_IF_ERROR(check_vertices(graph, seeds, "seed", true));
  if (candidates) GAB_RETURN_IF_ERROR(check_vertices(graph, *candidates, "candidate", true));
  *this = FarthestPointSampler();
  graph_ = &graph;
  const int32_t n = graph.num_vertices();
  candidate_.assign(n, candidates ? 0 : 1);
  if (candidates) {
    for (int32_t v : *candidates) candidate_[v] = 1;
  }
  nearest_.assign(n, kUnreached);
  // The seeds at once: one search from all of them.
  seeds_ = seeds;
  for (int32_t s : seeds) {
    nearest_[s] = static_cast<uint64_t>(s);
    queue_.push_back(s);
  }
  spread_from_queue();
  return Status::Ok();
}

// First-in first-out visits in order of hops, so a vertex's key is final
// when it is taken from the queue: only vertices of the layer before can
// lower it. A vertex lowered again in its layer (by a lower chosen vertex
// at the same hops, only when searching from several at once) is queued
// again; taken the second time it offers what it offered the first, and
// nothing changes. A vertex the search does not lower passes nothing on:
// its key plus one hop is at most what the search would offer its
// neighbours. A candidate enters a bucket when its hops fall, not when
// only its nearest chosen vertex does.
void FarthestPointSampler::spread_from_queue() {
  const EdgeGraph& graph = *graph_;
  const int32_t* offsets = graph.offsets.data();
  const int32_t* neighbors = graph.neighbors.data();
  uint64_t* nearest = nearest_.data();
  for (size_t q = 0; q < queue_.size(); ++q) {
    const int32_t v = queue_[q];
    const uint64_t offer = nearest[v] + kOneHop;
    for (int32_t p = offsets[v]; p < offsets[v + 1]; ++p) {
      const int32_t u = neighbors[p];
      const uint64_t old = nearest[u];
      if (offer >= old) continue;
      nearest[u] = offer;
      queue_.push_back(u);
      const uint32_t hops = static_cast<uint32_t>(offer >> 32);
      if (hops == static_cast<uint32_t>(old >> 32) || !candidate_[u]) continue;
      if (hops >= buckets_.size()) buckets_.resize(static_cast<size_t>(hops) + 1);
      buckets_[hops].push_back(u);
    }
  }
}

void FarthestPointSampler::add(int32_t s) {
  nearest_[s] = static_cast<uint64_t>(s);
  queue_.assign(1, s);
  spread_from_queue();
}

int32_t FarthestPointSampler::next(int32_t count, std::vector<int32_t>* picked) {
  const size_t before = picked->size();
  auto taken = [&]() { return static_cast<int32_t>(picked->size() - before); };
  while (seeds_out_ < seeds_.size() && taken() < count) picked->push_back(seeds_[seeds_out_++]);
  // The smallest vertex of each component nothing reaches yet.
  const int32_t n = static_cast<int32_t>(nearest_.size());
  for (; scan_ < n && taken() < count; ++scan_) {
    if (candidate_[scan_] && nearest_[scan_] == kUnreached) {
      picked->push_back(scan_);
      add(scan_);
    }
  }
  if (scan_ < n) return taken();
  if (!buckets_started_) {
    buckets_started_ = true;
    bucket_ = buckets_.size();
  }
  // Distance 0 is a chosen vertex: every candidate is then chosen.
  while (taken() < count && bucket_ > 1) {
    std::vector<int32_t>& bucket = buckets_[bucket_ - 1];
    if (!bucket_sorted_) {
      std::sort(bucket.begin(), bucket.end());
      bucket_sorted_ = true;
    }
    for (; entry_ < bucket.size() && taken() < count; ++entry_) {
      const int32_t v = bucket[entry_];
      if ((nearest_[v] >> 32) == bucket_ - 1) {  // puts go below: no reallocation
        picked->push_back(v);
        add(v);
      }
    }
    if (entry_ < bucket.size()) break;
    std::vector<int32_t>().swap(bucket);
    --bucket_;
    entry_ = 0;
    bucket_sorted_ = false;
  }
  return taken();
}

}  // namespace gab
