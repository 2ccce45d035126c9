#include "attributes/attribute_section.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

#include "anchors/quantizer.h"
#include "attributes/attribute_quantizer.h"
#include "container/byte_io.h"
#include "entropy/int_coder.h"
#include "entropy/range_coder.h"

namespace gab {

namespace {

constexpr uint8_t kLayoutPerVertex = 0;
constexpr uint8_t kLayoutPerCorner = 1;
// The predictors (docs/format.md 6.4); a later one gets another code, which
// this build skips as unsupported.
constexpr uint8_t kPredictorParallelogram = 0;
constexpr uint8_t kPredictorSurface = 1;  // normals: the decoded surface's, else the parallelogram
constexpr uint8_t kPredictorBlend = 2;    // normals: predictors 1 and 0 summed on the lattice
constexpr uint8_t kPredictorFaces = 3;    // normals: 1 with each triangle's unit normal (unweighted)
constexpr uint8_t kPredictorAngles = 4;   // normals: 1 with unit normals weighted by the corner's angle
constexpr uint8_t kPredictorMean = 5;     // any kind: the decoded values in the wedge's triangles, else 0's chain
constexpr uint8_t kPredictorMeanSurface = 6;  // normals: 5, else 1 (faceted normals: a triangle's corners alike)
constexpr uint8_t kLastPredictor = kPredictorMeanSurface;

// What each predictor does, in order: the mean of the decoded values in the
// wedge's triangles first; the decoded surface's normal (summed with 0's
// prediction for 2); else predictor 0's chain.
struct PredictorSteps {
  bool mean_first = false;
  bool surface = false;
  bool blend = false;
};
PredictorSteps steps_of(uint8_t predictor) {
  PredictorSteps s;
  s.mean_first = predictor == kPredictorMean || predictor == kPredictorMeanSurface;
  s.surface = predictor != kPredictorParallelogram && predictor != kPredictorMean;
  s.blend = predictor == kPredictorBlend;
  return s;
}
// The surface normal's scale before the lattice: 2^5 times the lattice's
// radius, so that its rounding (through the guard band) moves the
// prediction by a thirty-second of a lattice step at most.
constexpr int kSurfaceExtraBits = 5;
// Residual contexts per component: the bit length of the magnitude that
// sets it, capped.
constexpr int kBuckets = 8;

Status corrupt(const std::string& what) { return Status::Error(StatusCode::kParseError, what); }

int64_t floor_div(int64_t a, int64_t b) {  // b > 0
  const int64_t q = a / b;
  return (a % b != 0 && a < 0) ? q - 1 : q;
}
// a / b rounded half up, b > 0.
int64_t round_div(int64_t a, int64_t b) { return floor_div(2 * a + b, 2 * b); }

int bucket(int64_t m) {
  int b = 0;
  while (m > 0 && b < kBuckets - 1) {
    m >>= 1;
    ++b;
  }
  return b;
}

// A normal's frame: the lattice point `p` (the prediction) seen with its
// largest component last and every component non-negative, by exact axis
// permutations and sign flips, so the value coded near it is near the
// middle of its octant and never across the octahedron's folds.
struct NormalFrame {
  explicit NormalFrame(const int32_t p[3]) {
    int z = 2;
    if (std::abs(p[1]) > std::abs(p[z])) z = 1;
    if (std::abs(p[0]) > std::abs(p[z])) z = 0;
    int i = 0;
    for (int c = 0; c < 3; ++c) {
      if (c != z) axis[i++] = c;
    }
    axis[2] = z;
    for (int c = 0; c < 3; ++c) sign[c] = p[axis[c]] < 0 ? -1 : 1;
  }
  void to(const int32_t in[3], int32_t out[3]) const {
    for (int c = 0; c < 3; ++c) out[c] = sign[c] * in[axis[c]];
  }
  void from(const int32_t in[3], int32_t out[3]) const {
    for (int c = 0; c < 3; ++c) out[axis[c]] = sign[c] * in[c];
  }
  int axis[3];
  int sign[3];
};

// A vertex's corners that share one element.
struct Wedge {
  const int32_t* first;
  const int32_t* last;
  const int32_t* begin() const { return first; }
  const int32_t* end() const { return last; }
  bool empty() const { return first == last; }
};

// The walk both sides make: elements as they are created (per corner: a
// wedge of corners sharing a value; per vertex: the vertex), their values,
// and the prediction of the next from them.
class Walk {
 public:
  Walk(const CornerTable& t, const AttributeQuantizer& q, bool per_corner)
      : t_(t), q_(q), k_(q.components), per_corner_(per_corner), element_(t.triangles->size(), -1) {
    if (!per_corner) {
      values_.assign(static_cast<size_t>(t.num_vertices) * k_, 0);
      activity_.assign(t.num_vertices, 0);
    }
  }

  int32_t element(int32_t corner) const { return element_[corner]; }
  const int32_t* value(int32_t e) const { return &values_[static_cast<size_t>(e) * k_]; }
  int64_t elements() const { return per_corner_ ? static_cast<int64_t>(values_.size() / k_) : t_.num_vertices; }
  std::vector<int32_t>& values() { return values_; }
  std::vector<int32_t>& corner_elements() { return element_; }

  // The prediction of the element of the corners `wedge` (at one vertex,
  // none yet an element): the mean of the parallelograms across the
  // triangles opposite them whose edge has no seam, else of the decoded
  // neighbours in their triangles, else the last element.
  void predict(const Wedge& wedge, int32_t* out) const {
    int64_t sum[4] = {0, 0, 0, 0};
    int64_t count = 0;
    for (int32_t c : wedge) {
      const int32_t a = CornerTable::next(c), b = CornerTable::prev(c);
      const int32_t ea = element_[a], eb = element_[b];
      if (ea < 0 || eb < 0) continue;
      const int32_t a2 = t_.across[a];
      if (a2 < 0 || element_[a2] != ea || element_[CornerTable::prev(a2)] != eb) continue;
      const int32_t ed = element_[CornerTable::next(a2)];
      if (ed < 0) continue;
      for (int i = 0; i < k_; ++i) sum[i] += int64_t{value(ea)[i]} + value(eb)[i] - value(ed)[i];
      ++count;
    }
    if (count == 0) count = neighbour_sum(wedge, sum);
    if (place(sum, count, out)) return;
    for (int i = 0; i < k_; ++i) {
      if (last_ >= 0) {
        out[i] = value(last_)[i];
      } else {
        out[i] = q_.lattice() ? (i == 2 ? q_.radius() : 0) : static_cast<int32_t>((q_.max_index() + 1) / 2);
      }
    }
  }

  // The mean of the decoded values in the wedge's triangles (predictors 5
  // and 6); false when none is decoded (or, for normals, they cancel).
  bool mean(const Wedge& wedge, int32_t* out) const {
    int64_t sum[4] = {0, 0, 0, 0};
    return place(sum, neighbour_sum(wedge, sum), out);
  }

  // The decoded surface's normal at the wedge: the sum of its triangles'
  // normals (the cross products of their edges at the corner, in the
  // triangles' orientation): as they are (area-weighted, predictors 1 and
  // 2), of unit length (3) or of unit length times the corner's angle (4).
  static void surface_normal(const CornerTable& t, const Wedge& wedge, const std::vector<double>& positions,
                             uint8_t predictor, double n[3]) {
    n[0] = n[1] = n[2] = 0;
    for (int32_t c : wedge) {
      const double* p = &positions[3 * static_cast<size_t>(t.vertex(c))];
      const double* a = &positions[3 * static_cast<size_t>(t.vertex(CornerTable::next(c)))];
      const double* b = &positions[3 * static_cast<size_t>(t.vertex(CornerTable::prev(c)))];
      const double e1[3] = {a[0] - p[0], a[1] - p[1], a[2] - p[2]};
      const double e2[3] = {b[0] - p[0], b[1] - p[1], b[2] - p[2]};
      double f[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
      if (predictor == kPredictorFaces || predictor == kPredictorAngles) {
        const double length = std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
        if (!(length > 0)) continue;
        double w = 1 / length;
        if (predictor == kPredictorAngles) {
          const double dot = e1[0] * e2[0] + e1[1] * e2[1] + e1[2] * e2[2];
          w *= std::atan2(length, dot);
        }
        for (double& x : f) x *= w;
      }
      n[0] += f[0];
      n[1] += f[1];
      n[2] += f[2];
    }
  }

  // The wedge's element is `value`, coded with residuals of largest
  // magnitude `activity`: its corners take it.
  void add(const Wedge& wedge, int32_t vertex, const int32_t* value, int32_t activity) {
    int32_t e = vertex;
    if (per_corner_) {
      e = static_cast<int32_t>(values_.size() / k_);
      values_.insert(values_.end(), value, value + k_);
      activity_.push_back(activity);
    } else {
      std::copy(value, value + k_, values_.begin() + static_cast<std::ptrdiff_t>(e) * k_);
      activity_[e] = activity;
    }
    for (int32_t c : wedge) element_[c] = e;
    last_ = e;
  }

  // The residuals' size around the wedge: the mean of the largest residual
  // magnitudes of the decoded elements in its triangles (rounded down), or
  // `otherwise` when none is decoded.
  int32_t activity(const Wedge& wedge, int32_t otherwise) const {
    int64_t sum = 0, count = 0;
    for (int32_t c : wedge) {
      for (int32_t x : {CornerTable::next(c), CornerTable::prev(c)}) {
        if (element_[x] < 0) continue;
        sum += activity_[element_[x]];
        ++count;
      }
    }
    return count > 0 ? static_cast<int32_t>(sum / count) : otherwise;
  }

 private:
  // Adds to `sum` the values of the decoded elements in the wedge's
  // triangles (each corner's two others); returns how many.
  int64_t neighbour_sum(const Wedge& wedge, int64_t* sum) const {
    int64_t count = 0;
    for (int32_t c : wedge) {
      for (int32_t x : {CornerTable::next(c), CornerTable::prev(c)}) {
        if (element_[x] < 0) continue;
        for (int i = 0; i < k_; ++i) sum[i] += value(element_[x])[i];
        ++count;
      }
    }
    return count;
  }

  // `count` values summing to `sum` as one element: on the lattice (their
  // direction) or the grid (their mean, rounded half up, clamped); false
  // when there are none, or normals that cancel.
  bool place(const int64_t* sum, int64_t count, int32_t* out) const {
    if (count == 0) return false;
    if (q_.lattice()) {
      if (sum[0] == 0 && sum[1] == 0 && sum[2] == 0) return false;
      project_to_lattice(sum, q_.radius(), out);
      return true;
    }
    for (int i = 0; i < k_; ++i) {
      out[i] = static_cast<int32_t>(std::min<int64_t>(std::max<int64_t>(round_div(sum[i], count), 0), q_.max_index()));
    }
    return true;
  }

  const CornerTable& t_;
  const AttributeQuantizer& q_;
  const int k_;
  const bool per_corner_;
  std::vector<int32_t> element_;
  std::vector<int32_t> values_;
  std::vector<int32_t> activity_;
  int32_t last_ = -1;
};

// Vertex v's corners grouped into wedges by `joined(c)` (the corner across
// from c shares c's value), in the order of their first corner. The
// scratch is kept across vertices: no allocation once it has grown.
class WedgeSplitter {
 public:
  template <typename Joined>
  const std::vector<Wedge>& split(const CornerTable& t, int32_t v, Joined joined) {
    const int32_t first = t.corner_offsets[v], count = t.corner_offsets[v + 1] - first;
    const int32_t* corners = t.corners.data() + first;
    wedges_.clear();
    if (count == 0) {
      wedges_.push_back({corners, corners});
      return wedges_;
    }
    parent_.resize(count);
    for (int32_t i = 0; i < count; ++i) parent_[i] = i;
    auto find = [&](int32_t i) {
      while (parent_[i] != i) i = parent_[i] = parent_[parent_[i]];
      return i;
    };
    bool any = false;
    for (int32_t i = 0; i < count; ++i) {
      const int32_t c = corners[i];
      if (t.across[c] >= 0 && joined(c)) {
        const int32_t j = static_cast<int32_t>(std::lower_bound(corners, corners + count, t.across[c]) - corners);
        const int32_t a = find(i), b = find(j);
        if (a != b) parent_[std::max(a, b)] = std::min(a, b);
      } else {
        any = true;
      }
    }
    if (!any) {  // every pair joined: one wedge, the vertex's corners
      wedges_.push_back({corners, corners + count});
      return wedges_;
    }
    // Corners grouped by root, roots in the order of their first corner.
    slot_.assign(count, -1);
    sizes_.clear();
    for (int32_t i = 0; i < count; ++i) {
      const int32_t r = find(i);
      if (slot_[r] < 0) {
        slot_[r] = static_cast<int32_t>(sizes_.size());
        sizes_.push_back(0);
      }
      ++sizes_[slot_[r]];
    }
    grouped_.resize(count);
    starts_.assign(sizes_.size() + 1, 0);
    for (size_t w = 0; w < sizes_.size(); ++w) starts_[w + 1] = starts_[w] + sizes_[w];
    fill_.assign(starts_.begin(), starts_.end() - 1);
    for (int32_t i = 0; i < count; ++i) grouped_[fill_[slot_[find(i)]]++] = corners[i];
    for (size_t w = 0; w < sizes_.size(); ++w) {
      wedges_.push_back({grouped_.data() + starts_[w], grouped_.data() + starts_[w + 1]});
    }
    return wedges_;
  }

  // All of v's corners as one wedge (per-vertex layout).
  const std::vector<Wedge>& whole(const CornerTable& t, int32_t v) {
    wedges_.assign(1, {t.corners.data() + t.corner_offsets[v], t.corners.data() + t.corner_offsets[v + 1]});
    return wedges_;
  }

 private:
  std::vector<int32_t> parent_, slot_, sizes_, grouped_, starts_, fill_;
  std::vector<Wedge> wedges_;
};

// The contexts of the residual coders.
struct ResidualModels {
  explicit ResidualModels(int components) : residual(components * kBuckets), seam(3), below(1) {}
  SIntCoder residual;
  std::vector<BitModel> seam;  // by the edge's other end: not yet walked, joined, a seam
  BitModel below;              // a normal's last component is negative
  BitModel near_tie{7};        // a surface normal's component is near a rounding tie (rare: a long memory)
  BitModel round_up;           // and was rounded up
  int32_t previous_max = 0;
};

// The surface normal `n` (not zero) at the lattice's scale times
// 2^kSurfaceExtraBits, each component rounded through the guard band
// (docs/format.md 5.3), then on the lattice: what both sides predict.
template <typename Flags>
void surface_prediction(const double n[3], const AttributeQuantizer& q, Flags flags, int32_t* pred) {
  const double l1 = std::fabs(n[0]) + std::fabs(n[1]) + std::fabs(n[2]);
  const double scale = static_cast<double>(int64_t{q.radius()} << kSurfaceExtraBits);
  int64_t p[3];
  for (int c = 0; c < 3; ++c) p[c] = flags(n[c] / l1 * scale);
  if (p[0] == 0 && p[1] == 0 && p[2] == 0) p[2] = 1;  // cannot happen: |p| sums to about the scale
  project_to_lattice(p, q.radius(), pred);
}

// The seam context of corner c's pair: what the edge's other end says.
int seam_context(const Walk& walk, int32_t c, const CornerTable& t) {
  const int32_t other = CornerTable::next(c), other_across = CornerTable::prev(t.across[c]);
  const int32_t a = walk.element(other), b = walk.element(other_across);
  if (a < 0 || b < 0) return 0;
  return a == b ? 1 : 2;
}

// Residual contexts: component 0 by the previous element's largest
// residual, later ones by this element's so far.
int residual_context(int c, const int32_t* r, int32_t previous_max) {
  int64_t m = previous_max;
  if (c > 0) {
    m = 0;
    for (int i = 0; i < c; ++i) m = std::max<int64_t>(m, std::llabs(r[i]));
  }
  return c * kBuckets + bucket(m);
}

// Predictor 2: the surface's lattice point `pred` and the parallelogram's,
// summed and put back on the lattice (the surface's alone if they cancel).
void blend(const Walk& walk, const Wedge& wedge, const AttributeQuantizer& q, int32_t* pred) {
  int32_t neighbours[3];
  walk.predict(wedge, neighbours);
  const int64_t sum[3] = {int64_t{pred[0]} + neighbours[0], int64_t{pred[1]} + neighbours[1],
                          int64_t{pred[2]} + neighbours[2]};
  if (sum[0] != 0 || sum[1] != 0 || sum[2] != 0) project_to_lattice(sum, q.radius(), pred);
}

// The prediction `predictor` makes for the wedge, in its order of steps
// (PredictorSteps); `flags(x)` rounds a surface normal's scaled component
// through the guard band: the encoder codes the flags, the decoder reads
// them, so both sides make the same prediction through one function.
template <typename Flags>
void predict_wedge(uint8_t predictor, const Walk& walk, const CornerTable& t, const Wedge& wedge,
                   const std::vector<double>* positions, const AttributeQuantizer& q, Flags flags, int32_t* pred) {
  const PredictorSteps use = steps_of(predictor);
  if (use.mean_first && walk.mean(wedge, pred)) return;
  double n[3] = {0, 0, 0};
  if (use.surface) Walk::surface_normal(t, wedge, *positions, predictor, n);
  if (n[0] != 0 || n[1] != 0 || n[2] != 0) {
    surface_prediction(n, q, flags, pred);
    if (use.blend) blend(walk, wedge, q, pred);
    return;
  }
  walk.predict(wedge, pred);
}

void write_description(const MeshAttribute& a, const AttributeQuantizer& q, bool per_corner, uint8_t predictor,
                       int64_t elements, ByteWriter* out) {
  out->u8(kGabSectionAttribute);
  out->u8(0);  // flags: optional (a decoder that does not know it skips it)
  out->u8(static_cast<uint8_t>(a.kind));
  out->u8(static_cast<uint8_t>(a.type));
  out->u8(static_cast<uint8_t>(a.components));
  out->u8(per_corner ? kLayoutPerCorner : kLayoutPerVertex);
  out->u8(predictor);
  out->u8(static_cast<uint8_t>(q.bits));
  out->u8(static_cast<uint8_t>(a.name.size()));
  out->bytes(reinterpret_cast<const uint8_t*>(a.name.data()), a.name.size());
  if (!q.lattice()) {
    for (int c = 0; c < a.components; ++c) out->f64(q.origin[c]);
    out->f64(q.step);
  }
  out->varint(static_cast<uint64_t>(elements));
}

double angle_degrees(const double* a, const double* b) {
  const double la = std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  const double lb = std::sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
  if (!(la > 0) || !(lb > 0)) return 0;
  const double cosine = (a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) / (la * lb);
  return std::acos(std::min(1.0, std::max(-1.0, cosine))) * (180.0 / 3.14159265358979323846);
}

}  // namespace

namespace {

// One way of coding the attribute: the stream and the elements it made.
struct Coded {
  std::vector<uint8_t> stream;
  int64_t elements = 0;
};

// The stream of `a` (its elements quantized in `input`) by `predictor`.
Coded encode_stream(const MeshAttribute& a, const CornerTable& t, const AttributeQuantizer& q,
                    const std::vector<int32_t>& input, bool per_corner, uint8_t predictor,
                    const std::vector<double>* positions) {
  const int k = a.components;
  const size_t ku = static_cast<size_t>(k);
  auto corner_value = [&](int32_t c) {
    return &input[ku * static_cast<size_t>(a.per_corner() ? a.corners[c] : t.vertex(c))];
  };
  Walk walk(t, q, per_corner);
  ResidualModels models(k);
  RangeEncoder enc;
  WedgeSplitter splitter;
  int32_t pred[4], r[4], actual[4];
  for (int32_t v : t.visit) {
    auto joined = [&](int32_t c) { return std::equal(corner_value(c), corner_value(c) + k, corner_value(t.across[c])); };
    if (per_corner) {
      for (int32_t p = t.corner_offsets[v]; p < t.corner_offsets[v + 1]; ++p) {
        const int32_t c = t.corners[p];
        if (t.across[c] < 0) continue;
        enc.encode(&models.seam[seam_context(walk, c, t)], joined(c) ? 0 : 1);
      }
    }
    for (const Wedge& wedge : per_corner ? splitter.split(t, v, joined) : splitter.whole(t, v)) {
      predict_wedge(predictor, walk, t, wedge, positions, q, [&](double x) {
        bool up = false;
        const int64_t rounded = round_prediction(x, &up);
        const bool near = prediction_is_near_tie(x);
        enc.encode(&models.near_tie, near ? 1 : 0);
        if (near) enc.encode(&models.round_up, up ? 1 : 0);
        return rounded;
      }, pred);
      if (!wedge.empty()) {
        std::copy(corner_value(*wedge.first), corner_value(*wedge.first) + k, actual);
      } else if (!a.per_corner()) {
        std::copy(&input[ku * v], &input[ku * v] + k, actual);
      } else {
        std::copy(pred, pred + k, actual);  // a vertex in no triangle: nothing to keep
      }
      const int32_t around = walk.activity(wedge, models.previous_max);
      if (q.lattice()) {
        const NormalFrame frame(pred);
        int32_t p2[3], a2[3];
        frame.to(pred, p2);
        frame.to(actual, a2);
        for (int c = 0; c < 2; ++c) {
          r[c] = a2[c] - p2[c];
          models.residual.encode(&enc, r[c], residual_context(c, r, around));
        }
        if (q.radius() - std::abs(a2[0]) - std::abs(a2[1]) > 0) enc.encode(&models.below, a2[2] < 0 ? 1 : 0);
        models.previous_max = std::max(std::abs(r[0]), std::abs(r[1]));
      } else {
        int32_t m = 0;
        for (int c = 0; c < k; ++c) {
          r[c] = actual[c] - pred[c];
          models.residual.encode(&enc, r[c], residual_context(c, r, around));
          m = std::max(m, std::abs(r[c]));
        }
        models.previous_max = m;
      }
      walk.add(wedge, v, actual, models.previous_max);
    }
  }
  return {enc.finish(), walk.elements()};
}

}  // namespace

std::vector<uint8_t> encode_attribute_section(const MeshAttribute& a, const CornerTable& t, int bits,
                                              const std::vector<double>* positions, AttributeCoding* coding) {
  const AttributeQuantizer q = AttributeQuantizer::fit(a, bits);
  const int k = a.components;
  const size_t ku = static_cast<size_t>(k);
  // Every input element quantized once; a corner's value is its element's.
  std::vector<int32_t> input(a.values.size());
  for (int64_t e = 0; e < a.num_elements(); ++e) q.quantize(&a.values[e * k], &input[e * k]);
  auto corner_value = [&](int32_t c) {
    return &input[ku * static_cast<size_t>(a.per_corner() ? a.corners[c] : t.vertex(c))];
  };
  bool per_corner = false;
  if (a.per_corner()) {
    for (int32_t v = 0; v < t.num_vertices && !per_corner; ++v) {
      for (int32_t p = t.corner_offsets[v] + 1; p < t.corner_offsets[v + 1]; ++p) {
        if (!std::equal(corner_value(t.corners[p]), corner_value(t.corners[p]) + k,
                        corner_value(t.corners[t.corner_offsets[v]]))) {
          per_corner = true;
          break;
        }
      }
    }
  }
  // The smallest of every predictor the attribute can take (normals over
  // the decoded surface: every one).
  uint8_t predictor = kPredictorParallelogram;
  Coded coded = encode_stream(a, t, q, input, per_corner, predictor, nullptr);
  std::vector<uint8_t> others = {kPredictorMean};
  if (q.lattice() && positions != nullptr) {
    others.insert(others.end(),
                  {kPredictorSurface, kPredictorBlend, kPredictorFaces, kPredictorAngles, kPredictorMeanSurface});
  }
  for (uint8_t other : others) {
    Coded candidate = encode_stream(a, t, q, input, per_corner, other, positions);
    if (candidate.stream.size() < coded.stream.size()) {
      coded = std::move(candidate);
      predictor = other;
    }
  }

  ByteWriter out;
  write_description(a, q, per_corner, predictor, coded.elements, &out);
  out.bytes(coded.stream.data(), coded.stream.size());

  if (coding != nullptr) {
    *coding = AttributeCoding();
    coding->bits = q.bits;
    coding->per_corner = per_corner;
    coding->elements = coded.elements;
    coding->surface = steps_of(predictor).surface;
    // The error of every input element that reaches the output.
    double decoded[4];
    for (int64_t e = 0; e < a.num_elements(); ++e) {
      q.dequantize(&input[e * k], decoded);
      const double* original = &a.values[e * k];
      if (q.lattice()) {
        coding->max_error = std::max(coding->max_error, angle_degrees(original, decoded));
      } else {
        for (int c = 0; c < k; ++c) coding->max_error = std::max(coding->max_error, std::fabs(original[c] - decoded[c]));
      }
    }
  }
  return out.take();
}

Status read_attribute_description(const uint8_t* payload, size_t size, AttributeDescription* d) {
  ByteReader in(payload, size);
  uint8_t section = 0, flags = 0, kind = 0, type = 0, components = 0, layout = 0, predictor = 0, bits = 0, name_size = 0;
  const bool head = in.u8(&section) && in.u8(&flags) && in.u8(&kind) && in.u8(&type) && in.u8(&components) &&
                    in.u8(&layout) && in.u8(&predictor) && in.u8(&bits) && in.u8(&name_size);
  if (!head || section != kGabSectionAttribute) return corrupt("attribute section: its description is cut short");
  if (kind > static_cast<uint8_t>(AttributeKind::kGeneric)) {
    return Status::Error(StatusCode::kUnsupported, "attribute section: kind " + std::to_string(kind) + " is unknown");
  }
  if (type > static_cast<uint8_t>(ValueType::kFloat64)) {
    return Status::Error(StatusCode::kUnsupported,
                         "attribute section: value type " + std::to_string(type) + " is unknown");
  }
  if (predictor > kLastPredictor ||
      (kind != static_cast<uint8_t>(AttributeKind::kNormal) && steps_of(predictor).surface)) {
    return Status::Error(StatusCode::kUnsupported,
                         "attribute section: predictor " + std::to_string(predictor) + " is unknown");
  }
  d->predictor = predictor;
  d->surface = steps_of(predictor).surface;
  MeshAttribute& a = d->attribute;
  a = MeshAttribute();
  a.kind = static_cast<AttributeKind>(kind);
  a.type = static_cast<ValueType>(type);
  a.components = components;
  if (!valid_attribute_components(a.kind, a.components)) {
    return corrupt("attribute section: " + std::to_string(components) + " components for " + attribute_label(a));
  }
  if (layout > kLayoutPerCorner) return corrupt("attribute section: layout " + std::to_string(layout) + " is unknown");
  d->per_corner = layout == kLayoutPerCorner;
  const uint8_t* name = nullptr;
  if (!in.bytes(name_size, &name)) return corrupt("attribute section: its name is cut short");
  a.name.assign(reinterpret_cast<const char*>(name), name_size);
  AttributeQuantizer& q = d->quantizer;
  q = AttributeQuantizer();
  q.kind = a.kind;
  q.components = a.components;
  q.bits = bits;
  if (q.lattice() ? (bits < 2 || bits > kMaxNormalBits) : (bits < 1 || bits > kMaxGridBits)) {
    return corrupt("attribute section: " + std::to_string(bits) + " bits is out of range");
  }
  if (!q.lattice()) {
    for (int c = 0; c < a.components; ++c) {
      if (!in.f64(&q.origin[c])) return corrupt("attribute section: its grid is cut short");
    }
    if (!in.f64(&q.step)) return corrupt("attribute section: its grid is cut short");
    const double far = static_cast<double>(q.max_index()) * q.step;
    bool finite = std::isfinite(q.step) && q.step >= 0 && std::isfinite(far);
    for (int c = 0; c < a.components; ++c) finite = finite && std::isfinite(q.origin[c]) && std::isfinite(q.origin[c] + far);
    if (!finite) return corrupt("attribute section: its grid is not finite");
  }
  if (!in.varint(&d->elements)) return corrupt("attribute section: its element count is cut short");
  d->stream_offset = in.offset();
  return Status::Ok();
}

Status decode_attribute_section(const uint8_t* payload, size_t size, const CornerTable& t,
                                const std::vector<double>* positions, MeshAttribute* out) {
  AttributeDescription d;
  GAB_RETURN_IF_ERROR(read_attribute_description(payload, size, &d));
  if (d.surface && positions == nullptr) {
    return Status::Error(StatusCode::kUnsupported,
                         "attribute section: normals predicted from the whole decoded surface");
  }
  MeshAttribute a = std::move(d.attribute);
  const AttributeQuantizer& q = d.quantizer;
  const bool per_corner = d.per_corner;
  const uint64_t declared = d.elements;
  const size_t corners = t.triangles->size();
  if (per_corner ? declared > corners : declared != static_cast<uint64_t>(t.num_vertices)) {
    return corrupt("attribute section: " + std::to_string(declared) + " elements for " +
                   std::to_string(t.num_vertices) + " vertices and " + std::to_string(corners) + " corners");
  }
  // Each element costs at least one decision a component: a stream too
  // short for the declared count is refused before any work.
  const uint8_t* stream = payload + d.stream_offset;
  const size_t stream_size = size - d.stream_offset;
  if (declared * static_cast<uint64_t>(a.components) > max_decisions(stream_size)) {
    return corrupt("attribute section: its stream is too short for " + std::to_string(declared) + " elements");
  }

  const int k = a.components;
  Walk walk(t, q, per_corner);
  ResidualModels models(k);
  RangeDecoder dec(stream, stream_size);
  WedgeSplitter splitter;
  std::vector<char> seam(per_corner ? corners : 0, 0);
  auto joined = [&](int32_t c) { return seam[c] == 0; };
  int32_t pred[4], r[4], actual[4];
  for (int32_t v : t.visit) {
    if (per_corner) {
      for (int32_t p = t.corner_offsets[v]; p < t.corner_offsets[v + 1]; ++p) {
        const int32_t c = t.corners[p];
        if (t.across[c] >= 0) seam[c] = static_cast<char>(dec.decode(&models.seam[seam_context(walk, c, t)]));
      }
    }
    for (const Wedge& wedge : per_corner ? splitter.split(t, v, joined) : splitter.whole(t, v)) {
      if (walk.elements() >= static_cast<int64_t>(declared) && per_corner) {
        return corrupt("attribute section: more elements than its declared " + std::to_string(declared));
      }
      predict_wedge(d.predictor, walk, t, wedge, positions, q, [&](double x) {
        const bool near = dec.decode(&models.near_tie) != 0;
        const bool up = near && dec.decode(&models.round_up) != 0;
        return resolve_prediction(x, near, up);
      }, pred);
      const int32_t around = walk.activity(wedge, models.previous_max);
      if (q.lattice()) {
        const NormalFrame frame(pred);
        int32_t p2[3], a2[3];
        frame.to(pred, p2);
        for (int c = 0; c < 2; ++c) {
          r[c] = models.residual.decode(&dec, residual_context(c, r, around));
          const int64_t x = int64_t{p2[c]} + r[c];
          if (x < -q.radius() || x > q.radius()) return corrupt("attribute section: a normal is off its lattice");
          a2[c] = static_cast<int32_t>(x);
        }
        const int64_t rest = int64_t{q.radius()} - std::abs(a2[0]) - std::abs(a2[1]);
        if (rest < 0) return corrupt("attribute section: a normal is off its lattice");
        a2[2] = static_cast<int32_t>(rest > 0 && dec.decode(&models.below) ? -rest : rest);
        models.previous_max = std::max(std::abs(r[0]), std::abs(r[1]));
        frame.from(a2, actual);
      } else {
        int32_t m = 0;
        for (int c = 0; c < k; ++c) {
          r[c] = models.residual.decode(&dec, residual_context(c, r, around));
          const int64_t x = int64_t{pred[c]} + r[c];
          if (x < 0 || x > q.max_index()) return corrupt("attribute section: a value is off its grid");
          actual[c] = static_cast<int32_t>(x);
          m = std::max<int32_t>(m, r[c] == INT32_MIN ? INT32_MAX : std::abs(r[c]));
        }
        models.previous_max = m;
      }
      walk.add(wedge, v, actual, models.previous_max);
    }
    if (dec.overrun()) return corrupt("attribute section: its stream is cut short");
  }
  if (walk.elements() != static_cast<int64_t>(declared)) {
    return corrupt("attribute section: " + std::to_string(walk.elements()) + " elements where it declares " +
                   std::to_string(declared));
  }
  if (dec.bytes_consumed() != stream_size) return corrupt("attribute section: bytes after its stream");

  const int64_t elements = walk.elements();
  a.values.resize(static_cast<size_t>(elements) * k);
  const std::vector<int32_t>& values = walk.values();
  for (int64_t e = 0; e < elements; ++e) q.dequantize(&values[e * k], &a.values[e * k]);
  if (per_corner) a.corners = std::move(walk.corner_elements());
  const Status s = validate_attribute(a, t.num_vertices, static_cast<int64_t>(corners / 3), "attribute section");
  if (!s.ok()) return corrupt(s.message());
  *out = std::move(a);
  return Status::Ok();
}

}  // namespace gab
