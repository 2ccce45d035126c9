// Greedy anchor selection, one anchor per step as in the paper (Sorkine et
// al. 2005, sec. IV): start from a well-spread set, then repeatedly
// reconstruct, anchor the vertex whose reconstruction is farthest (in 3D)
// from its original position, and update the factor.
#pragma once

#include <cstdint>
#include <vector>

#include "gab/mesh/edge_graph.h"
#include "gab/mesh/mesh.h"
#include "gab/mesh/relaxed_reconstruction.h"
#include "gab/status.h"

namespace gab {

struct GreedyOptions {
  double weight = 1.0;        // anchor weight w of the relaxed basis
  int32_t initial = 0;        // farthest-point (hop) spread anchors to start from;
                              // raised to one per connected component
  int32_t max_anchors = 100;  // stop when this many anchors are chosen
  double target_rms_rel = 0;  // or when the relative vertex RMS is at most this (0: off)
  // 0: one anchor per step (the paper). Otherwise each step anchors up to
  // max(1, ceil(batch_fraction * anchors so far)) vertices among those whose
  // error is a maximum over their 1-ring (so a batch never piles anchors onto
  // one bump), largest 1-ring error mass first (pick_error_maxima).
  double batch_fraction = 0.0;
  int32_t threads = 1;  // for the factorizations; the anchors do not depend on it
};

// One point of the error curve: after `anchors` anchors, the vertex RMS and
// max 3D distance, relative to the bounding-box diagonal.
struct GreedyStep {
  int32_t anchors;
  double rms_rel;
  double linf_rel;
};

// Chooses anchors (initial set first, then in selection order) with their
// exact original positions as coefficients (quantization belongs to the
// codec). `curve` gets one entry per reconstruction. Cost per step: one
// three-right-hand-side solve, one (batched) factor update, an O(V + E)
// error scan.
Status select_anchors_greedy(const Mesh& mesh, const EdgeGraph& graph, const GreedyOptions& options,
                             std::vector<int32_t>* anchors, std::vector<GreedyStep>* curve);

// The `count` (> 1) vertices not anchored in `rec` among the 1-ring local
// maxima of `error` (at least every neighbour's) whose error has the largest
// mean over their closed 1-ring, largest first, ties to the smaller index.
// With count == 1 the worst free vertex (the paper's rule), local maximum or
// not; if no free vertex is a local maximum, the worst free vertex, so a
// greedy loop always progresses. Needs a free vertex. O(V + E + c log c),
// c the local maxima.
std::vector<int32_t> pick_error_maxima(const EdgeGraph& graph, const std::vector<double>& error,
                                       const RelaxedReconstruction& rec, int32_t count);

}  // namespace gab
