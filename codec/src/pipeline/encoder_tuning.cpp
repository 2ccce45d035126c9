#include "pipeline/encoder_tuning.h"

#include <algorithm>
#include <cmath>

#include "gab/codec/gab_format.h"
#include "reconstruction/shape_operator.h"

namespace gab {

int32_t default_initial_anchors(int32_t n) {
  const double scale = std::max(1.0, static_cast<double>(n) / 50000.0);
  return static_cast<int32_t>(std::max(1.0, std::min(n / 1000.0 * scale * scale * scale, n / 50.0)));
}

double default_batch_fraction(double flops) {
  return std::min(0.12, 0.05 * std::pow(std::max(1.0, flops / 2e9), 0.8));
}

GreedyBatches default_greedy_batches(double flops, bool iterative, int32_t n) {
  const bool small = n < kFarBatchFromVertices;
  if (!iterative) return {default_batch_fraction(flops), small ? 0.0 : kFarBatchFraction};
  if (small) return {kSmallIterativeBatchFraction, kSmallIterativeFarBatchFraction};
  return {kIterativeBatchFraction, kIterativeFarBatchFraction};
}

int32_t greedy_steps(int32_t n, bool far) {
  if (far && n >= kFarBatchFromVertices) return kFarGreedySteps;
  return std::max(kGreedySteps, kGreedyStepBudget / std::max(n, 1));
}

int32_t batch_separation(int32_t n, int32_t k) {
  return static_cast<int32_t>(kBatchSeparation * std::sqrt(static_cast<double>(n) / std::max(k, 1)));
}

double default_chunk_growth(double flops) { return 4.0 * std::pow(std::max(1.0, flops / 2e9), 0.6); }

double default_level_growth(double flops, bool iterative, int32_t n) {
  if (iterative && n > kLocalPredictionMostVertices) return kIterativeLevelGrowth;
  return 2.0 * std::pow(std::max(1.0, flops / 2e9), 0.6);
}

IterativeTuning default_iterative_tuning(int32_t n) {
  IterativeTuning t;
  t.prediction_sweeps = kTunedPredictionSweeps;
  t.final_sweeps = IterativeReconstruction::kStartSweeps;
  const bool small = n <= kMoreFinalStepsUpTo;
  t.final_steps16 = n > kFewerFinalStepsFrom ? 8 : small ? 32 : 16;
  t.final_most = small ? 64 : 32;
  return t;
}

int default_bits(double extent_over_diagonal, double target_rms_rel, double target_linf_rel) {
  if (!(target_rms_rel > 0) && !(target_linf_rel > 0)) return 12;
  for (int q = kGabMinBits; q < kGabMaxBits; ++q) {
    const double step = extent_over_diagonal / static_cast<double>((int64_t{1} << q) - 1);
    const bool rms_ok = !(target_rms_rel > 0) || step / 2 <= 0.8 * target_rms_rel;
    const bool linf_ok = !(target_linf_rel > 0) || step * std::sqrt(3.0) / 2 <= 0.5 * target_linf_rel;
    if (rms_ok && linf_ok) return q;
  }
  return kGabMaxBits;
}

}  // namespace gab

