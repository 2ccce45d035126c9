// Levels (format flag kGabFlagLevels, gab_format.h): a coarse-to-fine order
// of an anchor set that the decoder works out itself, so that the file codes
// the set once instead of chunk by chunk in selection order.
//
// Chunk 0 holds the spread set (the encoder's farthest-point start) and the
// set of all other anchors, "the rest". Level 1, 2, ... take the rest in
// farthest-point order (hops on the edge graph, from the spread set and the
// levels before), each level ending when the anchors so far reach
// growth16 / 16 times those before it (and has at least kMinLevelAnchors);
// the last level takes what remains.
// A level is well spread over the surface the way greedy batches are, which
// is what makes the reconstruction of the levels before it a good
// prediction of its positions; what the file saves is the selection order
// (at 1e-3 the first layout's nested chunk subsets cost 1.3-2.5 times the
// one subset of the whole set on the shared meshes; the levels' positions
// cost 0-5% more than the greedy chunks').
//
// Everything here is integer and deterministic: both sides get the same
// levels from the same connectivity. Internal to the codec.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

#include "gab/mesh/edge_graph.h"
#include "gab/mesh/graph_distance.h"
#include "gab/status.h"

namespace gab {

// Growth of the levels, in sixteenths: above 1 and bounded so that the
// products below stay far inside 64 bits.
constexpr uint32_t kMinLevelGrowth16 = 17;
constexpr uint32_t kMaxLevelGrowth16 = 1u << 16;
// Every level but the last holds at least this many anchors: a level costs
// 12 bytes of framing and coder flush, more than a few anchors' better
// prediction is worth (a 40 x 20 torus with 150 anchors: 790 bytes with
// levels of 1, 2, 4, ..., 771 with 8 at least; bunny-small 10.38 -> 10.35
// bits per vertex; 16-64 changed the shared meshes by under 1% either way).
constexpr uint64_t kMinLevelAnchors = 8;

struct LevelPlan {
  int32_t spread = 0;      // anchors of chunk 0
  int32_t rest = 0;        // anchors of the levels
  uint32_t growth16 = 32;  // kMinLevelGrowth16..kMaxLevelGrowth16

  // Sizes of levels 1..L: all positive, summing to rest. A level ends at
  // max(before + kMinLevelAnchors, floor(before * growth16 / 16)) anchors
  // in all (the last at rest + spread). O(L).
  std::vector<int32_t> level_sizes() const;
};

// A growth factor (> 1) in sixteenths, rounded and clamped to the range.
uint32_t level_growth16(double growth);

// The first `count` vertices of `rest` (distinct, none in `spread`) in
// farthest-point order: each pick is the vertex of rest farthest in hops
// from `spread` and the picks before it, ties to the smaller index; a vertex
// that none of them reaches is infinitely far: farthest_point_sampling's
// picks among `rest` after the seeds `spread` (graph_distance.h, its cost).
Status level_order(const EdgeGraph& graph, const std::vector<int32_t>& spread, const std::vector<int32_t>& rest,
                   int32_t count, std::vector<int32_t>* order);

// level_order's picks, level by level, with the nearest-anchor map the
// reconstruction needs at each level (IterativeReconstruction's
// kFewestHopsLowest rule: the farthest-point search keeps it as it goes, so
// the decoder need not search again). With `background` the picks are made
// on a thread of their own, so that a decoder works through the first
// levels while the later ones are picked (the first picks, far apart, cost
// the most: each moves the distances of a large region); without, here as
// wait() asks for them. The same picks as level_order, in the same order.
class LevelPicks {
 public:
  LevelPicks() = default;
  LevelPicks(const LevelPicks&) = delete;
  LevelPicks& operator=(const LevelPicks&) = delete;
  ~LevelPicks();  // stops the picking and joins its thread

  // Checks what level_order checks (it runs on this) for picks of levels
  // sized `levels` (each positive; their sum at most rest.size()), then
  // starts picking. `graph`, `spread` and `rest` must outlive this object.
  Status start(const EdgeGraph& graph, const std::vector<int32_t>& spread, const std::vector<int32_t>& rest,
               const std::vector<int32_t>& levels, bool background);
  // Sized the levels' sum; the picks of the levels wait() has returned
  // true for are in place.
  const std::vector<int32_t>& order() const { return order_; }
  // Returns once level `level`'s picks (and those before) are in order():
  // true, or false if the picking ended short of them (it cannot when
  // start's checks passed).
  bool wait(size_t level);
  // The nearest chosen vertex of every vertex (FarthestPointSampler::
  // nearest()) once the spread set and levels 0 .. level - 1 are chosen,
  // for level = 0 .. levels.size(): each once, in increasing order, after
  // wait(level - 1) and before wait(level). False, and *nearest untouched,
  // when asked out of that order (then search for it instead).
  bool nearest_before(size_t level, std::vector<uint64_t>* nearest);

 private:
  // The picks of level `level` (the sampler stands after the level before).
  bool pick_level(size_t level);
  // The thread's work: every level's picks, a copy of the nearest map
  // after each (the first, before them, start() makes), at most
  // kPendingMaps of them waiting.
  void pick_all();
  // Without a thread, copies of the nearest map are made when asked for;
  // with one, the thread makes them and holds at most this many at once
  // (memory: 8 bytes a vertex each).
  static constexpr size_t kPendingMaps = 2;

  FarthestPointSampler sampler_;
  std::vector<int32_t> order_, levels_;
  std::vector<size_t> ends_;  // ends_[k]: picks in levels 0..k
  std::vector<std::vector<uint64_t>> maps_;  // the thread's copies, by level
  size_t maps_given_ = 0;                    // nearest_before calls answered
  std::atomic<size_t> levels_made_{0};
  // Under mutex_: the maps made; the highest level wait() has waited for;
  // maps given up (the decoder did not take them).
  size_t maps_made_ = 0, waiting_for_ = 0;
  bool maps_off_ = false;
  bool background_ = false;
  std::atomic<bool> stopping_{false}, done_{false};
  std::mutex mutex_;
  std::condition_variable progress_, room_;
  std::thread thread_;
};

// The levels' members, level by level, from the farthest-point picks
// (`order`, level_order's output) and the rest: level k < L - 1 is the next
// sizes[k] picks, the last level every vertex of the rest not picked; each
// in vertex order (the order the chunks code them). The encoder and the
// decoder split the anchors through this one rule.
class LevelMembers {
 public:
  // `order` and `rest` (in increasing vertex order) must outlive this
  // object; `order` needs its picks only as far as next() reads them
  // (LevelPicks fills it as it goes).
  LevelMembers(const std::vector<int32_t>& order, const std::vector<int32_t>& rest, int32_t num_vertices);
  // Level k's anchors; call for k = 0, 1, ... in turn. Reads order's next
  // sizes[k] picks, or for the last level (every pick taken before it) none.
  std::vector<int32_t> next(const std::vector<int32_t>& sizes, size_t k);

 private:
  const std::vector<int32_t>& order_;
  const std::vector<int32_t>& rest_;
  std::vector<char> picked_;
  size_t start_ = 0;
};

}  // namespace gab
