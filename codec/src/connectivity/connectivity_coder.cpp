// Triangle-list coding (order and orientation kept) over the range coder.
//
// Encoder and decoder maintain the same three structures, updated after
// every triangle:
//  * the open edges: directed edges of coded triangles that no coded
//    triangle has glued onto yet (the reversed edge), listed per vertex;
//  * an edge cache: the most recent open edges (newest first);
//  * a vertex cache: the most recently used vertices (move to front).
//
// A triangle that closes an edge of the edge cache is coded as that edge's
// index, which side of the triangle it is (so rotation is kept), and its
// third vertex. Any other triangle codes its first vertex, then the others.
// A vertex after the first is first looked for among the candidates that
// would close an open edge: the sources x of open edges x -> (the previous
// vertex), then, for the third, the targets y of open edges (the first
// vertex) -> y. Failing that, or for a first vertex, it is coded as the next
// never-referenced vertex (meshes often introduce vertices in order), a
// vertex-cache position, or a cached reference vertex plus a signed delta
// (vertex numbers of neighbours tend to be close).
//
// Every decision has its own adaptive statistics per slot (first, second or
// third vertex of a triangle coded vertex by vertex, or the third vertex
// after a cached edge). Measured on the shared meshes: see
// tests/codec/connectivity/connectivity_coder_test.cpp.
#include "connectivity/connectivity_coder.h"

#include <algorithm>
#include <array>
#include <string>

#include "entropy/flat_int_map.h"
#include "entropy/int_coder.h"
#include "entropy/range_coder.h"

namespace gab {
namespace {

constexpr int kVertexCacheSize = 32;
constexpr int kEdgeCacheSize = 32;
constexpr int kCandidatesPerList = 16;  // most recent open edges looked at per vertex

enum Slot { kFirst = 0, kSecond = 1, kThird = 2, kApex = 3, kSlots = 4 };

struct Edge {
  int32_t from, to;
};

// Most recently used vertices, most recent first.
class VertexCache {
 public:
  int size() const { return size_; }
  int32_t at(int i) const { return vertices_[i]; }
  int find(int32_t v) const {
    for (int i = 0; i < size_; ++i) {
      if (vertices_[i] == v) return i;
    }
    return -1;
  }
  void touch(int32_t v) {
    int i = find(v);
    if (i < 0) {  // enters at the back, dropping the least recent when full
      if (size_ < kVertexCacheSize) ++size_;
      i = size_ - 1;
    }
    for (; i > 0; --i) vertices_[i] = vertices_[i - 1];
    vertices_[0] = v;
  }

 private:
  std::array<int32_t, kVertexCacheSize> vertices_{};
  int size_ = 0;
};

// The most recent open edges, newest first.
class EdgeCache {
 public:
  int size() const { return size_; }
  Edge at(int i) const { return edges_[i]; }
  int find(int32_t from, int32_t to) const {
    for (int i = 0; i < size_; ++i) {
      if (edges_[i].from == from && edges_[i].to == to) return i;
    }
    return -1;
  }
  // Each side of the triangle closes its reverse (removed) or is a new open edge.
  void add_triangle(const int32_t* v) {
    for (int k = 0; k < 3; ++k) {
      const int32_t from = v[k], to = v[(k + 1) % 3];
      const int i = find(to, from);
      if (i >= 0) {
        for (int j = i; j + 1 < size_; ++j) edges_[j] = edges_[j + 1];
        --size_;
      } else {
        if (size_ < kEdgeCacheSize) ++size_;
        for (int j = size_ - 1; j > 0; --j) edges_[j] = edges_[j - 1];
        edges_[0] = Edge{from, to};
      }
    }
  }

 private:
  std::array<Edge, kEdgeCacheSize> edges_{};
  int size_ = 0;
};

// All open edges: a hash from directed edge to node, and per vertex a
// doubly linked list of its incoming and of its outgoing open edges, newest
// first. A directed edge open several times (duplicate triangles) is one
// node with a count. Every operation is O(1) expected; storage is one node
// per open edge, so at most 3 per coded triangle.
class OpenEdges {
 public:
  void add_triangle(const int32_t* v) {
    for (int k = 0; k < 3; ++k) {
      const int32_t from = v[k], to = v[(k + 1) % 3];
      if (!close(to, from)) open(from, to);
    }
  }
  // Up to kCandidatesPerList sources x of open edges x -> v, newest first.
  void append_sources(int32_t v, std::vector<int32_t>* out) const { append(first_in_, v, false, out); }
  // Up to kCandidatesPerList targets y of open edges v -> y, newest first.
  void append_targets(int32_t v, std::vector<int32_t>* out) const { append(first_out_, v, true, out); }

 private:
  struct Node {
    int32_t from, to, count;
    int32_t prev_in, next_in, prev_out, next_out;  // -1: none
  };
  using Heads = FlatIntMap;  // vertex -> newest node of its list

  static uint64_t key(int32_t from, int32_t to) {
    return (uint64_t{static_cast<uint32_t>(from)} << 32) | static_cast<uint32_t>(to);
  }

  void append(const Heads& heads, int32_t v, bool outgoing, std::vector<int32_t>* out) const {
    const int32_t* head = heads.find(static_cast<uint64_t>(v));
    int32_t i = head == nullptr ? -1 : *head;
    for (int n = 0; i >= 0 && n < kCandidatesPerList; ++n) {
      const Node& node = nodes_[i];
      out->push_back(outgoing ? node.to : node.from);
      i = outgoing ? node.next_out : node.next_in;
    }
  }

  void open(int32_t from, int32_t to) {
    if (const int32_t* found = by_edge_.find(key(from, to))) {
      ++nodes_[*found].count;
      return;
    }
    int32_t i;
    if (!free_.empty()) {
      i = free_.back();
      free_.pop_back();
    } else {
      i = static_cast<int32_t>(nodes_.size());
      nodes_.emplace_back();
    }
    Node& node = nodes_[i];
    node = Node{from, to, 1, -1, -1, -1, -1};
    int32_t& in = first_in_.insert(static_cast<uint64_t>(to), -1);
    node.next_in = in;
    if (node.next_in >= 0) nodes_[node.next_in].prev_in = i;
    in = i;
    int32_t& out = first_out_.insert(static_cast<uint64_t>(from), -1);
    node.next_out = out;
    if (node.next_out >= 0) nodes_[node.next_out].prev_out = i;
    out = i;
    by_edge_.insert(key(from, to), i);
  }

  // Removes one instance of the open edge from -> to; false if there is none.
  bool close(int32_t from, int32_t to) {
    const int32_t* found = by_edge_.find(key(from, to));
    if (found == nullptr) return false;
    const int32_t i = *found;
    Node& node = nodes_[i];
    if (--node.count > 0) return true;
    by_edge_.erase(key(from, to));
    unlink(&first_in_, node.to, node.prev_in, node.next_in, &Node::next_in, &Node::prev_in);
    unlink(&first_out_, node.from, node.prev_out, node.next_out, &Node::next_out, &Node::prev_out);
    free_.push_back(i);
    return true;
  }

  void unlink(Heads* heads, int32_t v, int32_t prev, int32_t next, int32_t Node::*next_of,
              int32_t Node::*prev_of) {
    if (next >= 0) nodes_[next].*prev_of = prev;
    if (prev >= 0) {
      nodes_[prev].*next_of = next;
    } else if (next >= 0) {
      *heads->find(static_cast<uint64_t>(v)) = next;
    } else {
      heads->erase(static_cast<uint64_t>(v));
    }
  }

  std::vector<Node> nodes_;
  std::vector<int32_t> free_;
  FlatIntMap by_edge_;
  Heads first_in_, first_out_;
};

// Everything both sides know, and the adaptive models.
struct CoderState {
  VertexCache recent;
  EdgeCache edges;
  OpenEdges open;
  int64_t next_new = 0;  // one past the largest vertex referenced so far
  int previous_hit = 0;  // whether the previous triangle closed a cached edge
  std::vector<int32_t> candidates;

  BitModel edge_hit[2];
  UIntCoder edge_index{1};
  BitModel rotation[2];
  BitModel is_candidate[kSlots][4];  // by slot and min(candidate count, 3)
  UIntCoder candidate_index{kSlots * 3};
  BitModel is_new[kSlots];
  BitModel in_cache[kSlots];
  UIntCoder cache_position{kSlots};
  UIntCoder reference_position{kSlots};
  SIntCoder delta{kSlots};

  // Candidates for w[c] (c = 1, 2) given the vertices before it.
  void gather_candidates(const int32_t* w, int c) {
    candidates.clear();
    open.append_sources(w[c - 1], &candidates);
    if (c == 2) open.append_targets(w[0], &candidates);
  }
  int candidate_context() const { return std::min<int>(static_cast<int>(candidates.size()), 3); }

  void use(int32_t v) {
    recent.touch(v);
    next_new = std::max<int64_t>(next_new, int64_t{v} + 1);
  }
  void add_triangle(const int32_t* v) {
    edges.add_triangle(v);
    open.add_triangle(v);
  }
};

int bit_length(uint64_t x) {
  int length = 0;
  for (; x != 0; x >>= 1) ++length;
  return length;
}

// ---- Encoder --------------------------------------------------------------

// The cached vertex making position + delta cheapest (about 2 log2 each).
int pick_reference(const VertexCache& recent, int32_t v) {
  int best = 0, best_cost = 1 << 30;
  for (int j = 0; j < recent.size(); ++j) {
    const int64_t d = int64_t{v} - recent.at(j);
    const uint64_t magnitude = static_cast<uint64_t>(d < 0 ? -d : d);
    const int cost = 2 * bit_length(static_cast<uint64_t>(j) + 1) + 2 * bit_length(magnitude);
    if (cost < best_cost) {
      best_cost = cost;
      best = j;
    }
  }
  return best;
}

void encode_vertex(RangeEncoder* enc, CoderState* s, int slot, int32_t v) {
  const bool is_new = v == s->next_new;
  enc->encode(&s->is_new[slot], is_new);
  if (!is_new) {
    const int position = s->recent.find(v);
    enc->encode(&s->in_cache[slot], position >= 0);
    if (position >= 0) {
      s->cache_position.encode(enc, static_cast<uint32_t>(position), slot);
    } else {
      int64_t reference = 0;
      if (s->recent.size() > 0) {
        const int j = pick_reference(s->recent, v);
        s->reference_position.encode(enc, static_cast<uint32_t>(j), slot);
        reference = s->recent.at(j);
      }
      s->delta.encode(enc, static_cast<int32_t>(int64_t{v} - reference), slot);
    }
  }
  s->use(v);
}

// w[c], c = 1 or 2, as a candidate or else through encode_vertex.
void encode_later_vertex(RangeEncoder* enc, CoderState* s, int slot, const int32_t* w, int c) {
  s->gather_candidates(w, c);
  if (!s->candidates.empty()) {
    const auto it = std::find(s->candidates.begin(), s->candidates.end(), w[c]);
    const bool found = it != s->candidates.end();
    const int context = s->candidate_context();
    enc->encode(&s->is_candidate[slot][context], found);
    if (found) {
      s->candidate_index.encode(enc, static_cast<uint32_t>(it - s->candidates.begin()), 3 * slot + context - 1);
      s->use(w[c]);
      return;
    }
  }
  encode_vertex(enc, s, slot, w[c]);
}

// ---- Decoder --------------------------------------------------------------

Status triangle_error(int32_t t, const std::string& what) {
  return Status::Error(StatusCode::kParseError, "connectivity: triangle " + std::to_string(t) + ": " + what);
}

Status truncated(int32_t t) { return triangle_error(t, "stream ends inside the triangle"); }

Status decode_vertex(RangeDecoder* dec, CoderState* s, int slot, int32_t n, int32_t t, int32_t* v) {
  int64_t value;
  if (dec->decode(&s->is_new[slot])) {
    value = s->next_new;
  } else if (dec->decode(&s->in_cache[slot])) {
    const uint32_t position = s->cache_position.decode(dec, slot);
    if (dec->overrun()) return truncated(t);
    if (position >= static_cast<uint32_t>(s->recent.size())) {
      return triangle_error(t, "vertex cache position " + std::to_string(position) + " is empty");
    }
    value = s->recent.at(static_cast<int>(position));
  } else {
    int64_t reference = 0;
    if (s->recent.size() > 0) {
      const uint32_t position = s->reference_position.decode(dec, slot);
      if (dec->overrun()) return truncated(t);
      if (position >= static_cast<uint32_t>(s->recent.size())) {
        return triangle_error(t, "vertex cache position " + std::to_string(position) + " is empty");
      }
      reference = s->recent.at(static_cast<int>(position));
    }
    value = reference + s->delta.decode(dec, slot);
  }
  if (dec->overrun()) return truncated(t);
  if (value < 0 || value >= n) {
    return triangle_error(t, "vertex index " + std::to_string(value) + " out of range [0, " + std::to_string(n) + ")");
  }
  *v = static_cast<int32_t>(value);
  s->use(*v);
  return Status::Ok();
}

Status decode_later_vertex(RangeDecoder* dec, CoderState* s, int slot, int32_t n, int32_t t, int32_t* w, int c) {
  s->gather_candidates(w, c);
  if (!s->candidates.empty()) {
    const int context = s->candidate_context();
    if (dec->decode(&s->is_candidate[slot][context])) {
      const uint32_t index = s->candidate_index.decode(dec, 3 * slot + context - 1);
      if (dec->overrun()) return truncated(t);
      if (index >= s->candidates.size()) {
        return triangle_error(t, "candidate " + std::to_string(index) + " does not exist");
      }
      w[c] = s->candidates[index];  // already validated when first decoded
      s->use(w[c]);
      return Status::Ok();
    }
  }
  return decode_vertex(dec, s, slot, n, t, &w[c]);
}

}  // namespace

std::vector<uint8_t> encode_connectivity(int32_t num_vertices, const std::vector<int32_t>& triangles) {
  (void)num_vertices;  // only the decoder's validation depends on n, not the code
  RangeEncoder enc;
  CoderState s;
  const size_t count = triangles.size() / 3;
  for (size_t t = 0; t < count; ++t) {
    const int32_t* v = &triangles[3 * t];
    // The newest cached edge that one of the sides closes.
    int index = kEdgeCacheSize, rotation = -1;
    for (int r = 0; r < 3; ++r) {
      const int i = s.edges.find(v[(r + 1) % 3], v[r]);
      if (i >= 0 && i < index) {
        index = i;
        rotation = r;
      }
    }
    const bool hit = rotation >= 0;
    enc.encode(&s.edge_hit[s.previous_hit], hit);
    s.previous_hit = hit;
    if (hit) {
      // Side `rotation` (v[r] -> v[r+1]) closes the cached edge v[r+1] -> v[r].
      s.edge_index.encode(&enc, static_cast<uint32_t>(index));
      enc.encode(&s.rotation[0], rotation != 0);
      if (rotation != 0) enc.encode(&s.rotation[1], rotation == 2);
      const int32_t w[3] = {v[rotation], v[(rotation + 1) % 3], v[(rotation + 2) % 3]};
      s.use(w[0]);
      s.use(w[1]);
      encode_later_vertex(&enc, &s, kApex, w, 2);
    } else {
      encode_vertex(&enc, &s, kFirst, v[0]);
      encode_later_vertex(&enc, &s, kSecond, v, 1);
      encode_later_vertex(&enc, &s, kThird, v, 2);
    }
    s.add_triangle(v);
  }
  return enc.finish();
}

Status decode_connectivity(const uint8_t* data, size_t size, int32_t num_vertices, int32_t num_triangles,
                           std::vector<int32_t>* triangles) {
  triangles->clear();
  if (num_vertices < 0 || num_triangles < 0) {
    return Status::Error(StatusCode::kInvalidArgument, "connectivity: negative vertex or triangle count");
  }
  // Real streams spend about a byte per triangle or more: reserve for at
  // most twice that, and let a stream of cheaper triangles grow the vector.
  triangles->reserve(3 * std::min<size_t>(static_cast<size_t>(num_triangles), 2 * size + 16));
  RangeDecoder dec(data, size);
  CoderState s;
  for (int32_t t = 0; t < num_triangles; ++t) {
    int32_t v[3];
    const bool hit = dec.decode(&s.edge_hit[s.previous_hit]) != 0;
    s.previous_hit = hit;
    if (hit) {
      const uint32_t index = s.edge_index.decode(&dec);
      int rotation = 0;
      if (dec.decode(&s.rotation[0])) rotation = dec.decode(&s.rotation[1]) ? 2 : 1;
      if (dec.overrun()) return truncated(t);
      if (index >= static_cast<uint32_t>(s.edges.size())) {
        return triangle_error(t, "edge cache position " + std::to_string(index) + " is empty");
      }
      const Edge e = s.edges.at(static_cast<int>(index));
      int32_t w[3] = {e.to, e.from, 0};
      s.use(w[0]);
      s.use(w[1]);
      GAB_RETURN_IF_ERROR(decode_later_vertex(&dec, &s, kApex, num_vertices, t, w, 2));
      for (int k = 0; k < 3; ++k) v[(rotation + k) % 3] = w[k];
    } else {
      GAB_RETURN_IF_ERROR(decode_vertex(&dec, &s, kFirst, num_vertices, t, &v[0]));
      GAB_RETURN_IF_ERROR(decode_later_vertex(&dec, &s, kSecond, num_vertices, t, v, 1));
      GAB_RETURN_IF_ERROR(decode_later_vertex(&dec, &s, kThird, num_vertices, t, v, 2));
    }
    s.add_triangle(v);
    triangles->insert(triangles->end(), v, v + 3);
  }
  // With no triangle to name, only the 4 bytes read up front can overrun.
  if (dec.overrun()) return Status::Error(StatusCode::kParseError, "connectivity: stream truncated");
  if (dec.bytes_consumed() != size) {
    return Status::Error(StatusCode::kParseError,
                         "connectivity: " + std::to_string(size - dec.bytes_consumed()) + " trailing bytes after " +
                             std::to_string(num_triangles) + " triangles");
  }
  return Status::Ok();
}

uint64_t connectivity_hash(int32_t num_vertices, const std::vector<int32_t>& triangles) {
  uint64_t h = 0xcbf29ce484222325ull;  // FNV-1a 64 offset basis
  auto feed = [&h](int32_t value) {
    const uint32_t u = static_cast<uint32_t>(value);
    for (int i = 0; i < 4; ++i) {
      h ^= (u >> (8 * i)) & 0xFFu;
      h *= 0x100000001b3ull;  // FNV-1a 64 prime
    }
  };
  feed(num_vertices);
  feed(static_cast<int32_t>(triangles.size() / 3));
  for (const int32_t index : triangles) feed(index);
  return h;
}

}  // namespace gab
