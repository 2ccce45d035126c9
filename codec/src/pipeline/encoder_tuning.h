// The encoder's measured tuning: the defaults EncodeOptions leaves to the
// encoder, and the constants of its regimes. Private: what a caller may rely
// on is the contract in gab/codec/encoder.h; these rules may change with new
// measurements. The figures behind each rule (meshes, rates, times) are in
// bench/TUNING.md, with the runs that reproduce them.
#pragma once

#include <cstdint>

namespace gab {

// The q the encoder picks for an error target on a mesh whose longest box
// side over its diagonal is `extent_over_diagonal`: the smallest q whose
// grid alone errs (RMS s/2, max s sqrt(3)/2 for step s) by at most 0.8 of an
// RMS target or 0.5 of an L-inf one; 12 (the paper's) without a target.
// O(q).
int default_bits(double extent_over_diagonal, double target_rms_rel, double target_linf_rel);

// The farthest-point spread set the greedy loop starts from: n / 1000 up to
// 50,000 vertices, growing as n^4 / 1.25e17 beyond (at most n / 50), so
// large meshes take fewer, costlier greedy steps.
int32_t default_initial_anchors(int32_t n);

// The greedy batch fraction for a system whose factorization costs `flops`:
// 5% while a refactorization is cheap, growing as (flops / 2e9)^0.8 up to
// 12% so that large meshes need a bounded number of steps.
double default_batch_fraction(double flops);

// Chunk growth (selection order) for a system whose factorization costs
// `flops`: 4 while a refactorization is cheap, growing as (flops / 2e9)^0.6
// beyond, since each chunk costs the decoder a refactorization.
double default_chunk_growth(double flops);

// Level growth (level layout) for a system whose factorization costs
// `flops`: 2 while a refactorization is cheap, growing as (flops / 2e9)^0.6
// beyond like default_chunk_growth.
double default_level_growth(double flops);

// Refinement with an RMS target: the greedy loop first aims the unrefined
// shape this much above the target, then at what the last try measured.
constexpr double kExpectedRefinementGain = 1.25;

// The dense regime: past this fraction of the vertices as anchors the
// encoder also tries the grid whose error alone is kDenseGridShare of the
// RMS target, and keeps the smaller file.
constexpr double kDenseAnchorFraction = 0.5;
constexpr double kDenseGridShare = 0.95;

}  // namespace gab
