#include "connectivity/order_coder.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "entropy/int_coder.h"
#include "entropy/range_coder.h"

namespace gab {

namespace {

// The block's first symbol.
enum class OrderMode : uint32_t {
  kTraversal = 0,  // original[k] == k
  kPredicted = 1,  // ranks relative to the predictions
  kUniform = 2,    // ranks, each a uniform choice among the remaining
};

// The input indices not yet used, as a Fenwick tree of 0/1 counts, so that
// an index's rank among them and the index of a given rank both cost
// O(log n).
class UnusedIndices {
 public:
  explicit UnusedIndices(int32_t n) : tree_(static_cast<size_t>(n) + 1), used_(static_cast<size_t>(n), 0), top_(1) {
    for (int32_t i = 1; i <= n; ++i) tree_[i] = i & -i;  // all ones
    while (top_ * 2 <= n) top_ *= 2;
  }
  int32_t size() const { return static_cast<int32_t>(used_.size()); }
  bool contains(int32_t x) const { return used_[x] == 0; }
  // How many unused indices are below x (x in [0, n]).
  int32_t rank(int32_t x) const {
    int32_t count = 0;
    for (int32_t i = x; i > 0; i -= i & -i) count += tree_[i];
    return count;
  }
  // The unused index with `r` unused indices below it (r < remaining).
  int32_t select(int32_t r) const {
    int32_t at = 0;
    for (int32_t step = top_; step > 0; step /= 2) {
      const int32_t next = at + step;
      if (next < static_cast<int32_t>(tree_.size()) && tree_[next] <= r) {
        at = next;
        r -= tree_[next];
      }
    }
    return at;  // tree positions are 1-based: `at` is the 0-based index
  }
  // The nearest unused index above / below x, or -1.
  int32_t above(int32_t x) const {
    for (int32_t y = x + 1; y < size() && y <= x + 4; ++y) {
      if (!used_[y]) return y;  // the usual case, without the tree
    }
    const int32_t r = rank(x + 1);
    return r < remaining() ? select(r) : -1;
  }
  int32_t below(int32_t x) const {
    for (int32_t y = x - 1; y >= 0 && y >= x - 4; --y) {
      if (!used_[y]) return y;
    }
    const int32_t r = rank(x);
    return r > 0 ? select(r - 1) : -1;
  }
  int32_t remaining() const { return remaining_ < 0 ? size() : remaining_; }
  void remove(int32_t x) {
    used_[x] = 1;
    remaining_ = remaining() - 1;
    for (int32_t i = x + 1; i < static_cast<int32_t>(tree_.size()); i += i & -i) --tree_[i];
  }

 private:
  std::vector<int32_t> tree_;
  std::vector<uint8_t> used_;
  int32_t top_;
  int32_t remaining_ = -1;
};

// Each vertex's neighbours, CSR, without repeats.
struct Adjacency {
  std::vector<int32_t> start, neighbour;
};

Adjacency adjacency(int32_t n, const std::vector<int32_t>& triangles) {
  std::vector<int32_t> start(static_cast<size_t>(n) + 1, 0);
  for (int32_t v : triangles) start[static_cast<size_t>(v) + 1] += 2;
  for (int32_t v = 0; v < n; ++v) start[v + 1] += start[v];
  std::vector<int32_t> fill(start.begin(), start.end() - 1), all(2 * triangles.size());
  for (size_t f = 0; f + 2 < triangles.size(); f += 3) {
    for (int i = 0; i < 3; ++i) {
      const int32_t u = triangles[f + i];
      all[fill[u]++] = triangles[f + (i + 1) % 3];
      all[fill[u]++] = triangles[f + (i + 2) % 3];
    }
  }
  // Repeats dropped, in the order the triangles list them (`seen` marks
  // the neighbours taken for the vertex at hand).
  Adjacency adj;
  adj.start.assign(static_cast<size_t>(n) + 1, 0);
  adj.neighbour.reserve(all.size() / 2);
  std::vector<int32_t> seen(static_cast<size_t>(n), -1);
  for (int32_t v = 0; v < n; ++v) {
    seen[v] = v;
    for (int32_t e = start[v]; e < start[v + 1]; ++e) {
      if (seen[all[e]] != v) {
        seen[all[e]] = v;
        adj.neighbour.push_back(all[e]);
      }
    }
    adj.start[v + 1] = static_cast<int32_t>(adj.neighbour.size());
  }
  return adj;
}

// The walk both sides make along the input numbering: for input index i,
// the vertices that input indices i - d name (d among the gaps that have
// most often joined a vertex to its earlier neighbours: 1 and 2 along
// strips, 1 and a row's length in scans) offer their unplaced neighbours as
// candidates. Each candidate has a pattern (which of those vertices it
// touches, how many placed neighbours it has), and candidates are ranked by
// how often their pattern has been the right one so far after the pattern
// that was right for i - 1, so the walk learns the rule the numbering
// follows and notices when it switches (igea's strips run along a row, then
// across: 24,502 -> 19,949 bytes with the previous pattern as context): a
// coherent numbering puts the right vertex first.
class OrderWalk {
 public:
  static constexpr int kSources = 3;
  static constexpr int kMaxCandidates = 32;
  static constexpr int32_t kMaxGap = 1 << 12;

  OrderWalk(int32_t n, const std::vector<int32_t>& triangles)
      : adj_(adjacency(n, triangles)),
        vertex_of_(static_cast<size_t>(n), -1),
        index_of_(static_cast<size_t>(n), -1),
        stamp_(static_cast<size_t>(n), -1),
        gap_count_(kMaxGap + 1, 0),
        unplaced_(n) {
    for (int s = 0; s < kSources; ++s) top_gap_[s] = s + 1;
  }

  // The candidates for input index i, best first (at most kMaxCandidates);
  // `certainty` (0..3): whether the first's pattern has hit twice as often
  // as the second's, and at least 7 times in 8.
  int candidates(int32_t i, int32_t* out, int* certainty) {
    int count = 0;
    int64_t score[kMaxCandidates];
    int32_t source[kSources];
    for (int s = 0; s < kSources; ++s) source[s] = top_gap_[s] <= i ? vertex_of_[i - top_gap_[s]] : -1;
    for (int s = 0; s < kSources; ++s) {
      if (source[s] < 0) continue;
      for (int32_t e = adj_.start[source[s]]; e < adj_.start[source[s] + 1] && count < kMaxCandidates; ++e) {
        const int32_t w = adj_.neighbour[e];
        if (index_of_[w] >= 0 || stamp_[w] == i) continue;
        stamp_[w] = i;
        int placed = 0, pattern = 0;
        for (int32_t f = adj_.start[w]; f < adj_.start[w + 1]; ++f) {
          const int32_t u = adj_.neighbour[f];
          if (index_of_[u] < 0) continue;
          ++placed;
          for (int t = 0; t < kSources; ++t) {
            if (u == source[t]) pattern |= 1 << t;
          }
        }
        pattern |= std::min(placed, 3) << kSources;
        const int64_t fit = ((hits_[last_][pattern] + 1) << 20) / (offers_[last_][pattern] + 2);
        // insertion, stable: equal fits keep the order they were met in
        int at = count++;
        while (at > 0 && score[at - 1] < fit) {
          score[at] = score[at - 1];
          out[at] = out[at - 1];
          offered_[at] = offered_[at - 1];
          --at;
        }
        score[at] = fit;
        out[at] = w;
        offered_[at] = pattern;
      }
    }
    offered_count_ = count;
    const int64_t one = int64_t{1} << 20;
    *certainty = count == 0 ? 0 : (count == 1 || score[0] > 2 * score[1] ? 2 : 0) + (score[0] >= one * 7 / 8 ? 1 : 0);
    return count;
  }

  // After candidates(): which one was right (-1: none); the patterns learn.
  void learn(int position) {
    for (int c = 0; c < offered_count_; ++c) ++offers_[last_][offered_[c]];
    if (position >= 0) ++hits_[last_][offered_[position]];
    last_ = position >= 0 ? offered_[position] : kPatterns;
  }

  // How far back input index i's latest placed neighbour of `vertex` is (0:
  // none placed).
  int32_t latest_gap(int32_t i, int32_t vertex) const {
    int32_t latest = -1;
    for (int32_t e = adj_.start[vertex]; e < adj_.start[vertex + 1]; ++e) latest = std::max(latest, index_of_[adj_.neighbour[e]]);
    return latest < 0 ? 0 : i - latest;
  }

  // After a miss, for a vertex whose latest placed neighbour is input index
  // i - gap: the unplaced neighbours of that one that were not candidates
  // and have no later placed neighbour, in the adjacency's order (at most
  // kMaxCandidates).
  int gap_candidates(int32_t i, int32_t gap, int32_t* out) const {
    int count = 0;
    const int32_t source = vertex_of_[i - gap];
    for (int32_t e = adj_.start[source]; e < adj_.start[source + 1] && count < kMaxCandidates; ++e) {
      const int32_t w = adj_.neighbour[e];
      if (index_of_[w] < 0 && stamp_[w] != i && latest_gap(i, w) == gap) out[count++] = w;
    }
    return count;
  }

  // Input index i names `vertex` (not yet placed).
  void place(int32_t i, int32_t vertex) {
    vertex_of_[i] = vertex;
    index_of_[vertex] = i;
    unplaced_.remove(vertex);
    for (int32_t e = adj_.start[vertex]; e < adj_.start[vertex + 1]; ++e) {
      const int32_t u = adj_.neighbour[e];
      if (index_of_[u] < 0 || u == vertex || i - index_of_[u] > kMaxGap) continue;
      count_gap(i - index_of_[u]);
    }
  }

  int32_t vertex_of(int32_t i) const { return vertex_of_[i]; }
  bool placed(int32_t vertex) const { return index_of_[vertex] >= 0; }
  const UnusedIndices& unplaced() const { return unplaced_; }

 private:
  // One more time gap d joined a vertex to an earlier neighbour; keeps
  // top_gap_ the kSources most frequent gaps, most frequent first.
  void count_gap(int32_t d) {
    const int64_t c = ++gap_count_[d];
    int at = 0;
    while (at < kSources && top_gap_[at] != d) ++at;
    if (at == kSources) {
      if (c <= gap_count_[top_gap_[kSources - 1]]) return;
      at = kSources - 1;
      top_gap_[at] = d;
    }
    while (at > 0 && gap_count_[top_gap_[at - 1]] < c) {
      std::swap(top_gap_[at - 1], top_gap_[at]);
      --at;
    }
  }

  Adjacency adj_;
  std::vector<int32_t> vertex_of_, index_of_, stamp_;
  std::vector<int64_t> gap_count_;
  int32_t top_gap_[kSources];
  static constexpr int kPatterns = 4 << kSources;
  int64_t hits_[kPatterns + 1][kPatterns] = {}, offers_[kPatterns + 1][kPatterns] = {};
  int last_ = kPatterns;  // the previous hit's pattern (kPatterns: a miss)
  int offered_[kMaxCandidates] = {};
  int offered_count_ = 0;
  UnusedIndices unplaced_;
};

// A uniform choice of r in [0, m): its bits from the top, each at the
// probability that the values in [0, m) sharing the bits above give it (a
// bit no value could take costs nothing), so the price is log2 m bits up to
// the 16-bit probabilities' rounding: a shuffled numbering of igea's
// 134,345 vertices costs log2(n!) / 8 + 4 bytes (truncated binary: 0.35%
// more).
// `code(model, bit)` codes one bit, returning it. O(log m).
template <typename CodeBit>
uint32_t code_uniform(uint32_t r, uint32_t m, CodeBit code) {
  if (m <= 1) return 0;
  int bits = 0;
  while (bits < 32 && (uint64_t{1} << bits) < m) ++bits;  // 2^(bits-1) < m <= 2^bits
  uint64_t prefix = 0;  // the value's bits so far, as a number
  for (int b = bits - 1; b >= 0; --b) {
    const uint64_t low = prefix << (b + 1), half = uint64_t{1} << b;
    // Values of [0, m) under this prefix with the next bit 0, and with 1.
    const uint64_t with0 = std::min<uint64_t>(m > low ? m - low : 0, half);
    const uint64_t with1 = std::min<uint64_t>(m > low + half ? m - low - half : 0, half);
    int bit;
    if (with1 == 0) {
      bit = 0;
    } else {
      BitModel model;
      model.p0 = static_cast<uint16_t>(std::min<uint64_t>(
          std::max<uint64_t>(with0 * 65536 / (with0 + with1), BitModel::kMin), BitModel::kMax));
      bit = code(&model, static_cast<int>((r >> b) & 1u));
    }
    prefix = (prefix << 1) | static_cast<uint64_t>(bit);
  }
  return static_cast<uint32_t>(prefix);
}

void encode_uniform(RangeEncoder* enc, uint32_t r, uint32_t m) {
  code_uniform(r, m, [enc](BitModel* model, int bit) {
    enc->encode(model, bit);
    return bit;
  });
}

uint32_t decode_uniform(RangeDecoder* dec, uint32_t m) {
  return code_uniform(0, m, [dec](BitModel* model, int) { return dec->decode(model); });
}

// Input index i against its candidates: the position of its vertex among
// them (0 for none; nothing is coded without candidates), in a context of
// how many there are and whether the first stands out; without a hit, the
// gap back to its latest placed neighbour and its place among that one's
// neighbours that fit (gap_candidates); with no neighbour placed, its rank
// among the unplaced vertices relative to that of the vertex after input
// index i - 1's.
struct OrderModels {
  static constexpr int kContexts = 16;
  static int context(int count, int certainty) { return 4 * std::min(count, 3) + certainty; }
  UIntCoder position{kContexts}, gap, gap_position{3};
  SIntCoder offset;
};

int32_t escape_guess(const OrderWalk& walk, int32_t i, int32_t n) {
  return i > 0 ? std::min(walk.vertex_of(i - 1) + 1, n) : 0;
}

std::vector<uint8_t> encode_with(OrderMode mode, int32_t n, const std::vector<int32_t>& triangles,
                                 const std::vector<int32_t>& original) {
  RangeEncoder enc;
  UIntCoder mode_coder;
  mode_coder.encode(&enc, static_cast<uint32_t>(mode));
  if (mode == OrderMode::kTraversal) return enc.finish();
  if (mode == OrderMode::kUniform) {
    UnusedIndices unused(n);
    for (int32_t k = 0; k < n; ++k) {
      encode_uniform(&enc, static_cast<uint32_t>(unused.rank(original[k])), static_cast<uint32_t>(n - k));
      unused.remove(original[k]);
    }
    return enc.finish();
  }
  std::vector<int32_t> vertex_of(static_cast<size_t>(n));
  for (int32_t k = 0; k < n; ++k) vertex_of[original[k]] = k;
  OrderWalk walk(n, triangles);
  OrderModels models;
  int32_t cands[OrderWalk::kMaxCandidates];
  for (int32_t i = 0; i < n; ++i) {
    const int32_t v = vertex_of[i];
    int certainty = 0;
    const int count = walk.candidates(i, cands, &certainty);
    int position = 0;
    while (position < count && cands[position] != v) ++position;
    if (count > 0) {
      models.position.encode(&enc, position < count ? static_cast<uint32_t>(position + 1) : 0,
                             OrderModels::context(count, certainty));
    }
    walk.learn(position < count ? position : -1);
    if (position == count) {
      int32_t gap = walk.latest_gap(i, v);
      int found = gap > 0 ? walk.gap_candidates(i, gap, cands) : 0, at = 0;
      while (at < found && cands[at] != v) ++at;
      if (at == found) gap = 0;  // beyond kMaxCandidates: by rank, as with no placed neighbour
      models.gap.encode(&enc, static_cast<uint32_t>(gap));
      if (gap == 0) {
        models.offset.encode(&enc, walk.unplaced().rank(v) - walk.unplaced().rank(escape_guess(walk, i, n)));
      } else if (found > 1) {
        models.gap_position.encode(&enc, static_cast<uint32_t>(at), std::min(found, 4) - 2);
      }
    }
    walk.place(i, v);
  }
  return enc.finish();
}

// log2(n!): summed below 16, else Stirling's series to its 1 / (12 n) term
// (relative error under 1e-9). Not std::lgamma: it writes libm's global
// signgam, a data race when two threads encode.
double log2_factorial(int32_t n) {
  if (n < 16) {
    double sum = 0;
    for (int32_t k = 2; k <= n; ++k) sum += std::log2(static_cast<double>(k));
    return sum;
  }
  const double x = n;
  const double pi = 3.14159265358979323846;
  return (x * std::log(x) - x + 0.5 * std::log(2 * pi * x) + 1 / (12 * x)) / std::log(2.0);
}

}  // namespace

std::vector<uint8_t> encode_vertex_order(int32_t n, const std::vector<int32_t>& triangles,
                                         const std::vector<int32_t>& original) {
  bool traversal = true;
  for (int32_t k = 0; k < n && traversal; ++k) traversal = original[k] == k;
  if (traversal) return encode_with(OrderMode::kTraversal, n, triangles, original);
  std::vector<uint8_t> predicted = encode_with(OrderMode::kPredicted, n, triangles, original);
  // The uniform block needs log2(n!) / 8 bytes at least: no need to make it
  // when the prediction is clearly below (the margin keeps the choice the
  // same whatever the libm's last bits).
  const double uniform_at_least = log2_factorial(n) / 8.0;
  if (static_cast<double>(predicted.size()) + 16.0 < uniform_at_least) return predicted;
  std::vector<uint8_t> uniform = encode_with(OrderMode::kUniform, n, triangles, original);
  return predicted.size() <= uniform.size() ? predicted : uniform;
}

Status decode_vertex_order(const uint8_t* data, size_t size, int32_t n, const std::vector<int32_t>& triangles,
                           std::vector<int32_t>* original) {
  auto corrupt = [](const std::string& what) {
    return Status::Error(StatusCode::kParseError, "vertex order: " + what);
  };
  if (n < 1) return Status::Error(StatusCode::kInvalidArgument, "vertex order: bad vertex count");
  RangeDecoder dec(data, size);
  UIntCoder mode_coder;
  const uint32_t mode = mode_coder.decode(&dec);
  original->assign(static_cast<size_t>(n), 0);
  if (mode == static_cast<uint32_t>(OrderMode::kTraversal)) {
    for (int32_t k = 0; k < n; ++k) (*original)[k] = k;
  } else if (mode == static_cast<uint32_t>(OrderMode::kPredicted) ||
             mode == static_cast<uint32_t>(OrderMode::kUniform)) {
    if (mode == static_cast<uint32_t>(OrderMode::kUniform)) {
      UnusedIndices unused(n);
      for (int32_t k = 0; k < n; ++k) {
        (*original)[k] = unused.select(static_cast<int32_t>(decode_uniform(&dec, static_cast<uint32_t>(n - k))));
        unused.remove((*original)[k]);
      }
    } else {
      OrderWalk walk(n, triangles);
      OrderModels models;
      int32_t cands[OrderWalk::kMaxCandidates];
      for (int32_t i = 0; i < n; ++i) {
        int certainty = 0;
        const int count = walk.candidates(i, cands, &certainty);
        const uint32_t position = count > 0 ? models.position.decode(&dec, OrderModels::context(count, certainty)) : 0;
        if (position > static_cast<uint32_t>(count)) return corrupt("candidate out of range");
        int32_t v;
        const uint32_t gap = position > 0 ? 0 : models.gap.decode(&dec);
        if (gap > static_cast<uint32_t>(i)) return corrupt("gap out of range");
        walk.learn(static_cast<int>(position) - 1);
        if (position > 0) {
          v = cands[position - 1];
        } else if (gap > 0) {
          const int found = walk.gap_candidates(i, static_cast<int32_t>(gap), cands);
          const uint32_t at = found > 1 ? models.gap_position.decode(&dec, std::min(found, 4) - 2) : 0;
          if (at >= static_cast<uint32_t>(found)) return corrupt("gap candidate out of range");
          v = cands[at];
        } else {
          const int64_t rank = static_cast<int64_t>(walk.unplaced().rank(escape_guess(walk, i, n))) +
                               models.offset.decode(&dec);
          if (rank < 0 || rank >= n - i) return corrupt("vertex rank out of range");
          v = walk.unplaced().select(static_cast<int32_t>(rank));
        }
        (*original)[v] = i;
        walk.place(i, v);
      }
    }
  } else {
    return corrupt("unknown mode " + std::to_string(mode));
  }
  if (dec.overrun()) return corrupt("stream truncated");
  if (dec.bytes_consumed() != size) return corrupt("trailing bytes");
  return Status::Ok();
}

}  // namespace gab
