#include "detail/detail_chunk.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include "anchors/quantizer.h"
#include "container/byte_io.h"
#include "detail/detail_predictor.h"
#include "entropy/int_coder.h"
#include "entropy/range_coder.h"

namespace gab {

namespace {

// Contexts per frame axis: none of the neighbours decoded, then the bit
// length (0..6) of twice the mean residual magnitude at the decoded ones.
constexpr int kBuckets = 8;
// Beyond this many steps from the origin the lattice leaves doubles' exact integers.
constexpr double kMaxLatticeIndex = 4503599627370496.0;  // 2^52

Status corrupt(const std::string& what) { return Status::Error(StatusCode::kParseError, what); }

// Statistics of one chunk (nothing carries over: the chunk is the last).
struct DetailModels {
  DetailModels() : residual(3 * kBuckets) {
    near_tie = BitModel(10);
    near_tie.p0 = BitModel::kMax;
  }
  BitModel near_tie, round_up;
  SIntCoder residual;
};

// The context of step i's residual on `axis`.
int context(const DetailTopology& topo, const std::vector<int32_t>& magnitude, size_t i, int axis) {
  int64_t sum = 0;
  const int64_t known = topo.known_offsets[i + 1] - topo.known_offsets[i];
  for (int32_t p = topo.known_offsets[i]; p < topo.known_offsets[i + 1]; ++p) {
    sum += magnitude[3 * static_cast<size_t>(topo.known[p]) + axis];
  }
  if (known == 0) return axis * kBuckets;
  int64_t m = (2 * sum + known / 2) / known;
  int bucket = 1;
  while (m > 0 && bucket < kBuckets - 1) {
    m >>= 1;
    ++bucket;
  }
  return axis * kBuckets + bucket;
}

// The bits a residual costs, roughly (zero flag, sign, gamma-coded magnitude).
double estimated_bits(int32_t k) {
  return k == 0 ? 1.0 : 2.0 + 2.0 * std::log2(1.0 + std::fabs(static_cast<double>(k)));
}

// The residual the encoder sends for the scaled frame coordinate f.
int32_t choose_residual(double f, double rate_weight) {
  const int32_t k = static_cast<int32_t>(std::max(-1e9, std::min(1e9, std::nearbyint(f))));
  if (rate_weight <= 0 || k == 0) return k;
  const int32_t smaller = k > 0 ? k - 1 : k + 1;
  const double keep = (f - k) * (f - k) + rate_weight * estimated_bits(k);
  const double shrink = (f - smaller) * (f - smaller) + rate_weight * estimated_bits(smaller);
  return shrink < keep ? smaller : k;
}

int32_t clamp_magnitude(int32_t k) { return k == INT32_MIN ? INT32_MAX : (k < 0 ? -k : k); }

// The scaled coordinate of x~ on the lattice, or NaN past its range.
double lattice_scaled(double x, double origin, double step) {
  const double s = (x - origin) / step;
  return std::fabs(s) < kMaxLatticeIndex ? s : std::nan("");
}

}  // namespace

DetailFrame detail_frame_of(const GabHeader& header) {
  DetailFrame frame;
  for (int c = 0; c < 3; ++c) frame.origin[c] = header.box_min[c];
  frame.extent = header.step * static_cast<double>((int64_t{1} << header.bits) - 1);
  return frame;
}

Status read_detail_head(const uint8_t* payload, size_t size, const DetailFrame& frame, DetailParams* params,
                        size_t* stream_offset) {
  ByteReader in(payload, size);
  uint8_t version = 0, an = 0, at = 0;
  double step = 0;
  if (!in.u8(&version)) return corrupt("detail chunk is empty");
  if (version == 0) return corrupt("detail version 0 is not a version");
  if (version > kDetailVersion) {
    return Status::Error(StatusCode::kUnsupported, "detail version " + std::to_string(version) +
                                                       " is newer than this decoder's (" +
                                                       std::to_string(kDetailVersion) + ")");
  }
  if (!in.f64(&step) || !in.u8(&an) || !in.u8(&at)) return corrupt("detail chunk head is cut short");
  if (!(frame.extent > 0)) return corrupt("detail chunk in a file whose box has no size");
  if (!(step >= kMinDetailStep * frame.extent) || !(step <= kMaxDetailStep * frame.extent)) {
    return corrupt("detail step out of range");
  }
  if (an > kDetailAlphaOne || at > kDetailAlphaOne) return corrupt("detail blend out of range");
  params->step = step;
  params->alpha_normal16 = an;
  params->alpha_tangent16 = at;
  *stream_offset = in.offset();
  return Status::Ok();
}

std::vector<uint8_t> encode_detail_chunk(const DetailTopology& topo, const DetailFrame& frame,
                                         const std::vector<double>& smooth, const std::vector<double>& target,
                                         const DetailParams& params, std::vector<double>* decoded,
                                         DetailScratch* scratch) {
  DetailScratch own;
  DetailScratch& work = scratch ? *scratch : own;
  const int32_t n = topo.num_vertices;
  const size_t n3 = 3 * static_cast<size_t>(n);
  const double step = params.step, fine = step / kSmoothDivisions;
  ByteWriter head;
  head.u8(kDetailVersion);
  head.f64(step);
  head.u8(static_cast<uint8_t>(params.alpha_normal16));
  head.u8(static_cast<uint8_t>(params.alpha_tangent16));
  // The smooth shape on the lattice, its normals and its near ties: the
  // step's alone, kept for the next chunk of the same step.
  if (work.step != step || work.lattice.size() != n3) {
    const double guard = std::max(kDetailGuard, kDetailGuardFloor * frame.extent / fine);
    work.step = step;
    work.lattice.resize(n3);
    work.ties.resize(n3);
    for (size_t i = 0; i < n3; ++i) {
      const int c = static_cast<int>(i % 3);
      double s = lattice_scaled(smooth[i], frame.origin[c], fine);
      if (std::isnan(s)) s = 0;  // never for a reconstruction inside the box's reach (choose_detail checks)
      const bool near = prediction_is_near_tie(s, guard);
      bool up = false;
      const int64_t rounded = round_prediction(s, &up);
      work.ties[i] = static_cast<uint8_t>(near ? (up ? 2 : 1) : 0);
      work.lattice[i] = frame.origin[c] + fine * static_cast<double>(rounded);
    }
    smooth_normals(topo, work.lattice, &work.normals);
  }
  RangeEncoder enc;
  DetailModels models;
  for (size_t i = 0; i < n3; ++i) {
    enc.encode(&models.near_tie, work.ties[i] != 0 ? 1 : 0);
    if (work.ties[i] != 0) enc.encode(&models.round_up, work.ties[i] == 2 ? 1 : 0);
  }
  decoded->assign(n3, 0.0);
  work.magnitude.assign(n3, 0);
  DetailPrediction pred;
  for (size_t i = 0; i < topo.order.size(); ++i) {
    predict_detail(topo, work.lattice, work.normals, *decoded, params.alpha_normal16, params.alpha_tangent16, i,
                   &pred);
    const size_t v3 = 3 * static_cast<size_t>(topo.order[i]);
    const double d[3] = {target[v3] - pred.p[0], target[v3 + 1] - pred.p[1], target[v3 + 2] - pred.p[2]};
    int32_t k[3];
    for (int axis = 0; axis < 3; ++axis) {
      const double* e = pred.frame[axis];
      const double f = (d[0] * e[0] + d[1] * e[1] + d[2] * e[2]) / step;
      k[axis] = choose_residual(f, params.rate_weight);
      models.residual.encode(&enc, k[axis], context(topo, work.magnitude, i, axis));
    }
    for (int axis = 0; axis < 3; ++axis) work.magnitude[v3 + axis] = clamp_magnitude(k[axis]);
    place_detail(pred, step, k, decoded->data() + v3);
  }
  std::vector<uint8_t> out = head.take();
  const std::vector<uint8_t> stream = enc.finish();
  out.insert(out.end(), stream.begin(), stream.end());
  return out;
}

Status decode_detail_chunk(const uint8_t* payload, size_t size, const DetailTopology& topo, const DetailFrame& frame,
                           const std::vector<double>& smooth, std::vector<double>* decoded) {
  DetailParams params;
  size_t offset = 0;
  GAB_RETURN_IF_ERROR(read_detail_head(payload, size, frame, &params, &offset));
  const int32_t n = topo.num_vertices;
  const double step = params.step, fine = step / kSmoothDivisions;
  RangeDecoder dec(payload + offset, size - offset);
  DetailModels models;
  std::vector<double> lattice(3 * static_cast<size_t>(n));
  for (int32_t v = 0; v < n; ++v) {
    for (int c = 0; c < 3; ++c) {
      const size_t i = 3 * static_cast<size_t>(v) + c;
      const double s = lattice_scaled(smooth[i], frame.origin[c], fine);
      if (std::isnan(s)) return corrupt("the anchors' shape lies beyond the detail lattice");
      const bool near = dec.decode(&models.near_tie) != 0;
      const bool up = near && dec.decode(&models.round_up) != 0;
      lattice[i] = frame.origin[c] + fine * static_cast<double>(resolve_prediction(s, near, up));
    }
  }
  if (dec.overrun()) return corrupt("detail chunk is cut short");
  decoded->assign(3 * static_cast<size_t>(n), 0.0);
  std::vector<double> normals;
  smooth_normals(topo, lattice, &normals);
  std::vector<int32_t> magnitude(3 * static_cast<size_t>(n), 0);
  DetailPrediction pred;
  for (size_t i = 0; i < topo.order.size(); ++i) {
    predict_detail(topo, lattice, normals, *decoded, params.alpha_normal16, params.alpha_tangent16, i, &pred);
    const size_t v3 = 3 * static_cast<size_t>(topo.order[i]);
    int32_t k[3];
    for (int axis = 0; axis < 3; ++axis) {
      k[axis] = models.residual.decode(&dec, context(topo, magnitude, i, axis));
    }
    if (dec.overrun()) return corrupt("detail residuals are cut short");
    for (int axis = 0; axis < 3; ++axis) magnitude[v3 + axis] = clamp_magnitude(k[axis]);
    place_detail(pred, step, k, decoded->data() + v3);
    if (!std::isfinite((*decoded)[v3]) || !std::isfinite((*decoded)[v3 + 1]) || !std::isfinite((*decoded)[v3 + 2])) {
      return corrupt("detail residuals are corrupt");
    }
  }
  return Status::Ok();
}

}  // namespace gab
