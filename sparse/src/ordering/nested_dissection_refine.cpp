// FM refinement of a vertex separator (Fiduccia & Mattheyses, "A linear-time
// heuristic for improving network partitions", DAC 1982, moved from edges to
// vertex separators as in Ashcraft & Liu, "A partition improvement algorithm
// for generalized nested dissection", Boeing BCSTECH-94-020, 1994, and
// "Robust ordering of sparse matrices using multisection", SIAM J. Matrix
// Anal. Appl. 19(3), 1998; the multilevel use as in Karypis & Kumar 1998).
//
// A move takes a separator vertex v to side s; its neighbours on the other
// side enter the separator (else an edge would join the sides). With
// ext[v][t] = weight of v's neighbours on side t, the separator shrinks by
//
//     gain(v -> s) = w(v) - ext[v][1 - s].
//
// A pass keeps the separator vertices in a max-heap by gain, makes the best
// admissible move (the target side stays under the weight bound) even when
// its gain is negative, locks the moved vertex, updates the gains of the
// vertices around it, and stops after enough moves without a new best; the
// moves after the best state are then undone. By default the passes are
// one-sided (each moves vertices into one side only, the sides alternating:
// the refinement METIS uses for its orderings), which measured 10% fewer
// flops than two-sided passes (one heap per side, the better move of the
// two each time) on the shared meshes' factors (docs/tuning-engine.md, "Nested
// dissection"). Cost of a pass: O(sum of degrees of the vertices it touches
// * log), not O(n).
#include <algorithm>
#include <cstdlib>

#include "ordering/nested_dissection_graph.h"

namespace gab {
namespace nd {
namespace {

// Max-heap of vertices keyed by gain (ties: smaller vertex first), with each
// vertex's position so its key can change in place. The position and key
// arrays are the workspace's, sized for the largest graph; positions are -1
// for every vertex outside the heap between calls.
//
// A decrease is lazy: the heap is ordered by a stored key that may exceed the
// true key (never falls below it), and a stale top is settled (stored key set
// to the true one, sifted down) before it is read. The settled top is then
// the true maximum in the same order: every other vertex's true key is at
// most its stored key, which is at most the top's. Most key changes of a move
// lower the gains of vertices that never reach the top again (their moves
// would pull the moved vertex's side into the separator), and sifting those
// down was a third of the heap work.
class GainHeap {
 public:
  GainHeap(std::vector<int32_t>* pos, std::vector<int32_t>* key, std::vector<int32_t>* stored,
           std::vector<int32_t>* heap)
      : pos_(*pos), key_(*key), stored_(*stored), heap_(*heap) {}
  bool empty() const { return heap_.empty(); }
  // The vertex with the largest key; call settle() first.
  int32_t top() const { return heap_[0]; }
  int32_t key(int32_t v) const { return key_[v]; }
  bool contains(int32_t v) const { return pos_[v] >= 0; }

  // Makes the top's stored key its true key: top() is then the maximum.
  void settle() {
    while (!heap_.empty() && stored_[heap_[0]] != key_[heap_[0]]) {
      stored_[heap_[0]] = key_[heap_[0]];
      down(0);
    }
  }
  void push(int32_t v, int32_t key) {
    key_[v] = stored_[v] = key;
    pos_[v] = static_cast<int32_t>(heap_.size());
    heap_.push_back(v);
    up(pos_[v]);
  }
  void update(int32_t v, int32_t key) {
    key_[v] = key;
    if (key > stored_[v]) {
      stored_[v] = key;
      up(pos_[v]);
    }
  }
  void remove(int32_t v) {
    const int32_t i = pos_[v];
    const int32_t last = heap_.back();
    heap_.pop_back();
    pos_[v] = -1;
    if (last == v) return;
    heap_[i] = last;
    pos_[last] = i;
    up(i);
    down(pos_[last]);
  }
  void clear() {
    for (int32_t v : heap_) pos_[v] = -1;
    heap_.clear();
  }

 private:
  bool before(int32_t a, int32_t b) const {
    return stored_[a] > stored_[b] || (stored_[a] == stored_[b] && a < b);
  }
  void place(int32_t i, int32_t v) {
    heap_[i] = v;
    pos_[v] = i;
  }
  void up(int32_t i) {
    const int32_t v = heap_[i];
    while (i > 0) {
      const int32_t parent = (i - 1) / 2;
      if (!before(v, heap_[parent])) break;
      place(i, heap_[parent]);
      i = parent;
    }
    place(i, v);
  }
  void down(int32_t i) {
    const int32_t v = heap_[i];
    const int32_t size = static_cast<int32_t>(heap_.size());
    for (;;) {
      int32_t child = 2 * i + 1;
      if (child >= size) break;
      if (child + 1 < size && before(heap_[child + 1], heap_[child])) ++child;
      if (!before(heap_[child], v)) break;
      place(i, heap_[child]);
      i = child;
    }
    place(i, v);
  }

  std::vector<int32_t>& pos_;
  std::vector<int32_t>& key_;
  std::vector<int32_t>& stored_;
  std::vector<int32_t>& heap_;
};

// The quality of a state, compared lexicographically: weight beyond the
// bound first (only nonzero for a projection that starts unbalanced), then
// the separator's weight, then the difference of the sides.
struct Cost {
  int64_t excess;
  int64_t separator;
  int64_t difference;
  bool operator<(const Cost& o) const {
    if (excess != o.excess) return excess < o.excess;
    if (separator != o.separator) return separator < o.separator;
    return difference < o.difference;
  }
};

class SeparatorRefiner {
 public:
  SeparatorRefiner(const Graph& g, const NestedDissectionOptions& params, Workspace* ws, std::vector<uint8_t>* where)
      : g_(g), params_(params), where_(*where), max_side_(max_side_weight(g, params.imbalance)),
        // Small graphs need few speculative moves to climb out of a local minimum.
        patience_(static_cast<size_t>(std::min(params.refine_patience, std::max(20, g.n / 100)))),
        r_(ws->refine),
        heap_{GainHeap(&r_.pos[0], &r_.key[0], &r_.stored[0], &r_.heap[0]),
              GainHeap(&r_.pos[1], &r_.key[1], &r_.stored[1], &r_.heap[1])} {
    weight_[0] = weight_[1] = weight_[2] = 0;
    r_.separator.clear();
    for (int32_t v = 0; v < g.n; ++v) {
      weight_[where_[v]] += g.vw[v];
      if (where_[v] == kSeparator) r_.separator.push_back(v);
    }
  }

  void run() {
    if (params_.one_sided_refinement) {
      // Passes in alternating directions, the first into the lighter side;
      // stop after a pair of passes that did not improve the separator.
      int to = weight_[0] <= weight_[1] ? 0 : 1;
      bool first_improved = false;  // the first pass of the current pair
      for (int32_t pass = 0; pass < 2 * params_.refine_passes; ++pass, to = 1 - to) {
        const bool improved = one_sided_pass(to);
        if (pass % 2 == 0) {
          first_improved = improved;
        } else if (!first_improved && !improved) {
          break;
        }
      }
      // A last two-sided pass, free to move each vertex to either side,
      // trims what the alternating one-sided passes leave (NestedDissectionOptions::polish_from).
      if (g_.n >= params_.polish_from) {
        active_[0] = active_[1] = true;
        one_pass();
      }
      return;
    }
    active_[0] = active_[1] = true;
    for (int32_t pass = 0; pass < params_.refine_passes; ++pass) {
      if (!one_pass()) break;
    }
  }

 private:
  Cost cost() const {
    const int64_t heavier = std::max(weight_[0], weight_[1]);
    return {std::max<int64_t>(0, heavier - max_side_), weight_[2], std::llabs(weight_[0] - weight_[1])};
  }
  int32_t gain(int32_t v, int side) const { return g_.vw[v] - r_.ext[2 * v + (1 - side)]; }

  // Sets v's neighbour weights per side and enters it in both heaps.
  void enter(int32_t v) {
    int32_t ext[3] = {0, 0, 0};
    for (int32_t p = g_.xadj[v]; p < g_.xadj[v + 1]; ++p) ext[where_[g_.adj[p]]] += g_.vw[g_.adj[p]];
    enter(v, ext);
  }
  // The same with v's neighbour weights per side already counted.
  void enter(int32_t v, const int32_t ext[3]) {
    r_.ext[2 * v] = ext[0];
    r_.ext[2 * v + 1] = ext[1];
    if (r_.locked[v]) return;
    for (int s = 0; s < 2; ++s) {
      if (active_[s]) heap_[s].push(v, gain(v, s));
    }
  }
  void change_ext(int32_t v, int side, int32_t delta) {
    r_.ext[2 * v + side] += delta;
    // ext[side] enters the gain of the move to the other side.
    if (heap_[1 - side].contains(v)) heap_[1 - side].update(v, gain(v, 1 - side));
  }

  // The side to move heap top to, or -1 when neither move is admissible.
  int choose_side() {
    heap_[0].settle();
    heap_[1].settle();
    bool ok[2];
    for (int s = 0; s < 2; ++s) {
      ok[s] = !heap_[s].empty() && weight_[s] + g_.vw[heap_[s].top()] <= max_side_;
    }
    if (ok[0] && ok[1]) {
      const int32_t g0 = heap_[0].key(heap_[0].top()), g1 = heap_[1].key(heap_[1].top());
      if (g0 != g1) return g0 > g1 ? 0 : 1;
      return weight_[0] <= weight_[1] ? 0 : 1;
    }
    if (ok[0]) return 0;
    if (ok[1]) return 1;
    return -1;
  }

  void move(int32_t v, int to) {
    const int other = 1 - to;
    if (heap_[0].contains(v)) heap_[0].remove(v);
    if (heap_[1].contains(v)) heap_[1].remove(v);
    r_.locked[v] = 1;
    r_.moved.push_back(v);
    where_[v] = static_cast<uint8_t>(to);
    weight_[2] -= g_.vw[v];
    weight_[to] += g_.vw[v];
    for (int32_t p = g_.xadj[v]; p < g_.xadj[v + 1]; ++p) {
      const int32_t u = g_.adj[p];
      if (where_[u] == kSeparator) {
        change_ext(u, to, g_.vw[v]);
      } else if (where_[u] == other) {
        // u enters the separator: it no longer counts on `other` for its separator neighbours.
        where_[u] = kSeparator;
        weight_[other] -= g_.vw[u];
        weight_[2] += g_.vw[u];
        r_.pulled.push_back(u);
        // One sweep of u's list counts u's neighbours per side and updates
        // its separator neighbours (g has no self loops: x != u).
        int32_t ext[3] = {0, 0, 0};
        for (int32_t q = g_.xadj[u]; q < g_.xadj[u + 1]; ++q) {
          const int32_t x = g_.adj[q];
          const uint8_t side = where_[x];
          ext[side] += g_.vw[x];
          if (side == kSeparator) change_ext(x, other, -g_.vw[u]);
        }
        enter(u, ext);
      }
    }
    r_.pulled_end.push_back(static_cast<int32_t>(r_.pulled.size()));
  }

  // Undoes the moves after the first `keep`.
  void undo_to(size_t keep) {
    for (size_t k = r_.moved.size(); k-- > keep;) {
      const int32_t v = r_.moved[k];
      const int to = where_[v];
      const int32_t begin = k == 0 ? 0 : r_.pulled_end[k - 1];
      for (int32_t i = begin; i < r_.pulled_end[k]; ++i) {
        const int32_t u = r_.pulled[i];
        where_[u] = static_cast<uint8_t>(1 - to);
        weight_[2] -= g_.vw[u];
        weight_[1 - to] += g_.vw[u];
      }
      where_[v] = kSeparator;
      weight_[to] -= g_.vw[v];
      weight_[2] += g_.vw[v];
    }
  }

  // The separator after a pass: the old one's vertices still in it and the
  // vertices the kept moves pulled in, each once (locked[] marks those
  // listed; every vertex is unlocked on entry and on exit). Their order does
  // not matter: a heap's top is the largest (gain, -vertex) whatever order
  // the vertices entered in.
  void update_separator() {
    std::vector<int32_t>& list = r_.separator;
    size_t kept = 0;
    for (int32_t v : list) {
      if (where_[v] == kSeparator && !r_.locked[v]) {
        r_.locked[v] = 1;
        list[kept++] = v;
      }
    }
    list.resize(kept);
    for (int32_t u : r_.pulled) {
      if (where_[u] == kSeparator && !r_.locked[u]) {
        r_.locked[u] = 1;
        list.push_back(u);
      }
    }
    for (int32_t v : list) r_.locked[v] = 0;
  }

  // Ends a pass: undoes the moves past the best state, unlocks, lists the
  // separator, empties the heaps.
  void finish_pass(size_t best_moves) {
    undo_to(best_moves);
    for (int32_t v : r_.moved) r_.locked[v] = 0;
    update_separator();
    r_.moved.clear();
    r_.pulled.clear();
    r_.pulled_end.clear();
    heap_[0].clear();
    heap_[1].clear();
  }

  // One pass that moves separator vertices into side `to` only, pulling
  // their neighbours on the other side into the separator (one-sided FM, as
  // METIS's node refinement does by default: a pass that only grows one side
  // keeps pushing the separator the same way, where a two-sided pass tends to
  // undo itself). A move that would make `to` too heavy ends the pass. It
  // gives up after `limit` moves without a new best while the separator is
  // over 10% above the best, or 3 * limit moves in any case.
  bool one_sided_pass(int to) {
    active_[to] = true;
    active_[1 - to] = false;
    for (int32_t v : r_.separator) enter(v);
    const size_t limit = std::min<size_t>(3 * r_.separator.size(), static_cast<size_t>(params_.refine_patience));
    const Cost start = cost();
    Cost best = start;
    size_t best_moves = 0;
    while (!heap_[to].empty()) {
      heap_[to].settle();
      const int32_t v = heap_[to].top();
      if (weight_[to] + g_.vw[v] > max_side_) break;
      move(v, to);
      const Cost now = cost();
      if (now < best) {
        best = now;
        best_moves = r_.moved.size();
      } else {
        const size_t since = r_.moved.size() - best_moves;
        if (since > 3 * limit || (since > limit && 10 * now.separator > 11 * best.separator)) break;
      }
    }
    finish_pass(best_moves);
    return best < start;
  }

  // One FM pass; true when it improved the separator. Costs O(separator +
  // the degrees of the vertices it touches), not O(n).
  bool one_pass() {
    for (int32_t v : r_.separator) enter(v);
    const Cost start = cost();
    Cost best = start;
    size_t best_moves = 0;
    for (;;) {
      const int to = choose_side();
      if (to < 0) break;
      move(heap_[to].top(), to);
      const Cost now = cost();
      if (now < best) {
        best = now;
        best_moves = r_.moved.size();
      } else if (r_.moved.size() - best_moves > patience_) {
        break;
      }
    }
    finish_pass(best_moves);
    return best < start;
  }

  const Graph& g_;
  const NestedDissectionOptions& params_;
  std::vector<uint8_t>& where_;
  const int64_t max_side_;
  const size_t patience_;  // moves without a new best before a pass gives up
  int64_t weight_[3];
  RefineWorkspace& r_;
  GainHeap heap_[2];  // separator vertices by gain of the move to side 0 / 1
  bool active_[2] = {true, true};  // which heaps the pass fills
};

}  // namespace

void refine_separator(const Graph& g, const NestedDissectionOptions& params, Workspace* ws,
                      std::vector<uint8_t>* where) {
  SeparatorRefiner(g, params, ws, where).run();
}

}  // namespace nd
}  // namespace gab
