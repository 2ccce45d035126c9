// The reconstruction operator a .gab file names (header byte 12): the shape
// its anchors make, evaluated the same way by the encoder and the decoder.
// kGabReconstructionGlobal is the paper's relaxed least squares, factored
// (RelaxedReconstruction: anchors join by updates or refactorizations);
// kGabReconstructionIterative the same system by iterative_steps
// conjugate-gradient steps from the nearest-anchor start
// (IterativeReconstruction), linear in n: a function of the anchor set and
// its coefficients alone, whatever order or chunks they came in;
// kGabReconstructionIterativeLocal the same shape, a chunk predicted by the
// start alone at the chunk's vertices (cost: the ring around them);
// kGabReconstructionIterativeTuned operator 2 with its sweeps and final
// steps set by the file (iterative_tuning.h).
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "gab/mesh/edge_graph.h"
#include "gab/mesh/iterative_reconstruction.h"
#include "gab/mesh/relaxed_reconstruction.h"
#include "gab/status.h"
#include "reconstruction/iterative_tuning.h"

namespace gab {

class OrderingPlan;

// Conjugate-gradient steps of the iterative operator's shape for k anchors
// on n vertices. The anchors' spacing squared, in hops, is about n / k, and
// the steps a shape needs grow with it. A shape that is the decoder's result
// takes ceil(1.0 n / k), at most 32; a shape that only predicts the next
// chunk, ceil(0.75 n / k), at most 16: a rougher prediction costs that chunk
// bits, the steps cost every decode. Measured at 1e-3 --reorder, with the
// start's harmonic sweeps (whole file against the global operator's, decode
// seconds; docs/tuning-codec.md): twice these steps (2.0 and 1.5 per
// spacing, at most 64 and 32) gave horse 1.024x, feline 1.028x, igea 0.983x
// in about 1.7x the decode; these give 1.048x, 1.049x, 0.999x; half of them
// 1.085x, 1.066x, 1.029x, and camel-head 1.375x (1.128x here).
struct IterativeSteps {
  double per_spacing;
  int32_t most;
};
constexpr IterativeSteps kIterativeFinalSteps = {1.0, 32};
constexpr IterativeSteps kIterativePredictionSteps = {0.75, 16};
int32_t iterative_steps(int32_t n, int32_t k, const IterativeSteps& rule);

// Operator 2 predicts a chunk by its start alone (each vertex at its nearest
// anchor, smoothed), evaluated around the chunk's vertices: no step over the
// whole mesh per chunk. On a small mesh such steps cost little and a chunk
// of many anchors gains from them (bunny-small, 3,485 vertices, 92% of them
// anchors at 1e-3: 4.3% fewer bytes, camel-head 1.8%): meshes of at most
// kLocalPredictionMostVertices take kIterativePredictionSteps's steps
// from the start, at most kLocalPredictionStepBudget / n of them. (Up to
// 2^15, max-planck's 25,445 vertices took 2 steps a chunk: 0.6% fewer
// bytes for 1.4x its decode.)
constexpr int32_t kLocalPredictionMostVertices = 1 << 14;
constexpr int32_t kLocalPredictionStepBudget = 1 << 16;  // vertices times steps
int32_t local_prediction_steps(int32_t n, int32_t k);

class ShapeOperator {
 public:
  // `code`: a kGabReconstruction* value the header check accepted.
  explicit ShapeOperator(uint8_t code);
  uint8_t code() const { return code_; }
  bool global() const { return global_ != nullptr; }
  // Operator 3 only, before init: its parameters (default kOperator2Tuning's).
  Status set_tuning(const IterativeTuning& tuning);
  const IterativeTuning& tuning() const { return tuning_; }

  // Threads for the factorizations or the iterative steps (the same shapes
  // for any count).
  void set_threads(int32_t threads);
  // Global only (no-ops otherwise): the ordering, and a bound on the
  // factor's entries (RelaxedReconstruction).
  void apply(const OrderingPlan& ordering);
  void set_max_factor_entries(int64_t entries);

  // `nearest` (optional): the nearest-anchor map after these anchors, as a
  // FarthestPointSampler whose chosen vertices are the anchors keeps it;
  // the operators that start from nearest anchors (2 and 3) take it instead
  // of searching, the others ignore it.
  Status init(const EdgeGraph& graph, double weight, const std::vector<int32_t>& anchors,
              const std::vector<double>& coefficients, const std::vector<uint64_t>* nearest = nullptr);
  // Anchors joining (global: update or refactorization, the cheaper by the
  // cost model; *refactored says which); `nearest` as for init.
  Status add_anchors(const std::vector<int32_t>& anchors, const std::vector<double>& coefficients,
                     bool* refactored = nullptr, const std::vector<uint64_t>* nearest = nullptr);
  Status set_coefficients(int32_t first, const std::vector<double>& coefficients);
  // The shape of the anchors so far, 3 per vertex: the operator's, which
  // the decoder computes.
  Status shape(std::vector<double>* positions);
  // The shape that predicts the next chunk at its vertices `at` (null: not
  // known yet; every vertex), 3 per vertex, other vertices' entries
  // unspecified: the global operator's shape; operator 1's rougher one
  // (fewer steps); operator 2's start, at a cost of the ring around `at`.
  Status prediction(const std::vector<int32_t>* at, std::vector<double>* positions);
  // A shape for the encoder's greedy loop, which only ranks vertices by
  // error: global, shape's; iterative, shape's computation (the same start
  // and sweeps) cut to at most `most_steps` steps: where the decoder's shape
  // errs most, for fewer passes over the mesh.
  Status greedy_shape(int32_t most_steps, std::vector<double>* positions);

  int32_t num_anchors() const;
  bool is_anchor(int32_t v) const;
  const std::vector<int32_t>& anchors() const;
  const std::vector<double>& coefficients() const;
  // The factored solver (global only; null otherwise).
  RelaxedReconstruction* relaxed() { return global_.get(); }
  const RelaxedReconstruction* relaxed() const { return global_.get(); }

 private:
  // Operators 2 and 3: predictions by the start alone, final steps by the tuning.
  bool local() const;
  // Iterative: the conjugate-gradient steps of shape() for the anchors so far.
  int32_t final_step_count() const;

  uint8_t code_;
  IterativeTuning tuning_ = kOperator2Tuning;
  std::unique_ptr<RelaxedReconstruction> global_;
  std::unique_ptr<IterativeReconstruction> iterative_;
};

// `tuning` on an operator 3 (its set_tuning); the others take none: Ok.
Status tune(const IterativeTuning& tuning, ShapeOperator* op);

}  // namespace gab
