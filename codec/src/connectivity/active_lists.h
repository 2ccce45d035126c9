// The active lists of a valence-driven traversal (Touma & Gotsman 1998),
// on which the valence coder (valence_coder.h) conquers a mesh: the
// boundary of the conquered region as cycles of vertex occurrences, and the
// operations that grow it. Both sides apply the same calls, so the lists
// (node numbers included) are the same in the encoder and the decoder.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace gab {

// The most list steps (ActiveLists::walked) a decoder allowed at most
// `max_triangles` triangles may take: 2^20 plus 16 per triangle (a valence
// section allows 4 per triangle of the file, dummies' included: 64 per
// file triangle), far above any real mesh's (the shared meshes and
// libcgal-demo's walk at most 1.9 per file triangle), so that a forged
// stream cannot make a decoder
// quadratic.
inline int64_t walk_budget(int64_t max_triangles) { return (int64_t{1} << 20) + 16 * max_triangles; }

// The boundary of the conquered region: cycles of vertex occurrences
// ("nodes"), the region on their left. The current cycle is the one the
// focus is in; the others wait on a stack.
struct ActiveLists {
  struct Pending {
    int32_t head, length;
  };
  std::vector<int32_t> vertex, next, prev;  // per node
  std::vector<Pending> stack;
  int32_t focus = -1, length = 0;
  // List steps walked beyond O(1) per triangle: by splits and merges
  // (advance, retreat, the stack's upkeep, the callers' own walks). Linear
  // in practice, but a forged stream could make it quadratic: the decoders
  // stop at walk_budget.
  int64_t walked = 0;

  void reserve(size_t nodes) {
    vertex.reserve(nodes);
    next.reserve(nodes);
    prev.reserve(nodes);
  }
  int32_t new_node(int32_t v) {
    vertex.push_back(v);
    next.push_back(-1);
    prev.push_back(-1);
    return static_cast<int32_t>(vertex.size()) - 1;
  }
  int32_t advance(int32_t node, int32_t steps) {
    walked += steps;
    for (int32_t i = 0; i < steps; ++i) node = next[node];
    return node;
  }
  int32_t retreat(int32_t node, int32_t steps) {
    walked += steps;
    for (int32_t i = 0; i < steps; ++i) node = prev[node];
    return node;
  }
  void link(int32_t a, int32_t b) {
    next[a] = b;
    prev[b] = a;
  }
  // The seed triangle a b c: one cycle, focus on a.
  void start(int32_t a, int32_t b, int32_t c) {
    const int32_t na = new_node(a), nb = new_node(b), nc = new_node(c);
    link(na, nb);
    link(nb, nc);
    link(nc, na);
    focus = na;
    length = 3;
  }
  // ADD: the new vertex w between the focus and its successor.
  int32_t add(int32_t w) {
    const int32_t x = new_node(w), n1 = next[focus];
    link(focus, x);
    link(x, n1);
    ++length;
    return x;
  }
  // CLOSE: the focus's last triangle joins its neighbours; the focus leaves
  // the list and its successor takes over. Returns the predecessor.
  int32_t close() {
    const int32_t p = prev[focus], n1 = next[focus];
    link(p, n1);
    --length;
    focus = p;
    return p;
  }
  // SPLIT at node m, `offset` steps after the focus: the cycle
  // focus -> m -> ... stays current; w' -> next(focus) -> ... -> prev(m)
  // (w' a new occurrence of m's vertex) waits. Returns w'.
  int32_t split(int32_t m, int32_t offset) {
    const int32_t x = new_node(vertex[m]), n1 = next[focus], mp = prev[m];
    link(x, n1);
    link(mp, x);
    link(focus, m);
    stack.push_back({x, offset});
    length = length - offset + 1;
    return x;
  }
  // MERGE with node m of the waiting cycle stack[index]: one cycle
  // focus -> m -> ... -> prev(m) -> w' -> next(focus) -> ... Returns w'.
  int32_t merge(int32_t m, size_t index) {
    const int32_t x = new_node(vertex[m]), n1 = next[focus], mp = prev[m];
    length += stack[index].length + 1;
    walked += static_cast<int64_t>(stack.size() - index);
    stack.erase(stack.begin() + static_cast<std::ptrdiff_t>(index));
    link(focus, m);
    link(mp, x);
    link(x, n1);
    return x;
  }
  // CLOSE_NEXT: the focus's triangle was the successor's last: the
  // successor leaves the list, the focus stays.
  void close_next() {
    link(focus, next[next[focus]]);
    --length;
  }
  // The current cycle is done: the next waiting one becomes current.
  bool pop() {
    if (stack.empty()) return false;
    focus = stack.back().head;
    length = stack.back().length;
    stack.pop_back();
    return true;
  }
};

}  // namespace gab
