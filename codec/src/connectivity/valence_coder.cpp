// The valence coder (valence_coder.h), encoder and decoder as twins over one
// set of active-list operations (ActiveLists): each side decides the event
// its own way (the encoder from the mesh, the decoder from the stream and
// the valences), then both apply it with the same calls.
//
// What each piece buys, measured on the shared meshes (nefertiti bytes;
// Touma & Gotsman's traversal, the focus moving to a neighbour after each
// CLOSE and valences coded as Elias-gamma bits in the context of two
// neighbours: 17,661):
//  * the adaptive focus with the valence of a new vertex in the context of
//    three known valences summed (focus, successor, predecessor), coded in
//    unary with a model per step: 14,671. SPLITs fall from 3,071 to about
//    110: their flags and offsets cost 2.9 KB with the neighbour rule, 0.3 KB
//    here;
//  * models whose rate follows a count (~1/(n+2), then 2^-7) instead of a
//    fixed 2^-5: 14,389 (1-2% on every mesh);
//  * among vertices with equally few free triangles, the one whose count
//    changed longest ago: 14,144 (the most recently changed: 14,444; the
//    first after the old focus: 14,389);
//  * the ADD, CLOSE and dummy flags' rates following a count too: 14,105
//    (about 40 bytes on every mesh).
// Tried and dropped: contexts of four valences (14,538), of twice the
// focus and successor plus the predecessor (14,400), of the pair (focus +
// successor, predecessor) (14,486); coding each valence late, as free
// triangles given those already conquered when its vertex becomes the
// focus (20% cheaper valences on the neighbour rule's traversal, but the adaptive
// focus then cannot see free counts: 14,924 at best).
//
// The focus queue: the vertices of each list in buckets by free triangles
// (FIFO within a bucket), one set of buckets per list. A SPLIT moves the
// smaller of its two parts into a new set, so all the moves cost
// O(n log n); a MERGE (a handle) moves the waiting list.
#include "connectivity/valence_coder.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>

#include "connectivity/active_lists.h"
#include "entropy/int_coder.h"

namespace gab {

namespace {

// The adaptation rate (BitModel::shift) of a model used n times before:
// about 1/(n + 2), as a count would give, down to 2^-7.
uint8_t counted_shift(uint8_t n) {
  return static_cast<uint8_t>(n < 2 ? 1 : n < 4 ? 2 : n < 8 ? 3 : n < 16 ? 4 : n < 32 ? 5 : n < 64 ? 6 : 7);
}

// Small counts (a valence minus 2, typically 1-6): one adaptive bit per
// unit ("more?") up to kCap, then the rest through a UIntCoder; per context
// an adaptive distribution over 0..kCap. A bit's model adapts at a rate
// that follows how often it was used (about 1/(n+2) at first, as a count
// would, then settling at 2^-7), so rare contexts learn fast and busy ones
// become precise.
class CountCoder {
 public:
  static constexpr uint32_t kCap = 16;
  explicit CountCoder(int contexts)
      : more_(static_cast<size_t>(contexts) * kCap), seen_(more_.size(), 0), rest_(1) {}
  void encode(RangeEncoder* enc, uint32_t value, int context) {
    const size_t base = static_cast<size_t>(context) * kCap;
    for (uint32_t i = 0; i < kCap; ++i) {
      enc->encode(model(base + i), value > i);
      if (value == i) return;
    }
    rest_.encode(enc, value - kCap);
  }
  uint32_t decode(RangeDecoder* dec, int context) {
    const size_t base = static_cast<size_t>(context) * kCap;
    for (uint32_t i = 0; i < kCap; ++i) {
      if (!dec->decode(model(base + i))) return i;
    }
    const uint32_t rest = rest_.decode(dec);
    return rest > UINT32_MAX - kCap ? UINT32_MAX : rest + kCap;
  }

 private:
  BitModel* model(size_t i) {
    const uint8_t n = seen_[i];
    more_[i].shift = counted_shift(n);
    if (n < 255) seen_[i] = static_cast<uint8_t>(n + 1);
    return &more_[i];
  }
  std::vector<BitModel> more_;
  std::vector<uint8_t> seen_;
  UIntCoder rest_;
};

// A bit whose model's rate follows a count, as CountCoder's.
class CountedBit {
 public:
  BitModel* model() {
    model_.shift = counted_shift(seen_);
    if (seen_ < 255) ++seen_;
    return &model_;
  }

 private:
  BitModel model_;
  uint8_t seen_ = 0;
};

// Valence contexts: the sum of the focus's, its successor's and its
// predecessor's valences (18 is regular), clamped to 12..30; then the seed
// triangle's vertices, then dummies (a boundary loop's length).
constexpr int kSumContexts = 19;
constexpr int kSeedContext = kSumContexts;
constexpr int kDummyContext = kSumContexts + 1;

int valence_context(int32_t sum, bool dummy) {
  if (dummy) return kDummyContext;
  return std::min(std::max(sum - 12, 0), kSumContexts - 1);
}

// Per vertex, both sides: valence, triangles not yet conquered around it,
// occurrences on the lists, dummy flag.
struct VertexState {
  std::vector<int32_t> degree, remaining, occurrences;
  std::vector<uint8_t> dummy;
  void reserve(size_t n) {
    degree.reserve(n);
    remaining.reserve(n);
    occurrences.reserve(n);
    dummy.reserve(n);
  }
};

// Nodes of the active lists in buckets by their vertex's free triangles,
// one set of buckets per list ("queue"); within a bucket, first in first
// out. A node is in at most one queue.
class FocusQueue {
 public:
  static constexpr int kBuckets = 16;  // free counts 0..15; more share the last

  void reserve(size_t nodes) { slot_.reserve(nodes); }
  int32_t new_queue() {
    std::array<int32_t, kBuckets> empty;
    empty.fill(-1);
    head_.push_back(empty);
    tail_.push_back(empty);
    return static_cast<int32_t>(head_.size()) - 1;
  }
  // Puts `node` last among `queue`'s nodes with `free` triangles (taking it
  // out of wherever it was).
  void put(int32_t node, int32_t queue, int32_t free) {
    if (static_cast<size_t>(node) >= slot_.size()) {
      // Straight to the reserved room, then doubling.
      slot_.resize(std::max({static_cast<size_t>(node) + 1, 2 * slot_.size(), slot_.capacity()}));
    }
    remove(node);
    const int32_t b = std::min(std::max(free, 0), kBuckets - 1);
    Slot& s = slot_[node];
    s.queue = queue;
    s.bucket = b;
    s.next = -1;
    s.prev = tail_[queue][b];
    if (s.prev >= 0) {
      slot_[s.prev].next = node;
    } else {
      head_[queue][b] = node;
    }
    tail_[queue][b] = node;
  }
  void remove(int32_t node) {
    if (static_cast<size_t>(node) >= slot_.size() || slot_[node].queue < 0) return;
    Slot& s = slot_[node];
    if (s.prev >= 0) {
      slot_[s.prev].next = s.next;
    } else {
      head_[s.queue][s.bucket] = s.next;
    }
    if (s.next >= 0) {
      slot_[s.next].prev = s.prev;
    } else {
      tail_[s.queue][s.bucket] = s.prev;
    }
    s.queue = -1;
  }
  int32_t queue_of(int32_t node) const { return slot_[node].queue; }
  // The node of `queue` with the fewest free triangles (the earliest put
  // among equals); -1 if the queue is empty. O(kBuckets).
  int32_t first(int32_t queue) const {
    for (int32_t node : head_[queue]) {
      if (node >= 0) return node;
    }
    return -1;
  }

 private:
  // Per node, in one place (a node's links, queue and bucket are read
  // together).
  struct Slot {
    int32_t next = -1, prev = -1, queue = -1, bucket = 0;
  };
  std::vector<Slot> slot_;
  std::vector<std::array<int32_t, kBuckets>> head_, tail_;
};

// The active lists with their focus queues: the list operations both sides
// apply, each followed by the queue's upkeep and, where the focus is done,
// the choice of the next one. Every call comes after the triangle's
// vertices' remaining counts were lowered.
struct Front {
  ActiveLists lists;
  FocusQueue queue;
  int32_t current = -1;          // the current list's queue
  std::vector<int32_t> waiting;  // per waiting list (as lists.stack)

  void reserve(size_t nodes) {
    lists.reserve(nodes);
    queue.reserve(nodes);
  }
  int32_t free_of(const VertexState& vs, int32_t node) const { return vs.remaining[lists.vertex[node]]; }
  void touch(const VertexState& vs, int32_t node) { queue.put(node, queue.queue_of(node), free_of(vs, node)); }
  void refocus() { lists.focus = queue.first(current); }

  void start(const VertexState& vs, int32_t a, int32_t b, int32_t c) {
    lists.start(a, b, c);
    current = queue.new_queue();
    for (int i = 0; i < 3; ++i) queue.put(lists.focus + i, current, free_of(vs, lists.focus + i));
  }
  // ADD, SPLIT, MERGE return the new node (w's occurrence after the focus's).
  int32_t add(const VertexState& vs, int32_t w) {
    const int32_t x = lists.add(w);
    queue.put(x, current, free_of(vs, x));
    touch(vs, lists.focus);
    touch(vs, lists.next[x]);
    return x;
  }
  // CLOSE: the focus leaves; the vertex with the fewest free triangles
  // becomes the focus.
  void close(const VertexState& vs) {
    const int32_t f = lists.focus;
    const int32_t p = lists.close();
    queue.remove(f);
    touch(vs, p);
    touch(vs, lists.next[p]);
    refocus();
  }
  void close_next(const VertexState& vs) {
    queue.remove(lists.next[lists.focus]);
    lists.close_next();
    touch(vs, lists.focus);
    touch(vs, lists.next[lists.focus]);
  }
  int32_t split(const VertexState& vs, int32_t m, int32_t offset) {
    const int32_t f = lists.focus, n1 = lists.next[f];
    const int32_t x = lists.split(m, offset);
    // The smaller part moves to a new queue: the waiting one (x, n1, ...,
    // offset nodes) or the current one (f, m, ...).
    const int32_t fresh = queue.new_queue();
    lists.walked += std::min(offset, lists.length);
    if (offset <= lists.length) {
      int32_t node = x;
      for (int32_t i = 0; i < offset; ++i, node = lists.next[node]) queue.put(node, fresh, free_of(vs, node));
      waiting.push_back(fresh);
    } else {
      int32_t node = f;
      for (int32_t i = 0; i < lists.length; ++i, node = lists.next[node]) queue.put(node, fresh, free_of(vs, node));
      queue.put(x, current, free_of(vs, x));
      waiting.push_back(current);
      current = fresh;
    }
    touch(vs, f);
    touch(vs, m);
    touch(vs, n1);
    return x;
  }
  int32_t merge(const VertexState& vs, int32_t m, size_t index) {
    lists.walked += lists.stack[index].length + static_cast<int64_t>(waiting.size() - index);
    int32_t node = m;
    for (int32_t i = 0; i < lists.stack[index].length; ++i, node = lists.next[node]) {
      queue.put(node, current, free_of(vs, node));
    }
    waiting.erase(waiting.begin() + static_cast<std::ptrdiff_t>(index));
    const int32_t x = lists.merge(m, index);
    queue.put(x, current, free_of(vs, x));
    touch(vs, lists.focus);
    touch(vs, lists.next[x]);
    return x;
  }
  // The current list (two nodes) is done: the next waiting one, if any,
  // becomes current.
  bool pop() {
    queue.remove(lists.next[lists.focus]);
    queue.remove(lists.focus);
    if (!lists.pop()) return false;
    current = waiting.back();
    waiting.pop_back();
    refocus();
    return true;
  }
};

// The adaptive statistics both sides keep, in the same state.
struct AdaptiveModels {
  AdaptiveModels();
  BitModel merge, split_backward, two_cycle, another_component;
  CountedBit close[4], add[4], dummy[2];
  CountCoder valence;
  UIntCoder split_offset, merge_list, merge_offset;
};

AdaptiveModels::AdaptiveModels()
    : merge(8), two_cycle(8), valence(kDummyContext + 1), split_offset(1), merge_list(1), merge_offset(1) {
}

enum class Event { kAdd, kClose, kCloseNext, kSplit, kMerge };

// U is the successor's last triangle.
bool closes_next(const ActiveLists& lists, const VertexState& vs, int32_t focus) {
  const int32_t n1 = lists.vertex[lists.next[focus]];
  return lists.length >= 3 && vs.occurrences[n1] == 1 && vs.remaining[n1] == 1;
}

// The valence sum around the gap where a new vertex enters.
int32_t neighbour_sum(const ActiveLists& lists, const VertexState& vs) {
  const int32_t f = lists.focus;
  return vs.degree[lists.vertex[f]] + vs.degree[lists.vertex[lists.next[f]]] + vs.degree[lists.vertex[lists.prev[f]]];
}

}  // namespace

int64_t encode_valences(const ClosedMesh& mesh, RangeEncoder* enc, std::vector<int32_t>* order) {
  AdaptiveModels models;
  const int32_t halves = static_cast<int32_t>(mesh.triangles.size());
  const int32_t n = mesh.num_vertices;
  // Mesh vertices are renumbered as the decoder meets them (number[v]),
  // so the state and the lists are the decoder's.
  std::vector<int32_t> valence(static_cast<size_t>(n), 0), number(static_cast<size_t>(n), -1);
  for (int32_t v : mesh.triangles) ++valence[v];
  VertexState vs;
  vs.reserve(static_cast<size_t>(n));
  std::vector<uint8_t> conquered(static_cast<size_t>(halves / 3), 0);
  order->clear();
  order->reserve(static_cast<size_t>(n));

  // Encoder-only node data: the conquered triangle's half-edge each node
  // stands for (node -> its vertex to the next node's) and the reverse map
  // for boundary half-edges.
  Front front;
  front.reserve(static_cast<size_t>(n));
  ActiveLists& lists = front.lists;
  std::vector<int32_t> half(static_cast<size_t>(n), -1), node_of_half(static_cast<size_t>(halves), -1);
  auto set_half = [&](int32_t node, int32_t h) {
    if (static_cast<size_t>(node) >= half.size()) {
      half.resize(std::max(static_cast<size_t>(node) + 1, 2 * half.size()), -1);
    }
    half[node] = h;
    node_of_half[h] = node;
  };
  auto code_new_vertex = [&](int32_t w, int context, bool focus_dummy) {
    enc->encode(models.dummy[focus_dummy ? 1 : 0].model(), mesh.dummy[w]);
    models.valence.encode(enc, static_cast<uint32_t>(valence[w] - 2), mesh.dummy[w] ? kDummyContext : context);
    number[w] = static_cast<int32_t>(order->size());
    order->push_back(w);
    vs.degree.push_back(valence[w]);
    vs.remaining.push_back(valence[w]);
    vs.occurrences.push_back(1);
    vs.dummy.push_back(mesh.dummy[w]);
    return number[w];
  };

  // Components one after the other, each seeded at its first triangle; a
  // bit before each says whether one follows (the mesh may have none).
  for (int32_t s = 0;; ++s) {
    while (s < halves / 3 && conquered[s]) ++s;
    enc->encode(&models.another_component, s < halves / 3);
    if (s == halves / 3) break;
    int32_t seed[3];
    for (int i = 0; i < 3; ++i) seed[i] = code_new_vertex(mesh.triangles[3 * s + i], kSeedContext, false);
    conquered[s] = 1;
    for (int32_t k : seed) --vs.remaining[k];
    front.start(vs, seed[0], seed[1], seed[2]);
    for (int i = 0; i < 3; ++i) set_half(lists.focus + i, 3 * s + i);
    for (;;) {
      const int32_t f = lists.focus;
      const int32_t kf = lists.vertex[f];
      if (lists.length == 2) {
        const int32_t kg = lists.vertex[lists.next[f]];
        const bool closed = conquered[mesh.opposite[half[f]] / 3] != 0;
        if (vs.occurrences[kf] > 1 && vs.occurrences[kg] > 1) enc->encode(&models.two_cycle, closed);
        if (closed) {
          --vs.occurrences[kf];
          --vs.occurrences[kg];
          if (!front.pop()) break;
          continue;
        }
      }
      const int32_t across = mesh.opposite[half[f]];  // in U, from next(focus) to the focus
      const int32_t u = across / 3;
      const int32_t w = mesh.triangles[prev_corner(across)];
      const int32_t kn1 = lists.vertex[lists.next[f]];
      // The occurrence of w whose gap holds U.
      int32_t m = -1;
      if (number[w] >= 0) {
        int32_t k = prev_corner(across), h = mesh.opposite[k];
        while (!conquered[h / 3]) {
          k = next_corner(h);
          h = mesh.opposite[k];
        }
        m = lists.next[node_of_half[h]];
      }
      const bool closes = m >= 0 && conquered[mesh.opposite[next_corner(across)] / 3];
      const Event event = m < 0                                      ? Event::kAdd
                          : closes                                   ? Event::kClose
                          : closes_next(lists, vs, f)                ? Event::kCloseNext
                          : front.queue.queue_of(m) == front.current ? Event::kSplit
                                                                     : Event::kMerge;
      const int context = std::min(vs.remaining[kf], 4) - 1;
      if (vs.occurrences[kf] > 1) enc->encode(models.close[context].model(), event == Event::kClose);
      if (event != Event::kClose && event != Event::kCloseNext) {
        enc->encode(models.add[context].model(), event == Event::kAdd);
      }
      conquered[u] = 1;
      if (event == Event::kClose) {
        for (int32_t k : {kf, kn1, number[w]}) --vs.remaining[k];
        --vs.occurrences[kf];
        const int32_t p = lists.prev[f];
        front.close(vs);
        set_half(p, prev_corner(across));  // the predecessor now runs to next(focus)
        continue;
      }
      set_half(f, next_corner(across));  // the focus now runs to w
      if (event == Event::kCloseNext) {
        for (int32_t k : {kf, kn1, number[w]}) --vs.remaining[k];
        --vs.occurrences[kn1];
        front.close_next(vs);
        continue;
      }
      int32_t x;
      if (event == Event::kAdd) {
        const int32_t kw = code_new_vertex(w, valence_context(neighbour_sum(lists, vs), false), vs.dummy[kf] != 0);
        for (int32_t k : {kf, kn1, kw}) --vs.remaining[k];
        x = front.add(vs, kw);
      } else if (event == Event::kSplit) {
        enc->encode(&models.merge, 0);
        const int32_t kw = number[w];
        ++vs.occurrences[kw];
        int32_t offset = 0;
        for (int32_t node = f; node != m; node = lists.next[node]) ++offset;
        front.lists.walked += offset;
        // The nearer way round: splits are mostly local.
        const bool backward = lists.length - offset < offset;
        enc->encode(&models.split_backward, backward);
        models.split_offset.encode(enc, static_cast<uint32_t>(backward ? lists.length - offset - 1 : offset - 2));
        for (int32_t k : {kf, kn1, kw}) --vs.remaining[k];
        x = front.split(vs, m, offset);
      } else {
        enc->encode(&models.merge, 1);
        const int32_t kw = number[w];
        ++vs.occurrences[kw];
        const size_t index = static_cast<size_t>(
            std::find(front.waiting.begin(), front.waiting.end(), front.queue.queue_of(m)) - front.waiting.begin());
        models.merge_list.encode(enc, static_cast<uint32_t>(front.waiting.size() - 1 - index));
        int32_t offset = 0;
        for (int32_t node = lists.stack[index].head; node != m; node = lists.next[node]) ++offset;
        front.lists.walked += offset;
        models.merge_offset.encode(enc, static_cast<uint32_t>(offset));
        for (int32_t k : {kf, kn1, kw}) --vs.remaining[k];
        x = front.merge(vs, m, index);
      }
      set_half(x, prev_corner(across));  // w's new occurrence runs to next(focus)
    }
  }
  return front.lists.walked;
}

Status decode_valences(RangeDecoder* dec, int32_t max_vertices, int64_t max_triangles,
                                DecodedConnectivity* out, int64_t expected_triangles) {
  auto corrupt = [](const std::string& what) {
    return Status::Error(StatusCode::kParseError, "connectivity: " + what);
  };
  const int64_t budget = walk_budget(max_triangles);
  AdaptiveModels models;
  VertexState vs;
  out->num_vertices = 0;
  out->triangles.clear();
  out->dummy.clear();
  const int64_t max_valence = std::min<int64_t>(3 * max_triangles, INT32_MAX);

  auto new_vertex = [&](int context, bool focus_dummy, int32_t* v) {
    if (out->num_vertices >= max_vertices) return corrupt("more vertices than the header says");
    const bool dummy = dec->decode(models.dummy[focus_dummy ? 1 : 0].model()) != 0;
    const uint32_t valence = models.valence.decode(dec, dummy ? kDummyContext : context);
    if (static_cast<int64_t>(valence) + 2 > max_valence) return corrupt("valence out of range");
    *v = out->num_vertices++;
    vs.degree.push_back(static_cast<int32_t>(valence) + 2);
    vs.remaining.push_back(static_cast<int32_t>(valence) + 2);
    vs.occurrences.push_back(1);
    vs.dummy.push_back(dummy ? 1 : 0);
    out->dummy.push_back(dummy ? 1 : 0);
    return Status::Ok();
  };
  auto conquer = [&](int32_t a, int32_t b, int32_t c) {
    if (static_cast<int64_t>(out->triangles.size() / 3) >= max_triangles) {
      return corrupt("more triangles than the header says");
    }
    for (int32_t v : {a, b, c}) {
      if (--vs.remaining[v] < 0) return corrupt("vertex " + std::to_string(v) + " exceeds its valence");
    }
    out->triangles.push_back(a);
    out->triangles.push_back(b);
    out->triangles.push_back(c);
    return Status::Ok();
  };

  Front front;
  ActiveLists& lists = front.lists;
  // The header's counts size the arrays up front: grown by doubling, each
  // was copied and faulted in about twice over (igea: a fifth of the
  // connectivity's decoding time went to reallocations and page faults).
  // A list node stands for one vertex, but for a few per component and
  // split. Capped by the stream's size, so that a forged header reserves
  // little: real streams hold 5-10 vertices a byte (a regular grid up to
  // ~700), and past the cap the arrays grow as the vertices decode.
  // With the triangles expected, about half as many vertices and a
  // sixteenth more for the cut's copies and dummies: reserving for the
  // bounds (n + 4t vertices) took igea's decode 20-50 MB of heap more, and
  // its peak from 35 to 56 MB.
  constexpr int64_t kReservedPerByte = 64;
  const int64_t cap = kReservedPerByte * static_cast<int64_t>(dec->size()) + 1024;
  int64_t triangles_wanted = max_triangles, vertices_wanted = max_vertices;
  if (expected_triangles >= 0) {
    triangles_wanted = std::min(max_triangles, expected_triangles + expected_triangles / 16 + 64);
    vertices_wanted = std::min<int64_t>(max_vertices, triangles_wanted / 2 + 64);
  }
  const size_t vertices = static_cast<size_t>(std::min(vertices_wanted, cap));
  vs.reserve(vertices);
  out->dummy.reserve(vertices);
  out->triangles.reserve(3 * static_cast<size_t>(std::min<int64_t>(triangles_wanted, 2 * cap)));
  front.reserve(vertices + vertices / 16 + 64);
  // Each component conquers a triangle, so the header's count bounds them.
  while (dec->decode(&models.another_component)) {
    if (dec->overrun()) return corrupt("stream truncated");
    int32_t seed[3];
    for (int32_t& v : seed) GAB_RETURN_IF_ERROR(new_vertex(kSeedContext, false, &v));
    GAB_RETURN_IF_ERROR(conquer(seed[0], seed[1], seed[2]));
    front.start(vs, seed[0], seed[1], seed[2]);
    for (;;) {
      if (dec->overrun()) return corrupt("stream truncated");
      const int32_t f = lists.focus;
      const int32_t vf = lists.vertex[f];
      if (lists.length == 2) {
        const int32_t vg = lists.vertex[lists.next[f]];
        bool closed;
        if (vs.occurrences[vf] == 1) {
          closed = vs.remaining[vf] == 0;
        } else if (vs.occurrences[vg] == 1) {
          closed = vs.remaining[vg] == 0;
        } else {
          closed = dec->decode(&models.two_cycle) != 0;
        }
        if (closed) {
          --vs.occurrences[vf];
          --vs.occurrences[vg];
          if (!front.pop()) break;
          continue;
        }
      }
      if (vs.remaining[vf] < 1) return corrupt("a closed vertex is the focus");
      const int32_t n1 = lists.vertex[lists.next[f]];
      const int context = std::min(vs.remaining[vf], 4) - 1;
      const bool close = vs.occurrences[vf] > 1 ? dec->decode(models.close[context].model()) != 0
                                                : vs.remaining[vf] == 1;
      if (close) {
        if (lists.length < 3) return corrupt("a two-vertex boundary cannot close a triangle");
        GAB_RETURN_IF_ERROR(conquer(vf, lists.vertex[lists.prev[f]], n1));
        --vs.occurrences[vf];
        front.close(vs);
        continue;
      }
      if (closes_next(lists, vs, f)) {
        if (lists.length < 3) return corrupt("a two-vertex boundary cannot close a triangle");
        GAB_RETURN_IF_ERROR(conquer(vf, lists.vertex[lists.next[lists.next[f]]], n1));
        --vs.occurrences[n1];
        front.close_next(vs);
        continue;
      }
      if (dec->decode(models.add[context].model())) {
        int32_t w;
        GAB_RETURN_IF_ERROR(new_vertex(valence_context(neighbour_sum(lists, vs), false), vs.dummy[vf] != 0, &w));
        GAB_RETURN_IF_ERROR(conquer(vf, w, n1));
        front.add(vs, w);
      } else if (!dec->decode(&models.merge)) {
        const bool backward = dec->decode(&models.split_backward) != 0;
        const uint32_t distance = models.split_offset.decode(dec);
        if (lists.length < 3 || distance > static_cast<uint32_t>(lists.length - 3)) {
          return corrupt("split offset out of range");
        }
        const uint32_t offset = backward ? static_cast<uint32_t>(lists.length) - 1 - distance : distance + 2;
        // Walk the way the encoder counted: `distance` steps, not `offset`.
        const int32_t m = backward ? lists.retreat(lists.prev[f], static_cast<int32_t>(distance))
                                   : lists.advance(f, static_cast<int32_t>(offset));
        const int32_t w = lists.vertex[m];
        if (w == vf || w == n1) return corrupt("a triangle repeats a vertex");
        ++vs.occurrences[w];
        GAB_RETURN_IF_ERROR(conquer(vf, w, n1));
        front.split(vs, m, static_cast<int32_t>(offset));
        if (lists.walked > budget) return corrupt("splits walk more than " + std::to_string(budget) + " list steps");
      } else {
        const uint32_t back = models.merge_list.decode(dec);
        if (back >= lists.stack.size()) return corrupt("merge names a list that does not exist");
        const size_t index = lists.stack.size() - 1 - back;
        const uint32_t offset = models.merge_offset.decode(dec);
        if (offset >= static_cast<uint32_t>(lists.stack[index].length)) return corrupt("merge offset out of range");
        const int32_t m = lists.advance(lists.stack[index].head, static_cast<int32_t>(offset));
        const int32_t w = lists.vertex[m];
        if (w == vf || w == n1) return corrupt("a triangle repeats a vertex");
        ++vs.occurrences[w];
        GAB_RETURN_IF_ERROR(conquer(vf, w, n1));
        front.merge(vs, m, index);
        if (lists.walked > budget) return corrupt("merges walk more than " + std::to_string(budget) + " list steps");
      }
    }
  }
  if (dec->overrun()) return corrupt("stream truncated");
  for (int32_t v = 0; v < out->num_vertices; ++v) {
    if (vs.remaining[v] != 0) return corrupt("vertex " + std::to_string(v) + " falls short of its valence");
  }
  return Status::Ok();
}

}  // namespace gab
