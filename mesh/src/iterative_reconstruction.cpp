#include "gab/mesh/iterative_reconstruction.h"

#include <algorithm>
#include <cmath>
#include <condition_variable>
#include <cstddef>
#include <cstring>
#include <functional>
#include <limits>
#include <mutex>
#include <string>
#include <system_error>
#include <thread>

#include "anchor_checks.h"
#include "degree_runs.h"

namespace gab {

namespace {

// Four lanes, three used: a vertex's x, y, z (GCC and Clang vector
// extensions; each lane rounds exactly as scalar code would). They stay
// inside this file, so the note that their ABI depends on -mavx does not
// apply.
#if defined(__clang__)
#pragma clang diagnostic ignored "-Wpsabi"
#elif defined(__GNUC__)
#pragma GCC diagnostic ignored "-Wpsabi"
#endif
typedef float v4f __attribute__((vector_size(16)));
typedef double v4d __attribute__((vector_size(32)));
typedef double v2d __attribute__((vector_size(16)));

inline v2d load2(const double* p) {
  v2d r;
  std::memcpy(&r, p, sizeof r);
  return r;
}
inline void store2(double* p, v2d x) { std::memcpy(p, &x, sizeof x); }

// 1 / d in single precision for a vertex of degree d (the double quotient
// rounded to float).
class Reciprocals {
 public:
  Reciprocals() {
    for (int32_t d = 1; d < kCached; ++d) cached_[d] = static_cast<float>(1.0 / d);
  }
  float operator()(int32_t d) const { return d < kCached ? cached_[d] : static_cast<float>(1.0 / d); }

 private:
  static constexpr int32_t kCached = 64;
  float cached_[kCached] = {};
};
const Reciprocals kReciprocal;

inline v4f load4(const float* p) {
  v4f r;
  std::memcpy(&r, p, sizeof r);
  return r;
}

// Operator 2's harmonic sweep at a free vertex v (4 floats: x, y, z, 0)
// from the values `from` (4 per vertex), in single precision: its
// neighbours summed in two chains (even and odd places in adjacency order,
// each from 0: half the wait on the additions), (even + odd) times the
// reciprocal of its degree. D: v's degree when known here (DegreeRuns), 0
// when not.
template <int32_t D = 0>
inline void harmonic_row_float(const EdgeGraph& g, const float* from, int32_t v, float* to) {
  const int32_t first = g.offsets[v];
  const int32_t degree = D > 0 ? D : g.offsets[v + 1] - first;
  const int32_t* neighbors = g.neighbors.data() + first;
  v4f even = {0.0f, 0.0f, 0.0f, 0.0f}, odd = even;
  int32_t e = 0;
  for (; e + 1 < degree; e += 2) {
    even += load4(from + 4 * static_cast<size_t>(neighbors[e]));
    odd += load4(from + 4 * static_cast<size_t>(neighbors[e + 1]));
  }
  if (e < degree) even += load4(from + 4 * static_cast<size_t>(neighbors[e]));
  const v4f out = (even + odd) * kReciprocal(degree);
  std::memcpy(to, &out, sizeof out);
}

// Operator 1's harmonic sweep at a free vertex v (4 doubles: x, y, z, 0)
// from the values `from` (4 per vertex): its neighbours' sum in adjacency
// order from 0, each lane rounding as scalar code would, divided by the
// degree. Two halves of two doubles: native on every x86-64, where a
// 32-byte vector without AVX goes through memory.
inline void harmonic_row(const EdgeGraph& g, const double* from, int32_t v, double* to) {
  const int32_t first = g.offsets[v], last = g.offsets[v + 1];
  v2d xy = {0.0, 0.0}, z0 = xy;
  for (int32_t e = first; e < last; ++e) {
    const double* u = from + 4 * static_cast<size_t>(g.neighbors[e]);
    xy += load2(u);
    z0 += load2(u + 2);
  }
  const double d = static_cast<double>(last - first);
  store2(to, xy / d);
  store2(to + 2, z0 / d);
}

// x rounded to single precision; past its range, the infinity of x's sign
// (a plain conversion would be undefined there), which a decoder then
// refuses as a non-finite shape.
float to_float(double x) {
  if (x > std::numeric_limits<float>::max()) return std::numeric_limits<float>::infinity();
  if (x < -std::numeric_limits<float>::max()) return -std::numeric_limits<float>::infinity();
  return static_cast<float>(x);
}

// The threads of one solve: run(job) calls job(begin, end, b) for every
// block b of kBlock vertices (vertices [begin, end)), each member of the team
// taking a fixed range of blocks, and returns when all are done. Helpers the
// system refuses (an address-space cap maps each stack) leave a smaller
// team: the blocks split among fewer members, the same results.
class StepTeam {
 public:
  using Job = std::function<void(int32_t, int32_t, int32_t)>;

  StepTeam(int32_t threads, int32_t vertices)
      : blocks_((vertices + IterativeReconstruction::kBlock - 1) / IterativeReconstruction::kBlock),
        vertices_(vertices) {
    const int32_t wanted = std::max(1, std::min(threads, blocks_));
    for (int32_t member = 1; member < wanted; ++member) {
#if defined(__cpp_exceptions)
      try {
        helpers_.emplace_back([this, member] { serve(member); });
      } catch (const std::system_error&) {
        break;
      }
#else
      helpers_.emplace_back([this, member] { serve(member); });  // built without exceptions: a refusal ends the process
#endif
    }
    size_ = 1 + static_cast<int32_t>(helpers_.size());
  }
  ~StepTeam() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stopping_ = true;
    }
    start_.notify_all();
    for (std::thread& t : helpers_) t.join();
  }
  StepTeam(const StepTeam&) = delete;
  StepTeam& operator=(const StepTeam&) = delete;

  void run(const Job& job) {
    if (size_ == 1) {
      work(job, 0);
      return;
    }
    {
      std::lock_guard<std::mutex> lock(mutex_);
      job_ = &job;
      pending_ = size_ - 1;
      ++generation_;
    }
    start_.notify_all();
    work(job, 0);
    std::unique_lock<std::mutex> lock(mutex_);
    done_.wait(lock, [this] { return pending_ == 0; });
  }

 private:
  void work(const Job& job, int32_t member) const {
    const int32_t first = static_cast<int32_t>(static_cast<int64_t>(blocks_) * member / size_);
    const int32_t last = static_cast<int32_t>(static_cast<int64_t>(blocks_) * (member + 1) / size_);
    for (int32_t b = first; b < last; ++b) job(b * IterativeReconstruction::kBlock, end_of(b), b);
  }
  int32_t end_of(int32_t b) const { return std::min(vertices_, (b + 1) * IterativeReconstruction::kBlock); }
  void serve(int32_t member) {
    uint64_t seen = 0;
    for (;;) {
      const Job* job = nullptr;
      {
        std::unique_lock<std::mutex> lock(mutex_);
        start_.wait(lock, [&] { return stopping_ || generation_ != seen; });
        if (stopping_) return;
        seen = generation_;
        job = job_;
      }
      work(*job, member);
      {
        std::lock_guard<std::mutex> lock(mutex_);
        --pending_;
      }
      done_.notify_one();
    }
  }

  const int32_t blocks_, vertices_;
  int32_t size_ = 1;
  std::vector<std::thread> helpers_;
  std::mutex mutex_;
  std::condition_variable start_, done_;
  const Job* job_ = nullptr;
  uint64_t generation_ = 0;
  int32_t pending_ = 0;
  bool stopping_ = false;
};

}  // namespace

Status IterativeReconstruction::check_new(const std::vector<int32_t>& anchors,
                                          const std::vector<double>& coefficients) {
  return check_new_anchors<int32_t>(anchors, coefficients, &anchor_of_, -1, -2);
}

void IterativeReconstruction::record(const std::vector<int32_t>& anchors, const std::vector<double>& coefficients) {
  for (size_t i = 0; i < anchors.size(); ++i) {
    anchor_of_[anchors[i]] = static_cast<int32_t>(anchors_.size());
    anchors_.push_back(anchors[i]);
    coefficients_.insert(coefficients_.end(), &coefficients[3 * i], &coefficients[3 * i] + 3);
  }
}

Status IterativeReconstruction::init(const EdgeGraph& graph, double weight, const std::vector<int32_t>& anchors,
                                     const std::vector<double>& coefficients) {
  return init_with(graph, weight, anchors, coefficients, nullptr);
}

Status IterativeReconstruction::init(const EdgeGraph& graph, double weight, const std::vector<int32_t>& anchors,
                                     const std::vector<double>& coefficients, const std::vector<uint64_t>& nearest) {
  if (rule_ != NearestRule::kFewestHopsLowest) {
    return Status::Error(StatusCode::kInvalidArgument, "a nearest map needs the fewest-hops nearest rule");
  }
  return init_with(graph, weight, anchors, coefficients, &nearest);
}

Status IterativeReconstruction::init_with(const EdgeGraph& graph, double weight, const std::vector<int32_t>& anchors,
                                          const std::vector<double>& coefficients,
                                          const std::vector<uint64_t>* nearest) {
  if (!(weight > 0.0) || !std::isfinite(weight)) {
    return Status::Error(StatusCode::kInvalidArgument, "anchor weight must be positive and finite");
  }
  graph_ = &graph;
  n_ = graph.num_vertices();
  weight_ = weight;
  anchors_.clear();
  coefficients_.clear();
  shape_.clear();
  anchor_of_.assign(n_, -1);
  GAB_RETURN_IF_ERROR(check_new(anchors, coefficients));
  if (rule_ == NearestRule::kDiscovery) {
    GAB_RETURN_IF_ERROR(check_components_anchored(graph, anchors));
    record(anchors, coefficients);
    return Status::Ok();
  }
  // The nearest anchors' search reaches every vertex of an anchored
  // component: the first one it misses names the component without one (as
  // check_components_anchored would), with no pass of its own.
  record(anchors, coefficients);
  const Status taken = nearest ? take_nearest(*nearest) : Status::Ok();
  if (!taken.ok()) {
    graph_ = nullptr;
    return taken;
  }
  if (!nearest) {
    nearest_.assign(n_, std::numeric_limits<uint64_t>::max());
    update_nearest(anchors);
  }
  for (int32_t v = 0; v < n_; ++v) {
    if (nearest_[v] == std::numeric_limits<uint64_t>::max()) {
      graph_ = nullptr;
      return Status::Error(StatusCode::kInvalidArgument, "the connected component of vertex " + std::to_string(v) +
                                                             " has no anchor (every component needs one)");
    }
  }
  return Status::Ok();
}

Status IterativeReconstruction::take_nearest(const std::vector<uint64_t>& nearest) {
  if (nearest.size() != static_cast<size_t>(n_)) {
    return Status::Error(StatusCode::kInvalidArgument, "a nearest map needs one entry per vertex");
  }
  // Each entry must name an anchor (or none: an unanchored component, which
  // init reports); the hops are the caller's word.
  for (uint64_t key : nearest) {
    const uint64_t a = key & 0xffffffffu;
    if (key != std::numeric_limits<uint64_t>::max() && (a >= static_cast<uint64_t>(n_) || anchor_of_[a] < 0)) {
      return Status::Error(StatusCode::kInvalidArgument, "the nearest map names a vertex that is not an anchor");
    }
  }
  nearest_ = nearest;
  return Status::Ok();
}

Status IterativeReconstruction::set_start_sweeps(int32_t prediction, int32_t final) {
  if (prediction < 0 || prediction > kMostStartSweeps || final < 0 || final > kMostStartSweeps) {
    return Status::Error(StatusCode::kInvalidArgument,
                         "start sweeps must be in 0.." + std::to_string(kMostStartSweeps));
  }
  prediction_sweeps_ = prediction;
  final_sweeps_ = final;
  return Status::Ok();
}

Status IterativeReconstruction::add_anchors(const std::vector<int32_t>& anchors,
                                            const std::vector<double>& coefficients) {
  if (graph_ == nullptr) return Status::Error(StatusCode::kInvalidArgument, "add_anchors before init");
  GAB_RETURN_IF_ERROR(check_new(anchors, coefficients));
  record(anchors, coefficients);
  update_nearest(anchors);
  return Status::Ok();
}

Status IterativeReconstruction::add_anchors(const std::vector<int32_t>& anchors,
                                            const std::vector<double>& coefficients,
                                            const std::vector<uint64_t>& nearest) {
  if (graph_ == nullptr) return Status::Error(StatusCode::kInvalidArgument, "add_anchors before init");
  if (rule_ != NearestRule::kFewestHopsLowest) {
    return Status::Error(StatusCode::kInvalidArgument, "a nearest map needs the fewest-hops nearest rule");
  }
  GAB_RETURN_IF_ERROR(check_new(anchors, coefficients));
  const size_t before = anchors_.size();
  record(anchors, coefficients);
  const Status taken = take_nearest(nearest);
  if (!taken.ok()) {  // as before the call
    for (int32_t a : anchors) anchor_of_[a] = -1;
    anchors_.resize(before);
    coefficients_.resize(3 * before);
  }
  return taken;
}

void IterativeReconstruction::update_nearest(const std::vector<int32_t>& anchors) {
  if (rule_ != NearestRule::kFewestHopsLowest) return;
  // Layer by layer from the new anchors, a vertex whose (hops, anchor) the
  // layer lowers joins the next frontier (again if lowered twice: its final
  // key is what it passes on). A vertex the new anchors do not reach first
  // cannot pass them on: whoever is nearer to it is at least as near to its
  // neighbours. Within a layer the lowest anchor wins whatever the
  // frontier's order, so the result is the rule's. One key per vertex,
  // (hops << 32) | anchor, compares both at once.
  //
  // A vertex lowered twice in a layer joins the next frontier once (a bit
  // per vertex marks it). A frontier of many vertices is taken in vertex
  // order, read off those bits: its neighbours' keys are then near in
  // memory, where the order of discovery scatters them (igea, anchors 2-7%
  // of its vertices: 1.7-2x faster). A small one is taken as found: reading
  // the bits costs n / 64 words, at most 8 per vertex taken.
  const EdgeGraph& g = *graph_;
  std::vector<int32_t> frontier, next;
  std::vector<uint64_t> joined((static_cast<size_t>(n_) + 63) / 64, 0);
  for (int32_t a : anchors) {
    nearest_[a] = static_cast<uint64_t>(a);
    frontier.push_back(a);
  }
  for (uint64_t layer = 1; !frontier.empty(); ++layer) {
    next.clear();
    for (int32_t u : frontier) {
      const uint64_t key = (layer << 32) | (nearest_[u] & 0xffffffffu);
      for (int32_t e = g.offsets[u]; e < g.offsets[u + 1]; ++e) {
        const int32_t w = g.neighbors[e];
        if (key >= nearest_[w]) continue;
        nearest_[w] = key;
        uint64_t& word = joined[static_cast<size_t>(w) >> 6];
        const uint64_t bit = uint64_t{1} << (w & 63);
        if (word & bit) continue;
        word |= bit;
        next.push_back(w);
      }
    }
    if (next.size() * 8 >= joined.size()) {
      next.clear();
      for (size_t i = 0; i < joined.size(); ++i) {
        for (uint64_t word = joined[i]; word != 0; word &= word - 1) {
          next.push_back(static_cast<int32_t>(64 * i + static_cast<size_t>(__builtin_ctzll(word))));
        }
        joined[i] = 0;
      }
    } else {
      for (int32_t w : next) joined[static_cast<size_t>(w) >> 6] = 0;
    }
    frontier.swap(next);
  }
}

Status IterativeReconstruction::set_coefficients(int32_t first, const std::vector<double>& coefficients) {
  if (first < 0 || coefficients.size() % 3 != 0 ||
      static_cast<size_t>(first) + coefficients.size() / 3 > anchors_.size()) {
    return Status::Error(StatusCode::kInvalidArgument, "coefficients past the last anchor");
  }
  GAB_RETURN_IF_ERROR(check_anchor_coefficients(coefficients.size() / 3, coefficients));
  std::copy(coefficients.begin(), coefficients.end(), coefficients_.begin() + 3 * static_cast<size_t>(first));
  return Status::Ok();
}

Status IterativeReconstruction::set_start(const std::vector<double>& positions) {
  if (positions.size() != 3 * static_cast<size_t>(n_)) {
    return Status::Error(StatusCode::kInvalidArgument, "a start needs 3 coordinates per vertex");
  }
  for (double x : positions) {
    if (!std::isfinite(x)) return Status::Error(StatusCode::kInvalidArgument, "a start coordinate is not finite");
  }
  shape_ = positions;
  return Status::Ok();
}

std::vector<double> IterativeReconstruction::nearest_anchor_shape() const {
  std::vector<double> shape(3 * static_cast<size_t>(n_));
  if (rule_ == NearestRule::kFewestHopsLowest) {
    for (int32_t v = 0; v < n_; ++v) {
      const double* c = &coefficients_[3 * static_cast<size_t>(anchor_of_[nearest_anchor(v)])];
      std::copy(c, c + 3, shape.begin() + 3 * static_cast<std::ptrdiff_t>(v));
    }
    return shape;
  }
  const EdgeGraph& g = *graph_;
  std::vector<int32_t> source(n_, -1), frontier = anchors_, next;
  std::sort(frontier.begin(), frontier.end());
  for (int32_t a : frontier) source[a] = anchor_of_[a];
  while (!frontier.empty()) {
    next.clear();
    for (int32_t u : frontier) {
      for (int32_t p = g.offsets[u]; p < g.offsets[u + 1]; ++p) {
        const int32_t w = g.neighbors[p];
        if (source[w] >= 0) continue;
        source[w] = source[u];
        next.push_back(w);
      }
    }
    frontier.swap(next);
  }
  for (int32_t v = 0; v < n_; ++v) {
    const double* c = &coefficients_[3 * static_cast<size_t>(source[v])];
    std::copy(c, c + 3, shape.begin() + 3 * static_cast<std::ptrdiff_t>(v));
  }
  return shape;
}

Status IterativeReconstruction::start_at(const std::vector<int32_t>& at, std::vector<double>* positions) {
  return start_values(&at, prediction_sweeps_, positions);
}

Status IterativeReconstruction::start(std::vector<double>* positions) {
  return start_values(nullptr, prediction_sweeps_, positions);
}

Status IterativeReconstruction::start_values(const std::vector<int32_t>* at_or_all, int32_t sweeps,
                                             std::vector<double>* positions) {
  if (graph_ == nullptr) return Status::Error(StatusCode::kInvalidArgument, "start_at before init");
  if (rule_ != NearestRule::kFewestHopsLowest) {
    return Status::Error(StatusCode::kInvalidArgument, "start_at needs the fewest-hops nearest rule");
  }
  const size_t n = static_cast<size_t>(n_);
  if (positions->size() != 3 * n) return Status::Error(StatusCode::kInvalidArgument, "positions need 3 per vertex");
  const std::vector<int32_t> none;
  const std::vector<int32_t>& at = at_or_all ? *at_or_all : none;
  for (int32_t v : at) {
    if (v < 0 || v >= n_) return Status::Error(StatusCode::kInvalidArgument, "start_at: vertex out of range");
  }
  const EdgeGraph& g = *graph_;
  if (from_.size() != 4 * n) {
    from_.resize(4 * n);
    to_.resize(4 * n);
  }
  // The values in single precision, per axis in the anchors' frame: values
  // in [0, 1], whatever the coordinates' magnitude.
  double origin[3], scale[3];
  start_frame(origin, scale);
  float* from = from_.data();
  float* to = to_.data();
  const int32_t* anchor_of = anchor_of_.data();
  auto fixed = [&](int32_t v) { return anchor_of[v] >= 0 || g.offsets[v] == g.offsets[v + 1]; };
  auto start = [&](int32_t v) {
    const double* c = &coefficients_[3 * static_cast<size_t>(anchor_of[nearest_anchor(v)])];
    float* x = from + 4 * static_cast<size_t>(v);
    for (int k = 0; k < 3; ++k) x[k] = to_float((c[k] - origin[k]) * scale[k]);
    x[3] = 0.0f;
    // An anchor and a vertex of degree 0 keep their value through the
    // sweeps: in both buffers.
    if (fixed(v)) std::copy(x, x + 4, to + 4 * static_cast<size_t>(v));
  };
  // Sweep s needs its values within `sweeps` - s hops of `at` and reads
  // one hop further. Vertices whose neighbourhoods (about `ball` vertices
  // each, a regular triangulation's) would cover half the mesh: every
  // vertex is swept, in vertex order (neighbours near in memory), by blocks
  // on the threads; the values at `at` are the same. Fewer: only those
  // within reach, found breadth-first. (The neighbourhoods overlap, and a
  // row swept in breadth-first order costs about twice one in vertex
  // order: from half, feline's and horse's two smallest levels' starts
  // 6.9 -> 1.9 and 3.9 -> 1.8 ms, their other starts the same.)
  const size_t ball = 3 * static_cast<size_t>(sweeps) * static_cast<size_t>(sweeps + 1) + 1;
  if (!at_or_all || 2 * at.size() * ball >= n) {
    // Each anchor's value made once, every vertex a copy of its nearest's
    // (start(v) for every v, the same bits).
    std::vector<float> anchor_start(4 * anchors_.size());
    for (size_t a = 0; a < anchors_.size(); ++a) {
      for (int k = 0; k < 3; ++k) anchor_start[4 * a + k] = to_float((coefficients_[3 * a + k] - origin[k]) * scale[k]);
    }
    // The free vertices grouped by degree, block by block (DegreeRuns).
    StepTeam team(threads_, n_);
    DegreeRuns free_runs;
    free_runs.resize(n_, kBlock);
    team.run([&](int32_t begin, int32_t end, int32_t b) {
      for (int32_t v = begin; v < end; ++v) {
        const float* value = &anchor_start[4 * static_cast<size_t>(anchor_of[nearest_anchor(v)])];
        std::copy(value, value + 4, from + 4 * static_cast<size_t>(v));
        if (fixed(v)) std::copy(value, value + 4, to + 4 * static_cast<size_t>(v));
      }
      free_runs.fill(g, b, begin, end, [&](int32_t v) { return !fixed(v); });
    });
    for (int sweep = 1; sweep <= sweeps; ++sweep) {
      if (sweep == sweeps && at_or_all) {
        // The last sweep's values are read at `at` alone.
        for (int32_t v : at) {
          if (!fixed(v)) harmonic_row_float(g, from, v, to + 4 * static_cast<size_t>(v));
        }
      } else {
        team.run([&](int32_t, int32_t, int32_t b) {
          free_runs.visit(b, [&](auto degree, int32_t v) {
            harmonic_row_float<decltype(degree)::value>(g, from, v, to + 4 * static_cast<size_t>(v));
          });
        });
      }
      std::swap(from, to);
    }
  } else {
    if (reached_.size() != n) {
      reached_.assign(n, 0);
      depth_.assign(n, 0);
      call_ = 0;
    }
    if (++call_ == 0) {  // the marks wrapped: clear them
      std::fill(reached_.begin(), reached_.end(), 0u);
      call_ = 1;
    }
    // The vertices within `sweeps` hops of `at`, breadth-first (so in
    // increasing hops), each with its hops.
    std::vector<int32_t> region;
    for (int32_t v : at) {
      if (reached_[v] == call_) continue;
      reached_[v] = call_;
      depth_[v] = 0;
      region.push_back(v);
    }
    for (size_t i = 0; i < region.size(); ++i) {
      const int32_t u = region[i];
      if (depth_[u] == sweeps) break;
      for (int32_t e = g.offsets[u]; e < g.offsets[u + 1]; ++e) {
        const int32_t w = g.neighbors[e];
        if (reached_[w] == call_) continue;
        reached_[w] = call_;
        depth_[w] = static_cast<int8_t>(depth_[u] + 1);
        region.push_back(w);
      }
    }
    std::vector<int32_t> free;  // in increasing hops
    for (int32_t v : region) {
      start(v);
      if (!fixed(v) && depth_[v] < sweeps) free.push_back(v);
    }
    for (int sweep = 1; sweep <= sweeps; ++sweep) {
      const int8_t reach = static_cast<int8_t>(sweeps - sweep);
      for (int32_t v : free) {
        if (depth_[v] > reach) break;
        harmonic_row_float(g, from, v, to + 4 * static_cast<size_t>(v));
      }
      std::swap(from, to);
    }
  }
  auto put = [&](int32_t v) {
    for (int k = 0; k < 3; ++k) {
      (*positions)[3 * static_cast<size_t>(v) + k] =
          origin[k] + static_cast<double>(from[4 * static_cast<size_t>(v) + k]) / scale[k];
    }
  };
  if (at_or_all) {
    for (int32_t v : at) put(v);
  } else {
    for (int32_t v = 0; v < n_; ++v) put(v);
  }
  return Status::Ok();
}

void IterativeReconstruction::start_frame(double origin[3], double scale[3]) const {
  double high[3];
  for (int k = 0; k < 3; ++k) origin[k] = high[k] = coefficients_[k];
  for (size_t i = 0; i < coefficients_.size(); i += 3) {
    for (int k = 0; k < 3; ++k) {
      origin[k] = std::min(origin[k], coefficients_[i + k]);
      high[k] = std::max(high[k], coefficients_[i + k]);
    }
  }
  for (int k = 0; k < 3; ++k) {
    int exponent = 0;
    std::frexp(high[k] - origin[k], &exponent);  // the extent = m 2^exponent, m in [0.5, 1); 0 for 0
    scale[k] = std::ldexp(1.0, -exponent);
  }
}

Status IterativeReconstruction::solve(int32_t steps, std::vector<double>* positions) {
  if (graph_ == nullptr) return Status::Error(StatusCode::kInvalidArgument, "solve before init");
  if (steps < 0) return Status::Error(StatusCode::kInvalidArgument, "negative step count");
  const bool fresh = shape_.empty();
  const size_t n = static_cast<size_t>(n_);
  if (fresh && rule_ == NearestRule::kFewestHopsLowest) {
    // Operator 2's start, at every vertex, with the final shape's sweeps.
    shape_.resize(3 * n);
    GAB_RETURN_IF_ERROR(start_values(nullptr, final_sweeps_, &shape_));
    // Its buffers are not needed again before the next prediction: not
    // beside the steps' own (the decode's peak).
    std::vector<float>().swap(from_);
    std::vector<float>().swap(to_);
  } else if (fresh) {
    shape_ = nearest_anchor_shape();
  }
  const double w2 = weight_ * weight_;
  const int32_t blocks = (n_ + kBlock - 1) / kBlock;
  double* x = shape_.data();
  const int32_t* offsets = graph_->offsets.data();
  const int32_t* neighbors = graph_->neighbors.data();
  const int32_t* anchor_of = anchor_of_.data();
  // Every pass below runs over whole blocks, in parallel; a block's sums go
  // to partial[b], added in block order afterwards (the order the header
  // promises for any thread count).
  StepTeam team(threads_, n_);
  if (fresh && rule_ == NearestRule::kDiscovery) {
    // The nearest-anchor start is flat between anchors: kStartSweeps Jacobi
    // sweeps of the harmonic interpolation (each free vertex to its
    // neighbours' mean, anchors at their coefficients) round it off for
    // the price of a few steps and save more at a few steps per spacing
    // (horse, anchors 3 hops apart: 4 sweeps + 16 steps as near the least
    // squares as 24 steps alone, bench/reconstruction_candidates).
    std::vector<double> from(4 * n), to(4 * n);
    for (size_t v = 0; v < n; ++v) std::copy(&shape_[3 * v], &shape_[3 * v] + 3, &from[4 * v]);
    for (int sweep = 0; sweep < kStartSweeps; ++sweep) {
      const double* in = from.data();
      team.run([&](int32_t begin, int32_t end, int32_t) {
        for (int32_t v = begin; v < end; ++v) {
          double* out = &to[4 * static_cast<size_t>(v)];
          if (anchor_of[v] >= 0 || offsets[v] == offsets[v + 1]) {
            std::copy(in + 4 * static_cast<size_t>(v), in + 4 * static_cast<size_t>(v) + 4, out);
          } else {
            harmonic_row(*graph_, in, v, out);
          }
        }
      });
      from.swap(to);
    }
    for (size_t v = 0; v < n; ++v) std::copy(&from[4 * v], &from[4 * v] + 3, &shape_[3 * v]);
    x = shape_.data();
  }
  std::vector<v4d> partial(blocks);
  auto total = [&]() {
    v4d s = {0.0, 0.0, 0.0, 0.0};
    for (int32_t b = 0; b < blocks; ++b) s += partial[b];
    return s;
  };
  // A block's sum of a per-vertex v4f term: runs of kRun vertices summed in
  // single precision, the runs' sums in double (cheap, and the sums' rounding
  // stays far below what the steps need).
  constexpr int32_t kRun = 64;
  auto block_sum = [](int32_t begin, int32_t end, const auto& term_of, v4d* sum) {
    *sum = v4d{0.0, 0.0, 0.0, 0.0};
    for (int32_t run = begin; run < end; run += kRun) {
      v4f s = {0.0f, 0.0f, 0.0f, 0.0f};
      for (int32_t v = run; v < std::min(end, run + kRun); ++v) s += term_of(v);
      *sum += __builtin_convertvector(s, v4d);
    }
  };
  // The steps run on the residual scaled by a power of two, `scale`, that
  // brings its largest entry into [0.5, 1): single precision then neither
  // overflows nor underflows whatever the coordinates' magnitude, and the
  // scaling itself rounds nothing. The correction is divided by it at the end.
  double scale = 1.0;
  // The products by L row by row in groups of one degree (DegreeRuns).
  DegreeRuns runs;
  runs.resize(n_, kBlock);
  team.run([&](int32_t begin, int32_t end, int32_t b) { runs.fill(*graph_, b, begin, end, [](int32_t) { return true; }); });
  // r = w^2 S c - (L^T L + w^2 S) x, in double (L x first, freed after),
  // and per block its largest |entry| (a maximum is the same in any order).
  // Each vertex's four doubles in two halves of two (x y, z 0): in
  // registers on every x86-64, each lane rounding as with one vector of four.
  std::vector<v4d> residual(n);
  {
    std::vector<v4d> lx(n);
    double* lx_at = reinterpret_cast<double*>(lx.data());
    double* residual_at = reinterpret_cast<double*>(residual.data());
    auto xy_of = [x](int32_t v) { return load2(x + 3 * static_cast<size_t>(v)); };
    auto z0_of = [x](int32_t v) { return v2d{x[3 * static_cast<size_t>(v) + 2], 0.0}; };
    // Degree: v's when known here, 0 when not.
    auto lx_row = [&](auto degree_known, int32_t v) {
      const int32_t first = offsets[v];
      const int32_t degree = DegreeRuns::degree(degree_known, offsets, v);
      const double d = static_cast<double>(degree);
      v2d xy = d * xy_of(v), z0 = d * z0_of(v);
      for (int32_t e = first; e < first + degree; ++e) {
        xy -= xy_of(neighbors[e]);
        z0 -= z0_of(neighbors[e]);
      }
      store2(lx_at + 4 * static_cast<size_t>(v), xy);
      store2(lx_at + 4 * static_cast<size_t>(v) + 2, z0);
    };
    // -L (L x), the anchors' term after (the same operations in the same
    // order at each vertex).
    auto residual_row = [&](auto degree_known, int32_t v) {
      const int32_t first = offsets[v];
      const int32_t degree = DegreeRuns::degree(degree_known, offsets, v);
      const double d = static_cast<double>(degree);
      const double* own = lx_at + 4 * static_cast<size_t>(v);
      v2d xy = d * load2(own), z0 = d * load2(own + 2);
      for (int32_t e = first; e < first + degree; ++e) {
        const double* u = lx_at + 4 * static_cast<size_t>(neighbors[e]);
        xy -= load2(u);
        z0 -= load2(u + 2);
      }
      store2(residual_at + 4 * static_cast<size_t>(v), -xy);
      store2(residual_at + 4 * static_cast<size_t>(v) + 2, -z0);
    };
    team.run([&](int32_t, int32_t, int32_t b) { runs.visit(b, lx_row); });
    team.run([&](int32_t, int32_t, int32_t b) { runs.visit(b, residual_row); });
  }
  // + w^2 (c - x) at the anchors.
  for (size_t i = 0; i < anchors_.size(); ++i) {
    const int32_t v = anchors_[i];
    double* at = reinterpret_cast<double*>(residual.data()) + 4 * static_cast<size_t>(v);
    const double* c = &coefficients_[3 * i];
    store2(at, load2(at) + w2 * (load2(c) - load2(x + 3 * static_cast<size_t>(v))));
    store2(at + 2, load2(at + 2) + w2 * (v2d{c[2], 0.0} - v2d{x[3 * static_cast<size_t>(v) + 2], 0.0}));
  }
  team.run([&](int32_t begin, int32_t end, int32_t b) {
    double largest = 0.0;
    for (int32_t v = begin; v < end; ++v) {
      const v4d& rv = residual[v];
      largest = std::max({largest, std::fabs(rv[0]), std::fabs(rv[1]), std::fabs(rv[2])});
    }
    partial[b] = v4d{largest, 0.0, 0.0, 0.0};
  });
  double largest = 0.0;
  for (int32_t b = 0; b < blocks; ++b) largest = std::max(largest, partial[b][0]);
  if (largest > 0.0 && std::isfinite(largest)) {
    int exponent = 0;
    std::frexp(largest, &exponent);  // largest = m 2^exponent, m in [0.5, 1)
    scale = std::ldexp(1.0, -exponent);
  }
  // The recurrences' vectors in single precision, a vertex's three columns
  // and a zero lane in 16 bytes (one load per neighbour in the products):
  // floats move half the bytes of doubles and the steps are bound by moving
  // them. The shape and the first residual stay double: the steps' rounding
  // bends only the correction they add, not the shape it is added to.
  // q, t and the correction come after the double residual is freed: not
  // all at once (the decode's peak).
  std::vector<v4f> r(n), p(n);
  std::vector<float> inv_diag(n);  // 1 / diag(L^T L + w^2 S); (L^T L)_vv = d^2 + d
  team.run([&](int32_t begin, int32_t end, int32_t b) {
    block_sum(begin, end, [&](int32_t v) {
      const double d = offsets[v + 1] - offsets[v];
      inv_diag[v] = static_cast<float>(1.0 / (d * d + d + (anchor_of[v] >= 0 ? w2 : 0.0)));
      r[v] = __builtin_convertvector(scale * residual[v], v4f);
      p[v] = inv_diag[v] * r[v];
      return r[v] * p[v];
    }, &partial[b]);
  });
  std::vector<v4d>().swap(residual);
  std::vector<v4f> q(n), t(n);
  v4d rz = total();
  // (L in)_v: the neighbours summed in two chains (even and odd places),
  // which halves the wait on the additions.
  // Degree: v's when known here (DegreeRuns), 0 when not.
  auto laplacian_row = [offsets, neighbors](const v4f* in, int32_t v, auto degree_known) {
    const int32_t first = offsets[v];
    const int32_t degree = DegreeRuns::degree(degree_known, offsets, v);
    const int32_t* around = neighbors + first;
    v4f even = {0.0f, 0.0f, 0.0f, 0.0f}, odd = even;
    int32_t e = 0;
    for (; e + 1 < degree; e += 2) {
      even += in[around[e]];
      odd += in[around[e + 1]];
    }
    if (e < degree) even += in[around[e]];
    return static_cast<float>(degree) * in[v] - (even + odd);
  };

  // The correction the steps add to the shape, single precision like them;
  // x + correction / scale at the end, in double.
  std::vector<v4f> correction(n, v4f{0.0f, 0.0f, 0.0f, 0.0f});
  for (int32_t step = 0; step < steps; ++step) {
    // q = L (L p) + w^2 S p (t = L p first); per block the sums of p q.
    team.run([&](int32_t, int32_t, int32_t b) {
      runs.visit(b, [&](auto degree, int32_t v) { t[v] = laplacian_row(p.data(), v, degree); });
    });
    team.run([&](int32_t begin, int32_t end, int32_t b) {
      runs.visit(b, [&](auto degree, int32_t v) { q[v] = laplacian_row(t.data(), v, degree); });
      block_sum(begin, end, [&](int32_t v) {
        v4f qv = q[v];
        // At an anchor, w^2 p in double: w^2 may be past single precision's
        // range (the format allows w up to 1e100), where p is then 0.
        if (anchor_of[v] >= 0) {
          const v4d exact = __builtin_convertvector(qv, v4d) + w2 * __builtin_convertvector(p[v], v4d);
          qv = __builtin_convertvector(exact, v4f);
        }
        q[v] = qv;
        return p[v] * qv;
      }, &partial[b]);
    });
    const v4d pq = total();
    // A column already solved exactly (rz or pq zero) stays as it is.
    v4f alpha = {0.0f, 0.0f, 0.0f, 0.0f};
    for (int c = 0; c < 3; ++c) alpha[c] = (pq[c] > 0.0 && rz[c] > 0.0) ? to_float(rz[c] / pq[c]) : 0.0f;
    // correction += alpha p; r -= alpha q; z = M^-1 r (into t, free now);
    // per block the sums of r z.
    team.run([&](int32_t begin, int32_t end, int32_t b) {
      block_sum(begin, end, [&](int32_t v) {
        correction[v] += alpha * p[v];
        const v4f rv = r[v] - alpha * q[v];
        r[v] = rv;
        const v4f zv = inv_diag[v] * rv;
        t[v] = zv;
        return rv * zv;
      }, &partial[b]);
    });
    const v4d rz_next = total();
    v4f beta = {0.0f, 0.0f, 0.0f, 0.0f};
    for (int c = 0; c < 3; ++c) beta[c] = rz[c] > 0.0 ? to_float(rz_next[c] / rz[c]) : 0.0f;
    rz = rz_next;
    // p = z + beta p.
    team.run([&](int32_t begin, int32_t end, int32_t) {
      for (int32_t v = begin; v < end; ++v) p[v] = t[v] + beta * p[v];
    });
  }
  for (int32_t v = 0; v < n_; ++v) {
    for (int c = 0; c < 3; ++c) x[3 * v + c] += static_cast<double>(correction[v][c]) / scale;
  }
  // The steps' vectors go before the shape is copied out: not beside it
  // (the decode's peak).
  for (std::vector<v4f>* vectors : {&r, &p, &q, &t, &correction}) std::vector<v4f>().swap(*vectors);
  std::vector<float>().swap(inv_diag);
  *positions = shape_;
  return Status::Ok();
}

}  // namespace gab
