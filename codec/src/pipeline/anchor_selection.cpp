#include "pipeline/anchor_selection.h"

#include <algorithm>
#include <cmath>

#include "gab/mesh/graph_distance.h"
#include "gab/mesh/metrics.h"
#include "gab/mesh/optimal_coefficients.h"
#include "pipeline/error_maxima.h"
#include "pipeline/encoder_tuning.h"

namespace gab {

namespace {

// Anchors to add in the next greedy step: the batch fraction of those so
// far (`far_fraction` while the error is over kFarErrorOverTarget times an
// RMS target, when larger), but near an RMS target (0: none) only as many
// as the error curve's last two points (rms ~ k^-alpha) say are still needed.
int32_t next_batch(double target_rms_rel, double fraction, double far_fraction, const std::vector<GreedyStep>& curve,
                   int32_t cap) {
  const int32_t k = curve.back().anchors;
  const bool far = target_rms_rel > 0 && curve.back().rms_rel > kFarErrorOverTarget * target_rms_rel;
  if (far) fraction = std::max(fraction, far_fraction);
  int64_t wanted = fraction > 0 ? static_cast<int64_t>(std::ceil(fraction * k)) : 1;
  if (target_rms_rel > 0 && curve.size() >= 2) {
    const GreedyStep& a = curve[curve.size() - 2];
    const GreedyStep& b = curve.back();
    if (b.anchors > a.anchors && a.rms_rel > b.rms_rel && b.rms_rel > target_rms_rel) {
      const double alpha = std::log(a.rms_rel / b.rms_rel) / std::log(static_cast<double>(b.anchors) / a.anchors);
      const double needed = b.anchors * std::pow(b.rms_rel / target_rms_rel, 1.0 / alpha) - b.anchors;
      if (std::isfinite(needed)) wanted = std::min<int64_t>(wanted, static_cast<int64_t>(std::ceil(needed)));
    }
  }
  return static_cast<int32_t>(std::min<int64_t>(std::max<int64_t>(wanted, 1), cap - k));
}

// The refined coefficients of the current anchor set, as grid indices (3 per
// anchor, in rec->anchors() order), and the errors of their reconstruction.
struct Refinement {
  std::vector<int32_t> grid;
  double rms_rel = 0, linf_rel = 0;
};

// Least-squares coefficients from the quantized positions `rec` holds,
// rounded to the grid (the decoder gets exactly these), and their shape's
// errors; `rec` keeps its coefficients. Cost: 2 * iterations + 1 solves.
Status refine_coefficients(RelaxedReconstruction* rec, const Mesh& mesh, const Quantizer& quantizer, int iterations,
                           double scale, Refinement* out) {
  const std::vector<double> positions = rec->coefficients();
  std::vector<double> c = positions;
  OptimalCoefficientsReport report;
  GAB_RETURN_IF_ERROR(optimal_coefficients(rec, mesh, iterations, 0.0, &c, &report));
  out->grid.resize(c.size());
  for (size_t i = 0; i < c.size(); ++i) {
    const int axis = static_cast<int>(i % 3);
    out->grid[i] = quantizer.quantize(c[i], axis);
    c[i] = quantizer.dequantize(out->grid[i], axis);
  }
  GAB_RETURN_IF_ERROR(rec->set_coefficients(0, c));
  std::vector<double> shape, error2;
  const Status solved = rec->reconstruct(&shape);
  GAB_RETURN_IF_ERROR(rec->set_coefficients(0, positions));
  GAB_RETURN_IF_ERROR(solved);
  VertexDistance d;
  squared_vertex_errors(mesh, shape, &error2, &d);
  out->rms_rel = d.rms * scale;
  out->linf_rel = d.linf * scale;
  return Status::Ok();
}

// The refinement search (EncodeOptions::refine). With an RMS target the
// greedy batches aim the unrefined shape kExpectedRefinementGain above it,
// and once there each step first tries the refinement: the loop stops as
// soon as the refined shape meets the target, and otherwise aims at what the
// try measured. Out of anchors, refinement is the last way to get closer.
class RefinementSearch {
 public:
  // `target_rms_rel`, `target_linf_rel`: the loop's targets (0: none).
  RefinementSearch(const Mesh& mesh, bool enabled, int iterations, double target_rms_rel, double target_linf_rel,
                   const Quantizer& quantizer, double scale)
      : mesh_(mesh), enabled_(enabled), iterations_(iterations), target_rms_(target_rms_rel),
        target_linf_(target_linf_rel), quantizer_(quantizer), scale_(scale),
        position_target_(enabled ? target_rms_rel * kExpectedRefinementGain : target_rms_rel) {}

  // The RMS the greedy batches aim the unrefined shape at.
  double position_target() const { return position_target_; }

  // Before a greedy step, the unrefined shape erring rms / linf: *stop if
  // the refined shape meets the RMS target.
  Status before_step(RelaxedReconstruction* rec, double rms, double linf, bool* stop) {
    *stop = false;
    const double target = target_rms_;
    if (!(enabled_ && target > 0 && rms <= position_target_)) return Status::Ok();
    GAB_RETURN_IF_ERROR(try_refinement(rec));
    if (acceptable(rms, linf) && last_.rms_rel <= target) {
      refined_ = true;
      *stop = true;
      return Status::Ok();
    }
    // Aim at what this try says the refinement buys, a little beyond.
    position_target_ = std::min(position_target_, 0.99 * target * rms / std::max(last_.rms_rel, target));
    return Status::Ok();
  }

  // Out of anchors: the last try.
  Status at_cap(RelaxedReconstruction* rec, double rms, double linf) {
    if (!enabled_) return Status::Ok();
    GAB_RETURN_IF_ERROR(try_refinement(rec));
    refined_ = acceptable(rms, linf);
    return Status::Ok();
  }

  bool refined() const { return refined_; }
  const Refinement& refinement() const { return last_; }

 private:
  Status try_refinement(RelaxedReconstruction* rec) {
    return refine_coefficients(rec, mesh_, quantizer_, iterations_, scale_, &last_);
  }
  // A refinement that lowers the RMS without breaking an L-inf target the
  // unrefined shape meets (least squares may raise the maximum).
  bool acceptable(double rms, double linf) const {
    const double linf_bound = std::max(target_linf_, linf);
    return last_.rms_rel < rms && (!(target_linf_ > 0) || last_.linf_rel <= linf_bound);
  }

  const Mesh& mesh_;
  const bool enabled_;
  const int iterations_;
  const double target_rms_, target_linf_;
  const Quantizer& quantizer_;
  const double scale_;
  double position_target_;
  Refinement last_;
  bool refined_ = false;
};

}  // namespace

GridPositions::GridPositions(const Mesh& mesh, const Quantizer& q) : quantizer(q), index(mesh.positions.size()) {
  for (size_t i = 0; i < index.size(); ++i) index[i] = q.quantize(mesh.positions[i], static_cast<int>(i % 3));
}

std::vector<double> GridPositions::coefficients_of(const std::vector<int32_t>& anchors) const {
  std::vector<double> coefficients(anchors.size() * 3);
  for (size_t i = 0; i < anchors.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      coefficients[3 * i + c] = quantizer.dequantize(index[3 * static_cast<size_t>(anchors[i]) + c], c);
    }
  }
  return coefficients;
}

Status select_anchors(const Mesh& mesh, const EdgeGraph& graph, const AnchorRules& rules,
                      const EncodeOptions& options, const GridPositions& grid, double scale,
                      const OrderingPlan& ordering, ShapeOperator* rec, Selection* out) {
  const int32_t n = mesh.num_vertices();
  *out = Selection();
  int32_t components = 0;
  connected_components(graph, &components);
  const int32_t cap = rules.max_anchors > 0 ? std::min(rules.max_anchors, n) : n;
  // By default at most half the anchors are spread ones: the greedy steps choose the rest.
  int32_t initial = rules.initial_anchors > 0 ? rules.initial_anchors
                                              : std::min(default_initial_anchors(n), std::max(1, cap / 2));
  initial = std::min(std::max(initial, components), std::max(cap, components));
  AnchorSchedule& schedule = out->schedule;
  GAB_RETURN_IF_ERROR(farthest_point_sampling(graph, initial, {}, &schedule.order));
  schedule.spread = static_cast<int32_t>(schedule.order.size());
  schedule.cuts.push_back(schedule.spread);

  rec->set_threads(options.threads);
  rec->apply(ordering);
  GAB_RETURN_IF_ERROR(rec->init(graph, options.weight, schedule.order, grid.coefficients_of(schedule.order)));
  // Without a factor (the iterative operator) the cheap regime's defaults.
  out->flops = rec->relaxed() ? rec->relaxed()->cholesky().symbolic().flops : 0.0;
  const double fraction = options.batch_fraction >= 0 ? options.batch_fraction : default_batch_fraction(out->flops);
  // A fraction asked for is kept; below kFarBatchFromVertices a round costs little.
  const double far_fraction = options.batch_fraction >= 0 || n < kFarBatchFromVertices ? 0.0 : kFarBatchFraction;
  const double growth = options.chunk_growth > 0 ? options.chunk_growth : default_chunk_growth(out->flops);

  // A grid of step s errs s / 2 in RMS.
  const double target_rms = rules.stop_at_grid_reach ? std::max(rules.target_rms_rel, kAnchorTargetOverGrid *
                                                                                          grid.quantizer.step / 2 * scale)
                                                     : rules.target_rms_rel;
  const double target_linf = rules.target_linf_rel;
  RefinementSearch refinement(mesh, rules.refine, options.refine_iterations, target_rms, target_linf, grid.quantizer,
                              scale);
  auto meets_a_target = [&](const VertexDistance& d) {
    return (target_rms > 0 && d.rms * scale <= target_rms) || (target_linf > 0 && d.linf * scale <= target_linf);
  };
  std::vector<double> shape, error2(n);
  while (true) {
    GAB_RETURN_IF_ERROR(rec->greedy_shape(&shape));
    VertexDistance distance;
    squared_vertex_errors(mesh, shape, &error2, &distance);
    if (!rec->global()) {
      // The greedy shape is not the decoder's: where the loop may stop (the
      // file's error), the decoder's shape instead.
      if (meets_a_target(distance) || rec->num_anchors() >= cap) {
        GAB_RETURN_IF_ERROR(rec->shape(&shape));
        squared_vertex_errors(mesh, shape, &error2, &distance);
      }
    }
    out->rms_rel = distance.rms * scale;
    out->linf_rel = distance.linf * scale;
    out->curve.push_back({rec->num_anchors(), out->rms_rel, out->linf_rel});
    if (options.progress) options.progress(rec->num_anchors(), out->rms_rel);
    if (rec->num_anchors() == schedule.cuts.back()) {
      // No anchor since the last cut: what the decoder holds when the next chunk starts.
      schedule.shapes.resize(schedule.cuts.size());
      if (rec->global()) {
        schedule.shapes.back() = shape;
      } else {
        GAB_RETURN_IF_ERROR(rec->prediction(nullptr, &schedule.shapes.back()));
        // The greedy shapes drift from the decoder's (each warm from the
        // last, fewer steps): the decoder's shape here sets them back on it
        // (fewer anchors for the target: 1.6% fewer bytes over five shared
        // meshes at 1e-3), and is the warm start of the next.
        std::vector<double> decoded;
        GAB_RETURN_IF_ERROR(rec->shape(&decoded));
      }
    }
    if (meets_a_target(distance)) break;
    if (rec->num_anchors() >= cap) {
      GAB_RETURN_IF_ERROR(refinement.at_cap(rec->relaxed(), out->rms_rel, out->linf_rel));
      break;
    }
    bool stop = false;
    GAB_RETURN_IF_ERROR(refinement.before_step(rec->relaxed(), out->rms_rel, out->linf_rel, &stop));
    if (stop) break;
    const std::vector<int32_t> next =
        pick_error_maxima(graph, error2, *rec,
                          next_batch(refinement.position_target(), fraction, far_fraction, out->curve, cap));
    GAB_RETURN_IF_ERROR(rec->add_anchors(next, grid.coefficients_of(next)));
    schedule.order.insert(schedule.order.end(), next.begin(), next.end());
    const int32_t opened_at = schedule.cuts.back();
    if (rec->num_anchors() >= growth * opened_at) schedule.cuts.push_back(rec->num_anchors());
  }
  if (schedule.cuts.back() < rec->num_anchors()) schedule.cuts.push_back(rec->num_anchors());
  out->shape = std::move(shape);
  out->refined = refinement.refined();
  if (out->refined) {
    out->refined_grid = refinement.refinement().grid;
    out->refined_rms_rel = refinement.refinement().rms_rel;
    out->refined_linf_rel = refinement.refinement().linf_rel;
  }
  return Status::Ok();
}

}  // namespace gab
