// The encoder's first stage: greedy anchor selection in a closed loop (the
// reconstruction is always from the quantized positions the decoder will
// get), and the least-squares refinement search. It writes no bytes: what it
// decides is a schedule the layouts code afterwards (encoder.cpp).
#pragma once

#include <cstdint>
#include <vector>

#include "anchors/quantizer.h"
#include "gab/codec/encoder.h"
#include "gab/mesh/edge_graph.h"
#include "gab/mesh/mesh.h"
#include "gab/status.h"
#include "pipeline/encode_candidates.h"
#include "pipeline/ordering_choice.h"
#include "reconstruction/shape_operator.h"

namespace gab {

// Every vertex's quantized position (3 grid indices per vertex): what an
// anchor sends.
struct GridPositions {
  GridPositions(const Mesh& mesh, const Quantizer& quantizer);
  // The dequantized positions of `anchors`, 3 each: their coefficients.
  std::vector<double> coefficients_of(const std::vector<int32_t>& anchors) const;

  const Quantizer& quantizer;
  std::vector<int32_t> index;
};

// What selection decided: the anchors in the order chosen and where each
// selection-order chunk ends, with the reconstructions the decoder holds at
// those ends (the predictions of the chunks after them).
struct AnchorSchedule {
  std::vector<int32_t> order;  // the spread set first, then the greedy batches
  int32_t spread = 0;          // order[0, spread): the spread set, chunk 0
  std::vector<int32_t> cuts;   // chunk k is order[k > 0 ? cuts[k - 1] : 0, cuts[k])
  // shapes[k]: the reconstruction from chunks 0..k, 3 per vertex (chunk k + 1's
  // prediction; the last chunk's may be missing).
  std::vector<std::vector<double>> shapes;
};

struct Selection {
  AnchorSchedule schedule;
  double flops = 0;                  // the first factorization's cost (what the default growths follow)
  double rms_rel = 0, linf_rel = 0;  // of the last reconstruction (unrefined)
  std::vector<double> shape;         // that reconstruction, 3 per vertex: every anchor at its quantized position
  std::vector<GreedyStep> curve;     // after every greedy step
  bool refined = false;              // the refinement is worth a chunk
  std::vector<int32_t> refined_grid;  // then: the refined grid indices, 3 per anchor in schedule order
  double refined_rms_rel = 0, refined_linf_rel = 0;
};

// Selects anchors on `mesh` (its edge graph `graph`) at their positions on
// `grid` until `rules` stop the loop or every vertex is an anchor; `options`
// give the loop's tuning only (weight, batch fraction, chunk growth,
// refinement iterations, threads, progress), never its targets. `rec` (a
// fresh operator: the file's) is left holding the anchors in schedule order
// at their quantized positions (global: factored in `ordering`); the
// schedule's shapes, the last shape and its errors are the decoder's.
// `scale`: 1 / the bounding-box diagonal. Cost, global: a factorization,
// then per step a solve and an update or refactorization (and a refinement
// try: 2 * refine_iterations + 1 solves); iterative: per step a ranking
// shape (the decoder's start and a few steps: greedy_steps) or near a target
// the decoder's shape, at each cut a prediction, and at the end up to
// kTrimEvaluations decoder's shapes (the shortest prefix that meets the
// target: the schedule's order ends there).
Status select_anchors(const Mesh& mesh, const EdgeGraph& graph, const AnchorRules& rules,
                      const EncodeOptions& options, const GridPositions& grid, double scale,
                      const OrderingPlan& ordering, ShapeOperator* rec, Selection* out);

}  // namespace gab
