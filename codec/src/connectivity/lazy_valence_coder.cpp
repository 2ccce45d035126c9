// Version 2 of the valence coder: Touma & Gotsman's traversal (version 1,
// valence_coder.cpp) with each valence coded when the decoder first needs
// it rather than when its vertex is met.
//
// Why late: when a vertex is met (ADD) the decoder knows two of its
// neighbours, and a valence coded then costs about its order-0 entropy.
// When it becomes the focus, part of its fan is conquered, and the number
// of conquered triangles ("used") is strongly tied to the valence: the
// traversal's growing front wraps further around a vertex of high valence.
// Coding free = valence - used given used costs 13-15% less than the
// valence given its two neighbours (nefertiti: 12.4 against 14.2 KB).
//
// The price: before a vertex becomes the focus, the traversal may ask
// whether the focus's triangle is the successor's last (CLOSE_NEXT, implied
// in version 1 by the successor's valence). For a successor whose valence is
// not yet coded this is one coded bit, nearly always 0 (about 1.2 KB on
// nefertiti in all); a 1 fixes the valence (used + 1).
//
// Everything else (CLOSE, SPLIT with its nearer-way offset, MERGE, the
// two-vertex lists, the order of the vertices) is version 1's, and the two
// sides decide it from the same state: which valences are known, the
// triangles used around each vertex, and the lists.
#include "connectivity/lazy_valence_coder.h"

#include <algorithm>
#include <cstdint>
#include <string>

#include "connectivity/active_lists.h"
#include "entropy/int_coder.h"

namespace gab {

namespace {

// Small counts (free triangles, typically 1-6) in the context of the used
// count: one adaptive bit per unit ("more?") up to kCap, then the rest
// through a UIntCoder. Per context this is an adaptive distribution over
// 0..kCap, without the mantissa bits an Elias-gamma code would mix across
// values (3% of the valence bytes on nefertiti).
class CountCoder {
 public:
  static constexpr uint32_t kCap = 16;
  explicit CountCoder(int contexts) : more_(static_cast<size_t>(contexts) * kCap, BitModel(5)), rest_(1) {}
  void encode(RangeEncoder* enc, uint32_t value, int context) {
    BitModel* more = &more_[static_cast<size_t>(context) * kCap];
    for (uint32_t i = 0; i < kCap; ++i) {
      enc->encode(&more[i], value > i);
      if (value == i) return;
    }
    rest_.encode(enc, value - kCap);
  }
  uint32_t decode(RangeDecoder* dec, int context) {
    BitModel* more = &more_[static_cast<size_t>(context) * kCap];
    for (uint32_t i = 0; i < kCap; ++i) {
      if (!dec->decode(&more[i])) return i;
    }
    const uint32_t rest = rest_.decode(dec);
    return rest > UINT32_MAX - kCap ? UINT32_MAX : rest + kCap;
  }

 private:
  std::vector<BitModel> more_;
  UIntCoder rest_;
};

// Contexts: the used count (0..kUsedContexts-1, clamped), separately for
// dummies (whose valence is a boundary loop's length).
constexpr int kUsedContexts = 10;

int used_context(int32_t used, bool dummy) {
  return std::min(used, kUsedContexts - 1) + (dummy ? kUsedContexts : 0);
}

// Per vertex, both sides: the valence once coded (-1 before), triangles
// conquered around it, occurrences on the lists, dummy flag.
struct LazyState {
  std::vector<int32_t> degree, used, occurrences;
  std::vector<uint8_t> dummy;

  bool known(int32_t v) const { return degree[v] >= 0; }
  int32_t remaining(int32_t v) const { return degree[v] - used[v]; }
  int32_t add_vertex(bool is_dummy) {
    degree.push_back(-1);
    used.push_back(0);
    occurrences.push_back(1);
    dummy.push_back(is_dummy ? 1 : 0);
    return static_cast<int32_t>(degree.size()) - 1;
  }
};

// How many free triangles the traversal expects around v: the known count,
// else a guess from a typical valence of 6.
int32_t expected_free(const LazyState& state, int32_t v) {
  return state.known(v) ? state.remaining(v) : std::max(1, 6 - state.used[v]);
}

// After a CLOSE the focus moves to the predecessor unless the successor
// expects fewer free triangles (version 1's rule, on what both sides know).
void refocus_after_close(ActiveLists* lists, const LazyState& state) {
  const int32_t n1 = lists->next[lists->focus];
  if (expected_free(state, lists->vertex[n1]) < expected_free(state, lists->vertex[lists->focus])) lists->focus = n1;
}

// The decoder needs the successor's valence to know whether the focus's
// triangle is its last; when not yet coded, a bit says so.
bool asks_next_full(const ActiveLists& lists, const LazyState& state, int32_t n1) {
  return lists.length >= 3 && state.occurrences[n1] == 1 && !state.known(n1);
}

// The focus's triangle is the successor's last (known valence).
bool next_full(const ActiveLists& lists, const LazyState& state, int32_t n1) {
  return lists.length >= 3 && state.occurrences[n1] == 1 && state.known(n1) && state.remaining(n1) == 1;
}

// A two-vertex list f -> g -> f: whether its two edges are glued (the
// region closes) follows from a vertex on the lists once with a known
// valence; otherwise it is coded.
bool two_cycle_implied(const LazyState& state, int32_t vf, int32_t vg, bool* closed) {
  for (int32_t v : {vf, vg}) {
    if (state.occurrences[v] == 1 && state.known(v)) {
      *closed = state.remaining(v) == 0;
      return true;
    }
  }
  return false;
}

struct LazyModels {
  LazyModels();
  BitModel close[4], add[4], merge, split_backward, dummy[2], two_cycle, next_full[2 * kUsedContexts];
  CountCoder free_count;
  UIntCoder split_offset, merge_list, merge_offset, components;
};

LazyModels::LazyModels()
    : merge(8), two_cycle(8), free_count(2 * kUsedContexts), split_offset(1), merge_list(1), merge_offset(1),
      components(1) {
  for (BitModel& m : close) m = BitModel(6);
  for (BitModel& m : add) m = BitModel(7);
  for (BitModel& m : dummy) m = BitModel(7);
  for (BitModel& m : next_full) m = BitModel(6);
}

enum class Event { kAdd, kClose, kCloseNext, kSplit, kMerge };

}  // namespace

void encode_lazy_valences(const ClosedMesh& mesh, RangeEncoder* enc, std::vector<int32_t>* order) {
  LazyModels models;
  const int32_t halves = static_cast<int32_t>(mesh.triangles.size());
  const int32_t n = mesh.num_vertices;
  std::vector<int32_t> valence(static_cast<size_t>(n), 0);
  for (int32_t v : mesh.triangles) ++valence[v];
  // The state is kept in the decoder's numbering (k = order position);
  // number[v] maps a mesh vertex to it (-1 before it is met).
  LazyState state;
  std::vector<int32_t> number(static_cast<size_t>(n), -1);
  std::vector<uint8_t> conquered(static_cast<size_t>(halves / 3), 0);
  order->clear();

  int32_t components = 0;
  {
    std::vector<uint8_t> seen(static_cast<size_t>(halves / 3), 0);
    std::vector<int32_t> queue;
    for (int32_t t = 0; t < halves / 3; ++t) {
      if (seen[t]) continue;
      ++components;
      seen[t] = 1;
      queue.assign(1, t);
      while (!queue.empty()) {
        const int32_t u = queue.back();
        queue.pop_back();
        for (int i = 0; i < 3; ++i) {
          const int32_t o = mesh.opposite[3 * u + i] / 3;
          if (!seen[o]) {
            seen[o] = 1;
            queue.push_back(o);
          }
        }
      }
    }
  }
  models.components.encode(enc, static_cast<uint32_t>(components));

  // Encoder-only node data, as in version 1: the half-edge each node stands
  // for, the reverse map, and which cycle holds the node.
  ActiveLists lists;
  std::vector<int32_t> half, list_of, node_of_half(static_cast<size_t>(halves), -1), stack_ids;
  int32_t current = 0, next_id = 1;
  auto grow = [&](int32_t node) {
    if (static_cast<size_t>(node) >= half.size()) {
      half.resize(static_cast<size_t>(node) + 1, -1);
      list_of.resize(static_cast<size_t>(node) + 1, -1);
    }
  };
  auto set_half = [&](int32_t node, int32_t h) {
    grow(node);
    half[node] = h;
    node_of_half[h] = node;
  };
  auto label = [&](int32_t node, int32_t id) {
    grow(node);
    list_of[node] = id;
  };
  // The lists hold decoder numbers; half-edges lead to mesh vertices.
  auto code_new_vertex = [&](int32_t w, bool focus_dummy) {
    enc->encode(&models.dummy[focus_dummy ? 1 : 0], mesh.dummy[w]);
    number[w] = state.add_vertex(mesh.dummy[w] != 0);
    order->push_back(w);
    return number[w];
  };
  auto reveal = [&](int32_t k) { state.degree[k] = valence[(*order)[k]]; };

  int32_t seed_scan = 0;
  for (int32_t component = 0; component < components; ++component) {
    while (conquered[seed_scan]) ++seed_scan;
    const int32_t s = seed_scan;
    int32_t seed[3];
    for (int i = 0; i < 3; ++i) seed[i] = code_new_vertex(mesh.triangles[3 * s + i], false);
    conquered[s] = 1;
    for (int32_t k : seed) ++state.used[k];
    lists.start(seed[0], seed[1], seed[2]);
    for (int i = 0; i < 3; ++i) {
      set_half(lists.focus + i, 3 * s + i);
      label(lists.focus + i, current);
    }
    for (;;) {
      const int32_t f = lists.focus;
      const int32_t kf = lists.vertex[f];
      if (lists.length == 2) {
        const int32_t kg = lists.vertex[lists.next[f]];
        const bool closed = conquered[mesh.opposite[half[f]] / 3] != 0;
        bool implied;
        if (!two_cycle_implied(state, kf, kg, &implied)) enc->encode(&models.two_cycle, closed);
        if (closed) {
          --state.occurrences[kf];
          --state.occurrences[kg];
          if (!lists.pop()) break;
          current = stack_ids.back();
          stack_ids.pop_back();
          continue;
        }
      }
      if (!state.known(kf)) {
        const int32_t free = valence[(*order)[kf]] - state.used[kf];
        models.free_count.encode(enc, static_cast<uint32_t>(free - 1), used_context(state.used[kf], state.dummy[kf]));
        reveal(kf);
      }
      const int32_t across = mesh.opposite[half[f]];  // in U, from next(focus) to the focus
      const int32_t u = across / 3;
      const int32_t w = mesh.triangles[prev_corner(across)];
      const int32_t kn1 = lists.vertex[lists.next[f]];
      // The occurrence of w whose gap holds U (version 1's walk).
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
      // U is the successor's last triangle (the decoder learns it from the
      // successor's valence or from a bit).
      const bool last_of_next = lists.length >= 3 && state.occurrences[kn1] == 1 &&
                                valence[(*order)[kn1]] - state.used[kn1] == 1;
      const Event event = m < 0                   ? Event::kAdd
                          : closes                ? Event::kClose
                          : last_of_next          ? Event::kCloseNext
                          : list_of[m] == current ? Event::kSplit
                                                  : Event::kMerge;
      const int context = std::min(state.remaining(kf), 4) - 1;
      if (state.occurrences[kf] > 1) enc->encode(&models.close[context], event == Event::kClose);
      if (event != Event::kClose && asks_next_full(lists, state, kn1)) {
        enc->encode(&models.next_full[used_context(state.used[kn1], state.dummy[kn1])], event == Event::kCloseNext);
        if (event == Event::kCloseNext) reveal(kn1);
      }
      if (event != Event::kClose && event != Event::kCloseNext) {
        enc->encode(&models.add[context], event == Event::kAdd);
      }
      conquered[u] = 1;
      ++state.used[kf];
      ++state.used[kn1];
      if (number[w] >= 0) ++state.used[number[w]];
      if (event == Event::kClose) {
        --state.occurrences[kf];
        set_half(lists.close(), prev_corner(across));  // the predecessor now runs to next(focus)
        refocus_after_close(&lists, state);
        continue;
      }
      set_half(f, next_corner(across));  // the focus now runs to w
      if (event == Event::kCloseNext) {
        --state.occurrences[kn1];
        lists.close_next();
        continue;
      }
      int32_t x;
      if (event == Event::kAdd) {
        const int32_t kw = code_new_vertex(w, state.dummy[kf] != 0);
        ++state.used[kw];
        x = lists.add(kw);
        label(x, current);
      } else if (event == Event::kSplit) {
        enc->encode(&models.merge, 0);
        ++state.occurrences[number[w]];
        int32_t offset = 0;
        for (int32_t node = f; node != m; node = lists.next[node]) ++offset;
        const bool backward = lists.length - offset < offset;
        enc->encode(&models.split_backward, backward);
        models.split_offset.encode(enc, static_cast<uint32_t>(backward ? lists.length - offset - 1 : offset - 2));
        x = lists.split(m, offset);
        const int32_t id = next_id++;
        int32_t node = x;
        do {
          label(node, id);
          node = lists.next[node];
        } while (node != x);
        stack_ids.push_back(id);
      } else {
        enc->encode(&models.merge, 1);
        ++state.occurrences[number[w]];
        const size_t index =
            static_cast<size_t>(std::find(stack_ids.begin(), stack_ids.end(), list_of[m]) - stack_ids.begin());
        models.merge_list.encode(enc, static_cast<uint32_t>(stack_ids.size() - 1 - index));
        int32_t offset = 0;
        for (int32_t node = lists.stack[index].head; node != m; node = lists.next[node]) ++offset;
        models.merge_offset.encode(enc, static_cast<uint32_t>(offset));
        for (int32_t node = m, i = 0; i < lists.stack[index].length; ++i, node = lists.next[node]) {
          label(node, current);
        }
        stack_ids.erase(stack_ids.begin() + static_cast<std::ptrdiff_t>(index));
        x = lists.merge(m, index);
        label(x, current);
      }
      set_half(x, prev_corner(across));  // w's new occurrence runs to next(focus)
    }
  }
}

Status decode_lazy_valences(RangeDecoder* dec, int32_t max_vertices, int64_t max_triangles, DecodedConnectivity* out) {
  auto corrupt = [](const std::string& what) {
    return Status::Error(StatusCode::kParseError, "connectivity: " + what);
  };
  LazyModels models;
  LazyState state;
  out->num_vertices = 0;
  out->triangles.clear();
  out->dummy.clear();
  const uint32_t components = models.components.decode(dec);
  if (components > static_cast<uint32_t>(max_triangles)) return corrupt("component count out of range");

  auto new_vertex = [&](bool focus_dummy, int32_t* v) {
    if (out->num_vertices >= max_vertices) return corrupt("more vertices than the header says");
    const bool dummy = dec->decode(&models.dummy[focus_dummy ? 1 : 0]) != 0;
    *v = state.add_vertex(dummy);
    out->num_vertices = *v + 1;
    out->dummy.push_back(dummy ? 1 : 0);
    return Status::Ok();
  };
  auto conquer = [&](int32_t a, int32_t b, int32_t c) {
    if (static_cast<int64_t>(out->triangles.size() / 3) >= max_triangles) {
      return corrupt("more triangles than the header says");
    }
    for (int32_t v : {a, b, c}) {
      if (++state.used[v] > state.degree[v] && state.known(v)) {
        return corrupt("vertex " + std::to_string(v) + " exceeds its valence");
      }
    }
    out->triangles.insert(out->triangles.end(), {a, b, c});
    return Status::Ok();
  };

  ActiveLists lists;
  for (uint32_t component = 0; component < components; ++component) {
    int32_t seed[3];
    for (int32_t& v : seed) GAB_RETURN_IF_ERROR(new_vertex(false, &v));
    GAB_RETURN_IF_ERROR(conquer(seed[0], seed[1], seed[2]));
    lists.start(seed[0], seed[1], seed[2]);
    for (;;) {
      if (dec->overrun()) return corrupt("stream truncated");
      const int32_t f = lists.focus;
      const int32_t vf = lists.vertex[f];
      if (lists.length == 2) {
        const int32_t vg = lists.vertex[lists.next[f]];
        bool closed;
        if (!two_cycle_implied(state, vf, vg, &closed)) closed = dec->decode(&models.two_cycle) != 0;
        if (closed) {
          --state.occurrences[vf];
          --state.occurrences[vg];
          if (!lists.pop()) break;
          continue;
        }
      }
      if (!state.known(vf)) {
        const uint32_t free = models.free_count.decode(dec, used_context(state.used[vf], state.dummy[vf]));
        const int64_t degree = static_cast<int64_t>(state.used[vf]) + 1 + free;
        if (degree > std::min<int64_t>(3 * max_triangles, INT32_MAX)) return corrupt("valence out of range");
        state.degree[vf] = static_cast<int32_t>(degree);
      }
      if (state.remaining(vf) < 1) return corrupt("a closed vertex is the focus");
      const int32_t n1 = lists.vertex[lists.next[f]];
      const int context = std::min(state.remaining(vf), 4) - 1;
      const bool close = state.occurrences[vf] > 1 ? dec->decode(&models.close[context]) != 0
                                                   : state.remaining(vf) == 1;
      if (close) {
        if (lists.length < 3) return corrupt("a two-vertex boundary cannot close a triangle");
        GAB_RETURN_IF_ERROR(conquer(vf, lists.vertex[lists.prev[f]], n1));
        --state.occurrences[vf];
        lists.close();
        refocus_after_close(&lists, state);
        continue;
      }
      bool closes_next = next_full(lists, state, n1);
      if (asks_next_full(lists, state, n1) &&
          dec->decode(&models.next_full[used_context(state.used[n1], state.dummy[n1])])) {
        state.degree[n1] = state.used[n1] + 1;
        closes_next = true;
      }
      if (closes_next) {
        GAB_RETURN_IF_ERROR(conquer(vf, lists.vertex[lists.next[lists.next[f]]], n1));
        --state.occurrences[n1];
        lists.close_next();
        continue;
      }
      int32_t w = -1;
      if (dec->decode(&models.add[context])) {
        GAB_RETURN_IF_ERROR(new_vertex(state.dummy[vf] != 0, &w));
        lists.add(w);
      } else if (!dec->decode(&models.merge)) {
        const bool backward = dec->decode(&models.split_backward) != 0;
        const uint32_t distance = models.split_offset.decode(dec);
        if (distance > static_cast<uint32_t>(lists.length - 3)) return corrupt("split offset out of range");
        const uint32_t offset = backward ? static_cast<uint32_t>(lists.length) - 1 - distance : distance + 2;
        const int32_t m = backward ? lists.retreat(lists.prev[f], static_cast<int32_t>(distance))
                                   : lists.advance(f, static_cast<int32_t>(offset));
        w = lists.vertex[m];
        ++state.occurrences[w];
        lists.split(m, static_cast<int32_t>(offset));
      } else {
        const uint32_t back = models.merge_list.decode(dec);
        if (back >= lists.stack.size()) return corrupt("merge names a list that does not exist");
        const size_t index = lists.stack.size() - 1 - back;
        const uint32_t offset = models.merge_offset.decode(dec);
        if (offset >= static_cast<uint32_t>(lists.stack[index].length)) return corrupt("merge offset out of range");
        const int32_t m = lists.advance(lists.stack[index].head, static_cast<int32_t>(offset));
        w = lists.vertex[m];
        ++state.occurrences[w];
        lists.merge(m, index);
      }
      if (w == vf || w == n1) return corrupt("a triangle repeats a vertex");
      GAB_RETURN_IF_ERROR(conquer(vf, w, n1));
    }
  }
  if (dec->overrun()) return corrupt("stream truncated");
  for (int32_t v = 0; v < out->num_vertices; ++v) {
    if (state.known(v) && state.remaining(v) != 0) {
      return corrupt("vertex " + std::to_string(v) + " falls short of its valence");
    }
  }
  return Status::Ok();
}

}  // namespace gab
