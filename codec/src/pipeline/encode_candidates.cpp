#include "pipeline/encode_candidates.h"

#include <algorithm>

#include "gab/codec/gab_format.h"
#include "pipeline/encoder_tuning.h"

namespace gab {

namespace {

// The caller's rules on the default grid for its targets.
EncodeCandidate anchors_only(const EncodeOptions& options, const MeshSize& size) {
  EncodeCandidate c;
  c.name = "anchors";
  c.anchors.bits = options.bits != 0 ? options.bits
                                     : default_bits(size.diagonal > 0 ? size.extent / size.diagonal : 1.0,
                                                    options.target_rms_rel, options.target_linf_rel);
  c.anchors.target_rms_rel = options.target_rms_rel;
  c.anchors.target_linf_rel = options.target_linf_rel;
  c.anchors.max_anchors = options.max_anchors;
  c.anchors.initial_anchors = options.initial_anchors;
  c.anchors.refine = options.refine;
  return c;
}

// Anchors to `anchor_rms_rel` on q = `bits` (0: the default grid for that
// target) from a small spread set, or the spread set alone, under a detail
// chunk meeting the caller's targets. No refinement: the detail chunk moves
// every vertex anyway.
EncodeCandidate under_detail(const EncodeOptions& options, const MeshSize& size, const char* name,
                             double anchor_rms_rel, int bits, bool spread_only) {
  EncodeCandidate c;
  c.name = name;
  c.detail = true;
  AnchorRules& a = c.anchors;
  a.bits = options.bits != 0 ? options.bits
           : bits != 0       ? bits
                             : default_bits(size.extent / size.diagonal, anchor_rms_rel, 0);
  a.target_rms_rel = anchor_rms_rel;
  a.stop_at_grid_reach = true;
  a.initial_anchors = options.initial_anchors > 0
                          ? options.initial_anchors
                          : std::max<int32_t>(1, static_cast<int32_t>(size.num_vertices * kDetailSpreadShare));
  const int32_t cap =
      spread_only ? a.initial_anchors
                  : std::max(a.initial_anchors, static_cast<int32_t>(size.num_vertices * kDetailMaxAnchorShare));
  a.max_anchors = options.max_anchors > 0 ? std::min(options.max_anchors, cap) : cap;
  return c;
}

}  // namespace

std::vector<EncodeCandidate> encode_candidates(const EncodeOptions& options, const MeshSize& size) {
  std::vector<EncodeCandidate> out;
  const bool detail_possible = options.detail != DetailMode::kOff && size.diagonal > 0 && size.extent > 0 &&
                               (options.target_rms_rel > 0 || options.target_linf_rel > 0);
  if (!detail_possible) {
    out.push_back(anchors_only(options, size));
    return out;
  }
  // The target in RMS terms decides: anchors alone down to kAnchorsOnlyFrom,
  // a detail layer from kDetailFrom down (both between), a detail layer to
  // rescue a target the anchors alone missed.
  const double target =
      options.target_rms_rel > 0 ? options.target_rms_rel : options.target_linf_rel / kLinfOverRms;
  const bool anchors = options.detail == DetailMode::kAuto && target >= kAnchorsOnlyFrom;
  if (anchors) out.push_back(anchors_only(options, size));
  const bool rescue_only = anchors && !(target < kDetailFrom);
  const double anchor_target = std::max(kDetailAnchorTarget, kAnchorTargetOverTarget * target);
  out.push_back(under_detail(options, size, "detail", anchor_target, 0, false));
  out.back().rescue_only = rescue_only;
  // A fixed q puts both detail candidates' anchors on the same grid: the first is enough.
  if (options.bits == 0) {
    out.push_back(under_detail(options, size, "detail over coarse anchors", anchor_target, kCoarseAnchorBits,
                               target < kSpreadOnlyBelow));
    out.back().rescue_only = rescue_only;
  }
  return out;
}

bool dense_grid_candidate(const EncodeOptions& options, const MeshSize& size, const EncodeCandidate& tried,
                          int32_t anchors, EncodeCandidate* retry) {
  const bool dense = anchors > kDenseAnchorFraction * size.num_vertices;
  if (!dense || tried.detail || tried.anchors.min_step_rel > 0 || options.bits != 0 || !(options.target_rms_rel > 0) || !(size.diagonal > 0)) {
    return false;
  }
  // The grid whose error alone is kDenseGridShare of the RMS target (a grid
  // of step s errs s / 2 in RMS), at the fewest bits that cover the box.
  const double step_rel = 2 * kDenseGridShare * options.target_rms_rel;
  const double step = step_rel * size.diagonal;
  int bits = kGabMinBits;
  while (bits < kGabMaxBits && static_cast<double>((int64_t{1} << bits) - 1) * step < size.extent) ++bits;
  // Not coarser than the grid tried: nothing to gain.
  const double tried_step = size.extent / static_cast<double>((int64_t{1} << tried.anchors.bits) - 1);
  const double coarse_step = std::max(size.extent / static_cast<double>((int64_t{1} << bits) - 1), step);
  if (!(coarse_step > tried_step)) return false;
  *retry = tried;
  retry->name = "anchors on a coarser grid";
  retry->anchors.bits = bits;
  retry->anchors.min_step_rel = step_rel;
  return true;
}

}  // namespace gab
