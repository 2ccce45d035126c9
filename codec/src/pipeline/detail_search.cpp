#include "pipeline/detail_search.h"

#include <algorithm>
#include <cmath>

#include "gab/mesh/metrics.h"

namespace gab {

namespace {

// The blends tried, in sixteenths (normal, tangential), the default first.
constexpr int kNormalBlends[] = {4, 0, 2, 6, 8, 12, 16};
constexpr int kTangentBlends[] = {0, 4, 8, 12};
// Step search (Search::largest_step): at most kFitTrials secant steps, each
// moving the step by at most kMaxFitMove and aiming kFitMargin inside the
// target, done once within kFitTolerance of it (0.4% of the step: about
// 0.02 bits per coordinate); then, if nothing met the target, shrinking by
// kStepShrink down to the smallest step.
constexpr int kFitTrials = 6;
constexpr double kMaxFitMove = 4;
constexpr double kFitMargin = 0.001;
constexpr double kFitTolerance = 0.004;
constexpr double kStepShrink = 0.8;
// Rate weights tried (DetailParams::rate_weight), and the step each starts its
// search from, relative to plain rounding's.
constexpr double kRateWeights[] = {0.05, 0.1};
constexpr double kRateStepGuess = 0.9;
// How far from the box the smooth shape may lie, in box extents: the
// detail lattice (kMinDetailStep / kSmoothDivisions) then stays under 2^52.
constexpr double kMaxSmoothReach = 1 << 20;

// One encoding tried: what the search returns (its `trials` set at the end).
using Trial = DetailChoice;

class Search {
 public:
  Search(const DetailTopology& topo, const DetailFrame& frame, const std::vector<double>& smooth, const Mesh& mesh,
         double scale, double rms, double linf)
      : topo_(topo), frame_(frame), smooth_(smooth), mesh_(mesh), scale_(scale), rms_(rms), linf_(linf) {}

  Trial run(const DetailParams& params) {
    Trial t;
    t.params = params;
    t.chunk = encode_detail_chunk(topo_, frame_, smooth_, mesh_.positions, params, &decoded_, &scratch_);
    VertexDistance d;
    squared_vertex_errors(mesh_, decoded_, &error2_, &d);
    t.rms_rel = d.rms * scale_;
    t.linf_rel = d.linf * scale_;
    t.met = (rms_ <= 0 || t.rms_rel <= rms_) && (linf_ <= 0 || t.linf_rel <= linf_);
    ++trials_;
    return t;
  }

  // The largest step (within [lo, hi]) meeting the targets at this blend,
  // searched from `start`; the finest tried when none does. The errors of a
  // uniform quantizer grow in proportion to its step, so each trial aims the
  // next at the target by their ratio (a secant step) and the search ends
  // within kFitTolerance of it, in 2-3 trials; what the proportion misses
  // (rounding's zeros, a maximum) the next trial corrects.
  Trial largest_step(DetailParams params, double start, double lo, double hi) {
    params.step = std::min(hi, std::max(lo, start));
    Trial best, finest;
    for (int i = 0; i < kFitTrials; ++i) {
      Trial t = run(params);
      const double ratio = headroom(t);
      const bool close = t.met && ratio < 1 + kFitTolerance;
      const double step = t.params.step;
      if (t.met && (!best.met || step > best.params.step)) {
        best = std::move(t);
      } else if (!t.met && (finest.chunk.empty() || step < finest.params.step)) {
        finest = std::move(t);
      }
      if (close) break;
      double next = step * std::min(kMaxFitMove, std::max(1 / kMaxFitMove, ratio * (1 - kFitMargin)));
      next = std::min(hi, std::max(lo, next));
      if (best.met && next <= best.params.step) next = best.params.step * (1 + kFitTolerance / 2);
      if (next == step || next > hi) break;
      params.step = next;
    }
    if (best.met) return best;
    // Not met even at the finest step tried: shrink on down to the lower bound.
    params.step = finest.params.step;
    while (params.step * kStepShrink >= lo) {
      params.step *= kStepShrink;
      Trial t = run(params);
      if (t.met) return t;
      finest = std::move(t);
    }
    return finest;
  }

  int trials() const { return trials_; }

  // How much the errors may grow: the smallest target over error ratio.
  double headroom(const Trial& t) const {
    double ratio = kMaxFitMove;
    if (rms_ > 0) ratio = std::min(ratio, t.rms_rel > 0 ? rms_ / t.rms_rel : kMaxFitMove);
    if (linf_ > 0) ratio = std::min(ratio, t.linf_rel > 0 ? linf_ / t.linf_rel : kMaxFitMove);
    return ratio;
  }

 private:
  const DetailTopology& topo_;
  const DetailFrame& frame_;
  const std::vector<double>& smooth_;
  const Mesh& mesh_;
  const double scale_, rms_, linf_;
  std::vector<double> decoded_, error2_;
  DetailScratch scratch_;
  int trials_ = 0;
};

// The checks every entry makes.
Status check_search(const DetailFrame& frame, const std::vector<double>& smooth, double scale, double target_rms_rel,
                    double target_linf_rel) {
  if (!(frame.extent > 0) || !(scale > 0) || !(target_rms_rel > 0 || target_linf_rel > 0)) {
    return Status::Error(StatusCode::kInvalidArgument, "a detail layer needs a box of some size and an error target");
  }
  // The smooth shape must lie well within the lattice's reach (a finite
  // reconstruction of anchors inside the box always does).
  for (size_t i = 0; i < smooth.size(); ++i) {
    if (!(std::fabs(smooth[i] - frame.origin[i % 3]) < kMaxSmoothReach * frame.extent)) {
      return Status::Error(StatusCode::kNotPositiveDefinite, "the anchors' shape is not finite or far outside the box");
    }
  }
  return Status::Ok();
}

}  // namespace

Status fit_detail(const DetailTopology& topo, const DetailFrame& frame, const std::vector<double>& smooth,
                  const Mesh& mesh, double scale, double target_rms_rel, double target_linf_rel, DetailChoice* out) {
  GAB_RETURN_IF_ERROR(check_search(frame, smooth, scale, target_rms_rel, target_linf_rel));
  Search search(topo, frame, smooth, mesh, scale, target_rms_rel, target_linf_rel);
  const double diagonal = 1.0 / scale;
  // A uniform quantizer of step s errs s / 2 in RMS over three axes, at most s sqrt(3) / 2.
  double start = HUGE_VAL;
  if (target_rms_rel > 0) start = 2 * target_rms_rel * diagonal;
  if (target_linf_rel > 0) start = std::min(start, 2 * target_linf_rel * diagonal / std::sqrt(3.0));
  DetailParams params;
  params.alpha_normal16 = kNormalBlends[0];
  params.alpha_tangent16 = kTangentBlends[0];
  *out = search.largest_step(params, start, kMinDetailStep * frame.extent, kMaxDetailStep * frame.extent);
  out->trials = search.trials();
  return Status::Ok();
}

Status improve_detail(const DetailTopology& topo, const DetailFrame& frame, const std::vector<double>& smooth,
                      const Mesh& mesh, double scale, double target_rms_rel, double target_linf_rel,
                      DetailChoice* choice) {
  GAB_RETURN_IF_ERROR(check_search(frame, smooth, scale, target_rms_rel, target_linf_rel));
  if (!choice->met) return Status::Ok();  // nothing meets the targets: the finest step stands
  Search search(topo, frame, smooth, mesh, scale, target_rms_rel, target_linf_rel);
  const double lo = kMinDetailStep * frame.extent, hi = kMaxDetailStep * frame.extent;
  const int trials_before = choice->trials;
  Trial& best = *choice;
  // The blend that codes smallest at that step: the normal weight first,
  // then the tangential one (the two interact little). Each weight's values
  // are tried from the best parameters so far.
  const DetailParams first = best.params;
  auto try_each = [&](const auto& values, int DetailParams::*weight) {
    const DetailParams from = best.params;
    for (int value : values) {
      if (value == from.*weight) continue;
      DetailParams p = from;
      p.*weight = value;
      Trial t = search.run(p);
      if (!t.met && t.chunk.size() < best.chunk.size()) {
        // Smaller but just past the target at this step (a blend moves the
        // errors a little): the largest step that meets it with this blend.
        t = search.largest_step(p, p.step * search.headroom(t) * (1 - kFitMargin), lo, hi);
      }
      if (t.met && t.chunk.size() < best.chunk.size()) best = std::move(t);
    }
  };
  try_each(kNormalBlends, &DetailParams::alpha_normal16);
  try_each(kTangentBlends, &DetailParams::alpha_tangent16);
  // The step again for that blend (its zeros err a little differently).
  if (best.params.alpha_normal16 != first.alpha_normal16 || best.params.alpha_tangent16 != first.alpha_tangent16) {
    Trial again = search.largest_step(best.params, best.params.step, best.params.step, hi);
    if (again.met && again.chunk.size() <= best.chunk.size()) best = std::move(again);
  }
  // Rate-distortion rounding, each weight with the step it can afford.
  const DetailParams plain = best.params;
  for (double weight : kRateWeights) {
    DetailParams p = plain;
    p.rate_weight = weight;
    Trial t = search.largest_step(p, plain.step * kRateStepGuess, lo, hi);
    if (t.met && t.chunk.size() < best.chunk.size()) best = std::move(t);
  }
  best.trials = trials_before + search.trials();
  return Status::Ok();
}

}  // namespace gab
