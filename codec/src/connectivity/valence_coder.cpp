// Touma & Gotsman 1998, written as encoder and decoder twins over one set of
// active-list operations (ActiveLists): each side decides the event its own
// way (the encoder from the mesh, the decoder from the stream and the
// valences), then both apply it with the same calls.
#include "connectivity/valence_coder.h"

#include <algorithm>
#include <string>

#include "connectivity/active_lists.h"
#include "connectivity/adaptive_valence_coder.h"
#include "entropy/int_coder.h"

namespace gab {

namespace {

// A new vertex's valence is coded in the context of the two vertices it
// joins, the focus and its successor: their valences' sum (valences are
// anticorrelated around a triangle). On the shared meshes this codes 2-4%
// smaller than the focus's valence alone (igea 25,410 -> 24,428 bytes). The
// last context is for dummies (a boundary loop's length).
constexpr int kValenceContexts = 12;

int valence_context(int32_t focus_degree, int32_t next_degree, bool dummy) {
  if (dummy) return kValenceContexts - 1;
  return std::min(std::max(focus_degree + next_degree - 8, 0), kValenceContexts - 2);
}

// Per vertex, both sides: triangles not yet conquered around it, and its
// occurrences on the active lists.
struct VertexState {
  std::vector<int32_t> degree, remaining, occurrences;
  std::vector<uint8_t> dummy;
};

// After a CLOSE the focus moves to the predecessor (the region then grows
// as a spiral; moving to the successor, the newest vertex, makes it wander
// and split: 4.1 against 1.75 bits per vertex on igea) unless the successor
// has fewer triangles left (Alliez & Desbrun's rule, applied to the two
// candidates: 1.75 -> 1.59 on igea, fewer splits).
void refocus_after_close(ActiveLists* lists, const VertexState& vs) {
  const int32_t n1 = lists->next[lists->focus];
  if (vs.remaining[lists->vertex[n1]] < vs.remaining[lists->vertex[lists->focus]]) lists->focus = n1;
}

// The adaptive statistics both sides keep, in the same state.
struct ValenceModels {
  ValenceModels();
  BitModel close[4], add[4], merge, split_backward, dummy[2], two_cycle;
  UIntCoder valence, split_offset, merge_list, merge_offset, components;
};

ValenceModels::ValenceModels()
    : merge(8), two_cycle(8), valence(kValenceContexts), split_offset(1), merge_list(1), merge_offset(1),
      components(1) {
  for (BitModel& m : close) m = BitModel(6);
  for (BitModel& m : add) m = BitModel(7);
  for (BitModel& m : dummy) m = BitModel(7);
}

// What conquering the focus's next triangle U = (focus, w, next(focus)) is.
// kClose and kCloseNext are implied by the valences (kClose coded only when
// the focus lies on the lists more than once); the others are coded.
enum class Event { kAdd, kClose, kCloseNext, kSplit, kMerge };

// U is the successor's last triangle: then w is the successor's successor,
// and no symbol is needed. Only decidable for a successor on the lists once.
bool closes_next(const ActiveLists& lists, const VertexState& vs, int32_t focus) {
  const int32_t n1 = lists.vertex[lists.next[focus]];
  return lists.length >= 3 && vs.occurrences[n1] == 1 && vs.remaining[n1] == 1;
}

}  // namespace


int32_t count_components(const ClosedMesh& mesh) {
  const int32_t count = static_cast<int32_t>(mesh.triangles.size() / 3);
  int32_t components = 0;
  std::vector<uint8_t> seen(static_cast<size_t>(count), 0);
  std::vector<int32_t> queue;
  for (int32_t t = 0; t < count; ++t) {
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
  return components;
}

namespace {

// Closes a cut's triangles and opposites (already in `closed`, over
// closed->num_vertices vertices) in place: a boundary half-edge is one
// whose opposite is still -1 (the loops already closed have theirs set).
void close_loops(ClosedMesh* closed) {
  const int32_t cut_vertices = closed->num_vertices;
  const int32_t halves = static_cast<int32_t>(closed->triangles.size());
  std::vector<int32_t>& tri = closed->triangles;
  std::vector<int32_t>& opposite = closed->opposite;
  // Each cut vertex is one fan, so a boundary vertex has exactly one
  // outgoing boundary half-edge: the loop continues from there.
  std::vector<int32_t> leaving(static_cast<size_t>(cut_vertices), -1);
  for (int32_t h = 0; h < halves; ++h) {
    if (opposite[h] < 0) leaving[tri[h]] = h;
  }
  for (int32_t start = 0; start < halves; ++start) {
    if (opposite[start] >= 0) continue;
    const int32_t d = closed->num_vertices++;
    // One triangle (b, a, d) per boundary half-edge a -> b, glued to it and
    // to its neighbours in the loop.
    const int32_t first = static_cast<int32_t>(tri.size());
    int32_t h = start, previous = -1;
    do {
      const int32_t a = tri[h], b = tri[next_corner(h)];
      const int32_t t = static_cast<int32_t>(tri.size());
      tri.insert(tri.end(), {b, a, d});
      opposite.insert(opposite.end(), {h, -1, -1});
      opposite[h] = t;
      if (previous >= 0) {  // previous: (a, z, d); its d -> a meets our a -> d
        opposite[previous + 2] = t + 1;
        opposite[t + 1] = previous + 2;
      }
      previous = t;
      h = leaving[b];
    } while (h != start);
    opposite[previous + 2] = first + 1;
    opposite[first + 1] = previous + 2;
  }
  closed->dummy.assign(static_cast<size_t>(closed->num_vertices), 0);
  std::fill(closed->dummy.begin() + cut_vertices, closed->dummy.end(), 1);
}

}  // namespace

ClosedMesh close_boundaries(const ManifoldCut& cut) {
  ClosedMesh closed;
  closed.num_vertices = cut.num_vertices;
  closed.triangles = cut.triangles;
  closed.opposite = cut.opposite;
  close_loops(&closed);
  return closed;
}

ClosedMesh close_boundaries(ManifoldCut* cut) {
  ClosedMesh closed;
  closed.num_vertices = cut->num_vertices;
  closed.triangles.swap(cut->triangles);
  closed.opposite.swap(cut->opposite);
  close_loops(&closed);
  return closed;
}

namespace {

int64_t encode_valences_v1(const ClosedMesh& mesh, RangeEncoder* enc, std::vector<int32_t>* order) {
  ValenceModels models;
  const int32_t halves = static_cast<int32_t>(mesh.triangles.size());
  const int32_t n = mesh.num_vertices;
  VertexState vs;
  vs.degree.assign(static_cast<size_t>(n), 0);
  for (int32_t v : mesh.triangles) ++vs.degree[v];
  vs.remaining = vs.degree;
  vs.occurrences.assign(static_cast<size_t>(n), 0);
  std::vector<uint8_t> conquered(static_cast<size_t>(halves / 3), 0), visited(static_cast<size_t>(n), 0);
  order->clear();

  const int32_t components = count_components(mesh);
  models.components.encode(enc, static_cast<uint32_t>(components));

  // Encoder-only node data: the conquered triangle's half-edge each node
  // stands for (node -> its vertex to the next node's), the reverse map for
  // boundary half-edges, and which cycle holds the node (ids; the current
  // cycle's id is `current`).
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
  auto code_new_vertex = [&](int32_t w, int32_t focus_degree, int32_t next_degree, bool focus_dummy) {
    enc->encode(&models.dummy[focus_dummy ? 1 : 0], mesh.dummy[w]);
    models.valence.encode(enc, static_cast<uint32_t>(vs.degree[w] - 2),
                          valence_context(focus_degree, next_degree, mesh.dummy[w] != 0));
    visited[w] = 1;
    vs.occurrences[w] = 1;
    order->push_back(w);
  };

  int32_t seed_scan = 0;
  for (int32_t component = 0; component < components; ++component) {
    while (conquered[seed_scan]) ++seed_scan;
    const int32_t s = seed_scan;
    const int32_t a = mesh.triangles[3 * s], b = mesh.triangles[3 * s + 1], c = mesh.triangles[3 * s + 2];
    for (int32_t v : {a, b, c}) code_new_vertex(v, 0, 0, false);
    conquered[s] = 1;
    for (int32_t v : {a, b, c}) --vs.remaining[v];
    lists.start(a, b, c);
    for (int i = 0; i < 3; ++i) {
      set_half(lists.focus + i, 3 * s + i);
      label(lists.focus + i, current);
    }
    for (;;) {
      const int32_t f = lists.focus;
      if (lists.length == 2) {
        const int32_t g = lists.next[f];
        const bool closed = conquered[mesh.opposite[half[f]] / 3] != 0;
        const int32_t vf = lists.vertex[f], vg = lists.vertex[g];
        if (vs.occurrences[vf] > 1 && vs.occurrences[vg] > 1) enc->encode(&models.two_cycle, closed);
        if (closed) {
          --vs.occurrences[vf];
          --vs.occurrences[vg];
          if (!lists.pop()) break;
          current = stack_ids.back();
          stack_ids.pop_back();
          continue;
        }
      }
      const int32_t vf = lists.vertex[f];
      const int32_t across = mesh.opposite[half[f]];  // in U, from next(focus) to the focus
      const int32_t u = across / 3;
      const int32_t w = mesh.triangles[prev_corner(across)];
      const int32_t n1 = lists.vertex[lists.next[f]];
      // The occurrence of w whose gap holds U (if w was met before): turn
      // around w from U through unconquered triangles to the first
      // conquered one; the boundary half-edge met there enters it.
      int32_t m = -1;
      if (visited[w]) {
        int32_t k = prev_corner(across), h = mesh.opposite[k];
        while (!conquered[h / 3]) {
          k = next_corner(h);
          h = mesh.opposite[k];
        }
        m = lists.next[node_of_half[h]];
      }
      // CLOSE when U's edge focus -> w is the predecessor's boundary edge
      // (not merely a second edge to the same vertex: then it is a SPLIT).
      const bool closes = m >= 0 && conquered[mesh.opposite[next_corner(across)] / 3];
      const Event event = m < 0                       ? Event::kAdd
                          : closes                    ? Event::kClose
                          : closes_next(lists, vs, f) ? Event::kCloseNext
                          : list_of[m] == current     ? Event::kSplit
                                                      : Event::kMerge;
      const int context = std::min(vs.remaining[vf], 4) - 1;
      if (vs.occurrences[vf] > 1) enc->encode(&models.close[context], event == Event::kClose);
      if (event != Event::kClose && event != Event::kCloseNext) {
        enc->encode(&models.add[context], event == Event::kAdd);
      }
      conquered[u] = 1;
      --vs.remaining[vf];
      --vs.remaining[w];
      --vs.remaining[n1];
      if (event == Event::kClose) {
        --vs.occurrences[vf];
        set_half(lists.close(), prev_corner(across));  // the predecessor now runs to next(focus)
        refocus_after_close(&lists, vs);
        continue;
      }
      // U = (focus, w, next(focus)): the focus now runs to w.
      set_half(f, next_corner(across));
      if (event == Event::kCloseNext) {
        --vs.occurrences[n1];
        lists.close_next();
        continue;
      }
      int32_t x;
      if (event == Event::kAdd) {
        code_new_vertex(w, vs.degree[vf], vs.degree[n1], mesh.dummy[vf] != 0);
        x = lists.add(w);
        label(x, current);
      } else if (event == Event::kSplit) {
        enc->encode(&models.merge, 0);
        ++vs.occurrences[w];
        int32_t offset = 0;
        for (int32_t node = f; node != m; node = lists.next[node]) ++offset;
        lists.walked += offset;
        // The nearer way round: splits are mostly local.
        const bool backward = lists.length - offset < offset;
        enc->encode(&models.split_backward, backward);
        models.split_offset.encode(enc, static_cast<uint32_t>(backward ? lists.length - offset - 1 : offset - 2));
        x = lists.split(m, offset);
        // The waiting cycle gets a new id: relabel its nodes.
        const int32_t id = next_id++;
        int32_t node = x;
        do {
          label(node, id);
          node = lists.next[node];
        } while (node != x);
        stack_ids.push_back(id);
      } else {
        enc->encode(&models.merge, 1);
        ++vs.occurrences[w];
        const size_t index =
            static_cast<size_t>(std::find(stack_ids.begin(), stack_ids.end(), list_of[m]) - stack_ids.begin());
        models.merge_list.encode(enc, static_cast<uint32_t>(stack_ids.size() - 1 - index));
        int32_t offset = 0;
        for (int32_t node = lists.stack[index].head; node != m; node = lists.next[node]) ++offset;
        lists.walked += offset;
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
  return lists.walked;
}

Status decode_valences_v1(RangeDecoder* dec, int32_t max_vertices, int64_t max_triangles, DecodedConnectivity* out) {
  auto corrupt = [](const std::string& what) {
    return Status::Error(StatusCode::kParseError, "connectivity: " + what);
  };
  const int64_t budget = walk_budget(max_triangles);
  ValenceModels models;
  VertexState vs;
  out->num_vertices = 0;
  out->triangles.clear();
  out->dummy.clear();
  const uint32_t components = models.components.decode(dec);
  if (components > static_cast<uint32_t>(max_triangles)) return corrupt("component count out of range");

  auto new_vertex = [&](int32_t focus_degree, int32_t next_degree, bool focus_dummy, int32_t* v) {
    if (out->num_vertices >= max_vertices) return corrupt("more vertices than the header says");
    const bool dummy = dec->decode(&models.dummy[focus_dummy ? 1 : 0]) != 0;
    const uint32_t valence = models.valence.decode(dec, valence_context(focus_degree, next_degree, dummy));
    if (valence > static_cast<uint32_t>(3 * max_triangles)) return corrupt("valence out of range");
    *v = out->num_vertices++;
    vs.degree.push_back(static_cast<int32_t>(valence) + 2);
    vs.remaining.push_back(static_cast<int32_t>(valence) + 2);
    vs.occurrences.push_back(1);
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
    out->triangles.insert(out->triangles.end(), {a, b, c});
    return Status::Ok();
  };

  ActiveLists lists;
  for (uint32_t component = 0; component < components; ++component) {
    int32_t seed[3];
    for (int32_t& v : seed) GAB_RETURN_IF_ERROR(new_vertex(0, 0, false, &v));
    GAB_RETURN_IF_ERROR(conquer(seed[0], seed[1], seed[2]));
    lists.start(seed[0], seed[1], seed[2]);
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
          if (!lists.pop()) break;
          continue;
        }
      }
      if (vs.remaining[vf] < 1) return corrupt("a closed vertex is the focus");
      const int32_t n1 = lists.vertex[lists.next[f]];
      const int context = std::min(vs.remaining[vf], 4) - 1;
      const bool close = vs.occurrences[vf] > 1 ? dec->decode(&models.close[context]) != 0
                                                : vs.remaining[vf] == 1;
      if (close) {
        if (lists.length < 3) return corrupt("a two-vertex boundary cannot close a triangle");
        GAB_RETURN_IF_ERROR(conquer(vf, lists.vertex[lists.prev[f]], n1));
        --vs.occurrences[vf];
        lists.close();
        refocus_after_close(&lists, vs);
        continue;
      }
      if (closes_next(lists, vs, f)) {
        if (lists.length < 3) return corrupt("a two-vertex boundary cannot close a triangle");
        GAB_RETURN_IF_ERROR(conquer(vf, lists.vertex[lists.next[lists.next[f]]], n1));
        --vs.occurrences[n1];
        lists.close_next();
        continue;
      }
      int32_t w;
      if (dec->decode(&models.add[context])) {
        GAB_RETURN_IF_ERROR(new_vertex(vs.degree[vf], vs.degree[n1], out->dummy[vf] != 0, &w));
        lists.add(w);
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
        w = lists.vertex[m];
        ++vs.occurrences[w];
        lists.split(m, static_cast<int32_t>(offset));
        if (lists.walked > budget) return corrupt("splits walk more than " + std::to_string(budget) + " list steps");
      } else {
        const uint32_t back = models.merge_list.decode(dec);
        if (back >= lists.stack.size()) return corrupt("merge names a list that does not exist");
        const size_t index = lists.stack.size() - 1 - back;
        const uint32_t offset = models.merge_offset.decode(dec);
        if (offset >= static_cast<uint32_t>(lists.stack[index].length)) return corrupt("merge offset out of range");
        const int32_t m = lists.advance(lists.stack[index].head, static_cast<int32_t>(offset));
        w = lists.vertex[m];
        ++vs.occurrences[w];
        lists.merge(m, index);
        if (lists.walked > budget) return corrupt("merges walk more than " + std::to_string(budget) + " list steps");
      }
      if (w == vf || w == n1) return corrupt("a triangle repeats a vertex");
      GAB_RETURN_IF_ERROR(conquer(vf, w, n1));
    }
  }
  if (dec->overrun()) return corrupt("stream truncated");
  for (int32_t v = 0; v < out->num_vertices; ++v) {
    if (vs.remaining[v] != 0) return corrupt("vertex " + std::to_string(v) + " falls short of its valence");
  }
  return Status::Ok();
}

}  // namespace

int64_t encode_valences(const ClosedMesh& mesh, RangeEncoder* enc, std::vector<int32_t>* order, int version) {
  return version <= 1 ? encode_valences_v1(mesh, enc, order) : encode_adaptive_valences(mesh, enc, order);
}

Status decode_valences(RangeDecoder* dec, int32_t max_vertices, int64_t max_triangles, DecodedConnectivity* out,
                       int version) {
  if (version == 1) return decode_valences_v1(dec, max_vertices, max_triangles, out);
  if (version == 2) return decode_adaptive_valences(dec, max_vertices, max_triangles, out);
  return Status::Error(StatusCode::kParseError,
                       "connectivity: unknown valence coder version " + std::to_string(version));
}

}  // namespace gab
