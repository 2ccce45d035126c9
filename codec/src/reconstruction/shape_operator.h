// The reconstruction operator a .gab file names (header byte 12): the shape
// its anchors make, evaluated the same way by the encoder and the decoder.
// kGabReconstructionGlobal is the paper's relaxed least squares, factored
// (RelaxedReconstruction: anchors join by updates or refactorizations);
// kGabReconstructionIterative the same system by iterative_steps
// conjugate-gradient steps from the nearest-anchor start
// (IterativeReconstruction), linear in n: a function of the anchor set and
// its coefficients alone, whatever order or chunks they came in.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "gab/mesh/edge_graph.h"
#include "gab/mesh/iterative_reconstruction.h"
#include "gab/mesh/relaxed_reconstruction.h"
#include "gab/status.h"

namespace gab {

class OrderingPlan;

// Conjugate-gradient steps of the iterative operator's shape for k anchors
// on n vertices. The anchors' spacing squared, in hops, is about n / k; at
// 2 n / k steps the shape is the least squares' to 1e-3 of its error
// (bench/reconstruction_candidates). A shape that is the decoder's result
// takes ceil(2 n / k), at most 64; a shape that only predicts the next
// chunk, ceil(1.5 n / k), at most 32: a rougher prediction costs that chunk
// bits, the steps cost every decode (horse at 1e-3: at most 16 steps,
// +7.3% bytes against the global operator and 0.21 s; 32, +3.7% and 0.30 s;
// 64, +4.4% and 0.75 s, a busy machine, bench/solver_compare).
struct IterativeSteps {
  double per_spacing;
  int32_t most;
};
constexpr IterativeSteps kIterativeFinalSteps = {2.0, 64};
constexpr IterativeSteps kIterativePredictionSteps = {1.5, 32};
// The encoder's greedy shapes, each warm from the one before: fewer steps.
constexpr IterativeSteps kIterativeGreedySteps = {0.5, 16};
int32_t iterative_steps(int32_t n, int32_t k, const IterativeSteps& rule);

class ShapeOperator {
 public:
  // `code`: a kGabReconstruction* value the header check accepted.
  explicit ShapeOperator(uint8_t code);
  uint8_t code() const { return code_; }
  bool global() const { return global_ != nullptr; }

  // Threads for the factorizations or the iterative steps (the same shapes
  // for any count).
  void set_threads(int32_t threads);
  // Global only (no-ops otherwise): the ordering, and a bound on the
  // factor's entries (RelaxedReconstruction).
  void apply(const OrderingPlan& ordering);
  void set_max_factor_entries(int64_t entries);

  Status init(const EdgeGraph& graph, double weight, const std::vector<int32_t>& anchors,
              const std::vector<double>& coefficients);
  // Anchors joining (global: update or refactorization, the cheaper by the
  // cost model; *refactored says which).
  Status add_anchors(const std::vector<int32_t>& anchors, const std::vector<double>& coefficients,
                     bool* refactored = nullptr);
  Status set_coefficients(int32_t first, const std::vector<double>& coefficients);
  // The shape of the anchors so far, 3 per vertex: the operator's, which
  // the decoder computes; `prediction`: one that only predicts the next
  // chunk (the iterative operator's rougher one).
  Status shape(std::vector<double>* positions, bool prediction = false);
  // A shape for the encoder's greedy loop, which only ranks vertices by
  // error: iterative, the final rule's steps from the shape before (warm;
  // not what a decoder computes); global, shape's.
  Status greedy_shape(std::vector<double>* positions);

  int32_t num_anchors() const;
  bool is_anchor(int32_t v) const;
  const std::vector<int32_t>& anchors() const;
  const std::vector<double>& coefficients() const;
  // The factored solver (global only; null otherwise).
  RelaxedReconstruction* relaxed() { return global_.get(); }
  const RelaxedReconstruction* relaxed() const { return global_.get(); }

 private:
  uint8_t code_;
  std::unique_ptr<RelaxedReconstruction> global_;
  std::unique_ptr<IterativeReconstruction> iterative_;
};

}  // namespace gab
