#include "reconstruction/shape_operator.h"

#include <algorithm>
#include <cmath>

#include "gab/codec/gab_format.h"
#include "pipeline/ordering_choice.h"

namespace gab {

int32_t iterative_steps(int32_t n, int32_t k, const IterativeSteps& rule) {
  const double steps = std::ceil(rule.per_spacing * static_cast<double>(n) / std::max(k, 1));
  return static_cast<int32_t>(std::min<double>(steps, rule.most));
}

int32_t local_prediction_steps(int32_t n, int32_t k) {
  if (n > kLocalPredictionMostVertices) return 0;
  return std::min(iterative_steps(n, k, kIterativePredictionSteps), kLocalPredictionStepBudget / std::max(n, 1));
}

ShapeOperator::ShapeOperator(uint8_t code) : code_(code) {
  if (code == kGabReconstructionGlobal) {
    global_ = std::make_unique<RelaxedReconstruction>();
    return;
  }
  iterative_ = std::make_unique<IterativeReconstruction>();
  if (local()) iterative_->set_nearest_rule(IterativeReconstruction::NearestRule::kFewestHopsLowest);
}

bool ShapeOperator::local() const {
  return code_ == kGabReconstructionIterativeLocal || code_ == kGabReconstructionIterativeTuned;
}

Status ShapeOperator::set_tuning(const IterativeTuning& tuning) {
  if (code_ != kGabReconstructionIterativeTuned) {
    return Status::Error(StatusCode::kInvalidArgument, "only operator 3 takes parameters");
  }
  if (!tuning_in_range(tuning)) return Status::Error(StatusCode::kInvalidArgument, "operator parameters out of range");
  GAB_RETURN_IF_ERROR(iterative_->set_start_sweeps(tuning.prediction_sweeps, tuning.final_sweeps));
  tuning_ = tuning;
  return Status::Ok();
}

void ShapeOperator::set_threads(int32_t threads) {
  if (global_) global_->set_threads(threads);
  if (iterative_) iterative_->set_threads(threads);
}

void ShapeOperator::apply(const OrderingPlan& ordering) {
  if (global_) ordering.apply(global_.get());
}

void ShapeOperator::set_max_factor_entries(int64_t entries) {
  if (global_) global_->set_max_factor_entries(entries);
}

Status ShapeOperator::init(const EdgeGraph& graph, double weight, const std::vector<int32_t>& anchors,
                           const std::vector<double>& coefficients, const std::vector<uint64_t>* nearest) {
  if (global_) return global_->init(graph, weight, anchors, coefficients);
  return nearest && local() ? iterative_->init(graph, weight, anchors, coefficients, *nearest)
                            : iterative_->init(graph, weight, anchors, coefficients);
}

Status ShapeOperator::add_anchors(const std::vector<int32_t>& anchors, const std::vector<double>& coefficients,
                                  bool* refactored, const std::vector<uint64_t>* nearest) {
  if (refactored) *refactored = false;
  if (global_) return global_->add_anchors_cheapest(anchors, coefficients, refactored);
  return nearest && local() ? iterative_->add_anchors(anchors, coefficients, *nearest)
                            : iterative_->add_anchors(anchors, coefficients);
}

Status ShapeOperator::set_coefficients(int32_t first, const std::vector<double>& coefficients) {
  return global_ ? global_->set_coefficients(first, coefficients) : iterative_->set_coefficients(first, coefficients);
}

int32_t ShapeOperator::final_step_count() const {
  const int32_t n = iterative_->num_vertices(), k = iterative_->num_anchors();
  return local() ? final_steps(tuning_, n, k) : iterative_steps(n, k, kIterativeFinalSteps);
}

Status ShapeOperator::shape(std::vector<double>* positions) {
  if (global_) return global_->reconstruct(positions);
  iterative_->restart();
  return iterative_->solve(final_step_count(), positions);
}

Status ShapeOperator::prediction(const std::vector<int32_t>* at, std::vector<double>* positions) {
  if (global_) return global_->reconstruct(positions);
  if (code_ == kGabReconstructionIterative) {
    iterative_->restart();
    return iterative_->solve(
        iterative_steps(iterative_->num_vertices(), iterative_->num_anchors(), kIterativePredictionSteps), positions);
  }
  const int32_t steps = local_prediction_steps(iterative_->num_vertices(), iterative_->num_anchors());
  if (steps > 0) {
    iterative_->restart();
    return iterative_->solve(steps, positions);
  }
  positions->resize(3 * static_cast<size_t>(iterative_->num_vertices()));
  return at ? iterative_->start_at(*at, positions) : iterative_->start(positions);
}

Status ShapeOperator::greedy_shape(int32_t most_steps, std::vector<double>* positions) {
  if (global_) return global_->reconstruct(positions);
  iterative_->restart();
  return iterative_->solve(std::min(std::max(most_steps, 0), final_step_count()), positions);
}

Status tune(const IterativeTuning& tuning, ShapeOperator* op) {
  return op->code() == kGabReconstructionIterativeTuned ? op->set_tuning(tuning) : Status::Ok();
}

int32_t ShapeOperator::num_anchors() const { return global_ ? global_->num_anchors() : iterative_->num_anchors(); }
bool ShapeOperator::is_anchor(int32_t v) const { return global_ ? global_->is_anchor(v) : iterative_->is_anchor(v); }
const std::vector<int32_t>& ShapeOperator::anchors() const {
  return global_ ? global_->anchors() : iterative_->anchors();
}
const std::vector<double>& ShapeOperator::coefficients() const {
  return global_ ? global_->coefficients() : iterative_->coefficients();
}

}  // namespace gab
