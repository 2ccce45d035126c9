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
// far (the far one while the error is over kFarErrorOverTarget times an
// RMS target, when larger), but near an RMS target (0: none) only as many
// as the error curve's last two points (rms ~ k^-alpha) say are still needed.
int32_t next_batch(double target_rms_rel, const GreedyBatches& batches, const std::vector<GreedyStep>& curve,
                   int32_t cap) {
  const int32_t k = curve.back().anchors;
  const bool far = target_rms_rel > 0 && curve.back().rms_rel > kFarErrorOverTarget * target_rms_rel;
  const double fraction = far ? std::max(batches.fraction, batches.far_fraction) : batches.fraction;
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

// The loop's targets, relative to the diagonal (0: none); met when either is.
struct Targets {
  double rms = 0, linf = 0;
  double scale = 1;  // 1 / the diagonal
  // Relative errors within `factor` times a target.
  bool within(double factor, double rms_rel, double linf_rel) const {
    return (rms > 0 && rms_rel <= factor * rms) || (linf > 0 && linf_rel <= factor * linf);
  }
  bool met(const VertexDistance& d) const { return within(1.0, d.rms * scale, d.linf * scale); }
};

// A count of anchors and the relative RMS of the decoder's shape there
// (negative: not evaluated; anchors -1: none).
struct Evaluated {
  int32_t anchors = -1;
  double rms_rel = -1;
};

// The iterative operator's shape is a function of the anchor set alone, so
// every prefix of the selection order (the spread set and more) is a file.
// Once the anchors so far meet the targets, the shortest prefix that does,
// searched between a count that misses and one that meets: the RMS
// interpolated in log-log between them (rms ~ k^-alpha) for an RMS target,
// halved for an L-inf one, at most kTrimEvaluations shapes, each the
// decoder's on a fresh operator.
class ShortestPrefix {
 public:
  ShortestPrefix(const EdgeGraph& graph, const Mesh& mesh, const GridPositions& grid, const EncodeOptions& options,
                 const ShapeOperator& like, const std::vector<int32_t>& order, const Targets& targets)
      : graph_(graph), mesh_(mesh), grid_(grid), options_(options), like_(like), order_(order), targets_(targets) {}

  // `lo`: a count below found->anchors that misses the targets, its RMS
  // `lo_rms` (negative: not known, evaluated first: if it meets them after
  // all, it is the answer). *found: the count that meets them, replaced by
  // a shorter one that does, with its shape and distance.
  Status run(int32_t lo, double lo_rms, Evaluated* found, std::vector<double>* shape, VertexDistance* distance) {
    Evaluated low{lo, lo_rms};
    if (low.anchors < 0 || low.anchors >= found->anchors) return Status::Ok();
    std::vector<double> s;
    VertexDistance d;
    int evaluations = 0;
    if (low.rms_rel < 0) {
      GAB_RETURN_IF_ERROR(evaluate(low.anchors, &s, &d));
      ++evaluations;
      low.rms_rel = d.rms * targets_.scale;
      if (targets_.met(d)) {
        *found = low;
        *shape = std::move(s);
        *distance = d;
        return Status::Ok();
      }
    }
    while (evaluations < kTrimEvaluations &&
           found->anchors - low.anchors > std::max<int32_t>(1, found->anchors / kTrimPrecision)) {
      double t = 0.5;
      if (targets_.rms > 0 && low.rms_rel > targets_.rms && found->rms_rel < low.rms_rel) {
        t = std::log(low.rms_rel / targets_.rms) / std::log(low.rms_rel / found->rms_rel);
      }
      // Inside the bracket, never at an end: the log-log line may be off.
      t = std::min(0.9, std::max(0.1, t));
      const int32_t span = found->anchors - low.anchors;
      const int32_t k =
          std::min(found->anchors - 1, low.anchors + std::max(1, static_cast<int32_t>(std::ceil(t * span))));
      GAB_RETURN_IF_ERROR(evaluate(k, &s, &d));
      ++evaluations;
      const Evaluated at{k, d.rms * targets_.scale};
      if (targets_.met(d)) {
        *found = at;
        *shape = s;
        *distance = d;
      } else {
        low = at;
      }
    }
    return Status::Ok();
  }

 private:
  Status evaluate(int32_t k, std::vector<double>* shape, VertexDistance* distance) const {
    ShapeOperator op(like_.code());
    GAB_RETURN_IF_ERROR(tune(like_.tuning(), &op));
    op.set_threads(options_.threads);
    const std::vector<int32_t> prefix(order_.begin(), order_.begin() + k);
    GAB_RETURN_IF_ERROR(op.init(graph_, options_.weight, prefix, grid_.coefficients_of(prefix)));
    GAB_RETURN_IF_ERROR(op.shape(shape));
    std::vector<double> error2;
    squared_vertex_errors(mesh_, *shape, &error2, distance);
    return Status::Ok();
  }

  const EdgeGraph& graph_;
  const Mesh& mesh_;
  const GridPositions& grid_;
  const EncodeOptions& options_;
  const ShapeOperator& like_;
  const std::vector<int32_t>& order_;
  const Targets targets_;
};

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
  // A fraction asked for is kept throughout.
  const GreedyBatches batches = options.batch_fraction >= 0 ? GreedyBatches{options.batch_fraction, 0.0}
                                                            : default_greedy_batches(out->flops, !rec->global(), n);
  const double growth = options.chunk_growth > 0 ? options.chunk_growth : default_chunk_growth(out->flops);

  // A grid of step s errs s / 2 in RMS.
  const double target_rms = rules.stop_at_grid_reach ? std::max(rules.target_rms_rel, kAnchorTargetOverGrid *
                                                                                          grid.quantizer.step / 2 * scale)
                                                     : rules.target_rms_rel;
  const double target_linf = rules.target_linf_rel;
  RefinementSearch refinement(mesh, rules.refine, options.refine_iterations, target_rms, target_linf, grid.quantizer,
                              scale);
  const Targets targets{target_rms, target_linf, scale};
  const bool iterative = !rec->global();
  auto near_a_target = [&](double rms_rel, double linf_rel) {
    return targets.within(kDecoderCheckWithin, rms_rel, linf_rel);
  };
  std::vector<double> shape, error2(n);
  // Iterative: the most anchors whose decoder's shape missed the targets.
  Evaluated missed;
  while (true) {
    const int32_t k = rec->num_anchors();
    const bool far =
        target_rms > 0 && (out->curve.empty() || out->curve.back().rms_rel > kFarErrorOverTarget * target_rms);
    // Iterative, once near a target: the decoder's shape alone.
    const bool near = iterative && !out->curve.empty() && near_a_target(out->curve.back().rms_rel, out->curve.back().linf_rel);
    VertexDistance distance;
    if (!near) {
      GAB_RETURN_IF_ERROR(rec->greedy_shape(greedy_steps(n, far), &shape));
      squared_vertex_errors(mesh, shape, &error2, &distance);
    }
    bool met = !iterative && targets.met(distance);
    if (iterative && (near || near_a_target(distance.rms * scale, distance.linf * scale) || k >= cap)) {
      // The ranking shape is not the decoder's: where the loop may stop (the
      // file's error), the decoder's shape instead, which ranks the next
      // batch too.
      GAB_RETURN_IF_ERROR(rec->shape(&shape));
      squared_vertex_errors(mesh, shape, &error2, &distance);
      met = targets.met(distance);
      if (!met) missed = {k, distance.rms * scale};
    }
    out->rms_rel = distance.rms * scale;
    out->linf_rel = distance.linf * scale;
    out->curve.push_back({k, out->rms_rel, out->linf_rel});
    if (options.progress) options.progress(k, out->rms_rel);
    if (k == schedule.cuts.back()) {
      // No anchor since the last cut: what the decoder holds when the next chunk starts.
      schedule.shapes.resize(schedule.cuts.size());
      if (iterative) {
        GAB_RETURN_IF_ERROR(rec->prediction(nullptr, &schedule.shapes.back()));
      } else {
        schedule.shapes.back() = shape;
      }
    }
    if (met) {
      if (iterative) {
        // The last batch may have overshot: its shortest prefix that meets the targets.
        Evaluated below = missed;
        if (below.anchors < 0 && out->curve.size() >= 2) below = {out->curve[out->curve.size() - 2].anchors, -1.0};
        ShortestPrefix search(graph, mesh, grid, options, *rec, schedule.order, targets);
        Evaluated found{k, out->rms_rel};
        GAB_RETURN_IF_ERROR(
            search.run(std::max(below.anchors, schedule.spread), below.rms_rel, &found, &shape, &distance));
        if (found.anchors < k) {
          schedule.order.resize(found.anchors);
          while (schedule.cuts.back() > found.anchors) schedule.cuts.pop_back();
          schedule.shapes.resize(std::min(schedule.shapes.size(), schedule.cuts.size()));
          GAB_RETURN_IF_ERROR(rec->init(graph, options.weight, schedule.order, grid.coefficients_of(schedule.order)));
          out->rms_rel = distance.rms * scale;
          out->linf_rel = distance.linf * scale;
          out->curve.push_back({found.anchors, out->rms_rel, out->linf_rel});
        }
      }
      break;
    }
    if (k >= cap) {
      GAB_RETURN_IF_ERROR(refinement.at_cap(rec->relaxed(), out->rms_rel, out->linf_rel));
      break;
    }
    bool stop = false;
    GAB_RETURN_IF_ERROR(refinement.before_step(rec->relaxed(), out->rms_rel, out->linf_rel, &stop));
    if (stop) break;
    const std::vector<int32_t> next =
        pick_error_maxima(graph, error2, *rec, next_batch(refinement.position_target(), batches, out->curve, cap),
                          iterative ? batch_separation(n, k) : 0);
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
