// The encoder's measured tuning: the defaults EncodeOptions leaves to the
// encoder, and the constants of its regimes. Private: what a caller may rely
// on is the contract in gab/codec/encoder.h; these rules may change with new
// measurements. The figures behind each rule (meshes, rates, times) are in
// docs/tuning-codec.md, with the runs that reproduce them.
#pragma once

#include <cstdint>

#include "reconstruction/iterative_tuning.h"

namespace gab {

// The q the encoder picks for an error target on a mesh whose longest box
// side over its diagonal is `extent_over_diagonal`: the smallest q whose
// grid alone errs (RMS s/2, max s sqrt(3)/2 for step s) by at most 0.8 of an
// RMS target or 0.5 of an L-inf one; 12 (the paper's) without a target.
// O(q).
int default_bits(double extent_over_diagonal, double target_rms_rel, double target_linf_rel);

// The farthest-point spread set the greedy loop starts from: n / 1000 up to
// 50,000 vertices, growing as n^4 / 1.25e17 beyond (at most n / 50), so
// large meshes take fewer, costlier greedy steps. With the iterative
// operator a smaller set codes smaller (igea at 1e-3: 39,190 bytes from 134
// spread anchors against 41,269 from 2,606) but decodes slower (243 ms
// against 188: each level costs its decode passes over the mesh).
int32_t default_initial_anchors(int32_t n);

// The greedy batch fraction for a system whose factorization costs `flops`:
// 5% while a refactorization is cheap, growing as (flops / 2e9)^0.8 up to
// 12% so that large meshes need a bounded number of steps.
double default_batch_fraction(double flops);

// The greedy loop's batches: a fraction of the anchors so far, and a larger
// one (when more) while far above an RMS target.
struct GreedyBatches {
  double fraction = 0;
  double far_fraction = 0;
};
// The global operator's: default_batch_fraction, and kFarBatchFraction on
// meshes of kFarBatchFromVertices and more; the iterative operator's below.
GreedyBatches default_greedy_batches(double flops, bool iterative, int32_t n);

// On meshes of kFarBatchFromVertices and more, while the greedy loop's
// error is over kFarErrorOverTarget times an RMS target, its batches are
// kFarBatchFraction of the anchors so far when that is more than the batch
// fraction: far from the target a larger batch places its anchors about as
// well (measured at 1e-3 against 5% batches throughout: bunny, horse,
// feline, nefertiti +0.7 / +0.7 / +0.2 / -0.6% bytes, their encodes 30-45%
// faster; camel-head +0.5% in 0.22 s instead of 0.43; igea's spread set
// starts it within 3x). 25% batches while over 2x: +0.6-3.3% for 55-60%.
// Smaller meshes encode in a fraction of a second either way.
constexpr double kFarBatchFraction = 0.15;
constexpr double kFarErrorOverTarget = 3.0;
constexpr int32_t kFarBatchFromVertices = 1 << 14;

// The iterative operator's greedy loop (operator 3; the global one keeps
// the rules above). Measured at 1e-3 --reorder on the eight shared meshes
// against the loop of warm greedy shapes, 5% batches and the default spread
// set (docs/tuning-codec.md): 1.1% fewer bytes in about half the time.
// - Batches: kIterativeBatchFraction of the anchors so far, and
//   kIterativeFarBatchFraction while the error is over kFarErrorOverTarget
//   times an RMS target, on meshes of kFarBatchFromVertices and more; below
//   that, the kSmall* fractions.
// - Its picks at least kBatchSeparation anchor spacings apart (the spacing
//   sqrt(n / k) hops): what lets a batch be that large.
// - Vertices ranked by the decoder's shape cut to greedy_steps steps
//   (ShapeOperator::greedy_shape): its start and sweeps, where most of its
//   error is decided, and the few steps a ranking needs.
// - The decoder's own shape evaluated once the ranking shape's error is
//   within kDecoderCheckWithin of a target; when it meets the target, the
//   shortest prefix of the selection order that does is searched
//   (the operator's shape depends on the anchor set alone), at most
//   kTrimEvaluations shapes, to within 1 / kTrimPrecision of the count.
constexpr double kIterativeBatchFraction = 0.2;
constexpr double kIterativeFarBatchFraction = 0.5;
constexpr double kSmallIterativeBatchFraction = 0.1;
constexpr double kSmallIterativeFarBatchFraction = 0.2;
constexpr double kBatchSeparation = 0.8;
constexpr double kDecoderCheckWithin = 1.15;
constexpr int kTrimEvaluations = 4;
constexpr int32_t kTrimPrecision = 250;
// The ranking shape's steps for n vertices: kGreedySteps, more on small
// meshes (kGreedyStepBudget / n: a step costs little there, and camel-head
// codes 10% smaller with its decoder's steps), kFarGreedySteps while far
// from the target on meshes of kFarBatchFromVertices and more.
constexpr int32_t kGreedySteps = 8;
constexpr int32_t kGreedyStepBudget = 1 << 18;
constexpr int32_t kFarGreedySteps = 2;
int32_t greedy_steps(int32_t n, bool far);
// The separation in hops of a batch's picks with k anchors on n vertices.
int32_t batch_separation(int32_t n, int32_t k);

// Chunk growth (selection order) for a system whose factorization costs
// `flops`: 4 while a refactorization is cheap, growing as (flops / 2e9)^0.6
// beyond, since each chunk costs the decoder a refactorization.
double default_chunk_growth(double flops);

// Level growth (level layout) for a system whose factorization costs
// `flops`: 2 while a refactorization is cheap, growing as (flops / 2e9)^0.6
// beyond like default_chunk_growth. The iterative operator's on meshes
// past kLocalPredictionMostVertices is kIterativeLevelGrowth: each level
// costs its decode a prediction over (nearly) the whole mesh, and at 1e-3
// growth 2 / 3 / 4 gave feline 34,279 / 34,764 / 35,214 bytes and 0.159 /
// 0.142 / 0.124 s of decode, nefertiti 35,711 / 35,876 / 36,103 and 0.153 /
// 0.137 / 0.127 s (the whole mesh over a 10 Mbit/s link: 1 ms of bytes for
// 30 ms of decode). Smaller meshes keep 2: there whole-mesh work is cheap.
constexpr double kIterativeLevelGrowth = 4.0;
double default_level_growth(double flops, bool iterative, int32_t n);

// The iterative operator's parameters (operator 3, docs/format.md 5.2.3)
// for n vertices: prediction sweeps kTunedPredictionSweeps, final sweeps 8,
// final steps one per anchor spacing (at most 32), half of that past
// kFewerFinalStepsFrom vertices, twice that (at most 64) up to
// kMoreFinalStepsUpTo vertices, where a step costs a decode little
// (camel-head 3,160 -> 2,985 bytes for ~5 ms; bunny-small +0.2%).
// Measured at 1e-3 --reorder against
// operator 2 (8, 8, 1 per spacing; bytes, and the decode's work modelled
// as 13 ns a sweep and 19 ns a step per vertex), docs/tuning-codec.md:
// 4 prediction sweeps, 1.000-1.022x bytes (1.014x over eight shared
// meshes) for 4-13 ms less per decode of 25-50k vertices; half the final
// steps, igea 1.031x and 22 ms less, but camel-head 1.26x, bunny 1.05x
// for 1-2 ms. At 10 Mbit/s a percent of igea's file is 0.3 ms.
constexpr int32_t kTunedPredictionSweeps = 4;
constexpr int32_t kFewerFinalStepsFrom = 1 << 16;
constexpr int32_t kMoreFinalStepsUpTo = 1 << 14;
IterativeTuning default_iterative_tuning(int32_t n);

// Refinement with an RMS target: the greedy loop first aims the unrefined
// shape this much above the target, then at what the last try measured.
constexpr double kExpectedRefinementGain = 1.25;

// The dense regime: past this fraction of the vertices as anchors the
// encoder also tries the grid whose error alone is kDenseGridShare of the
// RMS target, and keeps the smaller file.
constexpr double kDenseAnchorFraction = 0.5;
constexpr double kDenseGridShare = 0.95;

// The detail layer (EncodeOptions::detail, auto): which candidate files the
// encoder codes for an error target (encode_candidates.h). The target in
// RMS terms is the RMS target, else the L-inf target over kLinfOverRms.
// Anchors alone win down to about 3e-4 and lose from 1e-4 down (the
// measured crossing: docs/tuning-codec.md). A detail layer codes smallest
// over the anchors of a coarse target (about 3e-3, whatever the final
// target), not more of them: on the grid that target calls for, or on a
// coarser one (kCoarseAnchorBits) with fewer anchors, whichever codes
// smaller (the coarse grid on 7 of the 8 shared meshes at 1e-4, by 0.1-6%;
// camel-head, with sharp creases, wants the finer by 7%).
constexpr double kLinfOverRms = 4;
// Below this target (in RMS terms) the anchors-only file is not tried; from
// kDetailFrom down the detail candidates are.
constexpr double kAnchorsOnlyFrom = 2e-4;
constexpr double kDetailFrom = 5e-4;
// The anchors' target of the detail candidate: kDetailAnchorTarget, or
// kAnchorTargetOverTarget times the target when that is coarser.
constexpr double kDetailAnchorTarget = 3e-3;
constexpr double kAnchorTargetOverTarget = 3;
// The detail candidate's spread set: this share of the vertices (the
// anchors-only default grows faster on large meshes to save greedy steps,
// which a detail layer does not need: igea at 1e-4, 2606 -> 1042 anchors,
// 3.2% smaller).
constexpr double kDetailSpreadShare = 1.0 / 1000;
// The detail candidate's anchors stop at kAnchorTargetOverGrid times the
// RMS error of their grid alone (a fixed coarse --bits; the default grid
// errs 0.8 of the target, so its target stands), and at
// kDetailMaxAnchorShare of the vertices: a smooth shape needs no more, and
// the greedy steps beyond would cost the encoder minutes on large meshes.
constexpr double kAnchorTargetOverGrid = 1.25;
constexpr double kDetailMaxAnchorShare = 0.25;
// The coarse grid of the second detail candidate (its anchors stop at the
// grid's reach, kAnchorTargetOverGrid); below kSpreadOnlyBelow it holds the
// spread set alone (at 3e-5: horse 89,091 bytes against 90,019 with the
// greedy steps, bunny 67,948 against 68,560, igea -0.3%).
constexpr int kCoarseAnchorBits = 6;
constexpr double kSpreadOnlyBelow = 5e-5;

}  // namespace gab
