// The files the encoder may code for one call, in one place: each a way to
// meet the caller's rules; the smallest that meets them is kept
// (encoder.cpp). The rules behind each candidate are measured in
// docs/tuning-codec.md. What each costs (names as EncodeStats reports them):
//
//   anchors            the greedy loop to the caller's rules on the default
//                      grid (a factorization, then per step a solve and an
//                      update or refactorization: igea at 1e-3, 11 steps,
//                      ~5 s), the level layout (a decoder's work)
//   anchors on a       only when "anchors" anchored over
//   coarser grid       kDenseAnchorFraction of the vertices (a small or
//                      rough mesh): the same again on a coarser grid
//   detail             the greedy loop to a coarse target (about 3e-3) from
//                      a small spread set, the level layout, then the detail
//                      search (up to ~20 O(n) trials; igea ~70 ms each)
//   detail over        the same over anchors on a 6-bit grid (fewer steps:
//   coarse anchors     the loop stops at the grid's reach)
//
// Each candidate is first estimated: its greedy loop, its anchor chunks in
// the layout that codes smaller (the level layout costs a decoder's work)
// and its detail chunk at the default blend (2-3 trials). Then they are
// finished from the best estimate on, the rest of the detail search (about
// 17 trials) included, each only while it can still beat the best file so
// far (its detail chunk shrinking to kLeastDetailGain at best).
#pragma once

#include <cstdint>
#include <vector>

#include "gab/codec/encoder.h"

namespace gab {

// When a candidate's greedy loop stops, and on which grid its anchors lie.
// The caller's targets reach the loop only through these rules.
struct AnchorRules {
  int bits = 0;                // q of the anchors' grid
  double min_step_rel = 0;     // its step at least this times the box diagonal (0: the box's longest side / (2^q - 1))
  double target_rms_rel = 0;   // 0: none
  double target_linf_rel = 0;  // 0: none
  // The RMS target raised to kAnchorTargetOverGrid times the grid's own
  // error (step / 2): a coarse grid cannot take the anchors below about
  // that, and trying would anchor every vertex.
  bool stop_at_grid_reach = false;
  int32_t max_anchors = 0;     // 0: no count limit
  int32_t initial_anchors = 0;  // the spread set; 0: the encoder's default
  bool refine = false;         // try the least-squares refinement chunk
};

struct EncodeCandidate {
  const char* name = "";  // as EncodeStats::candidates reports it
  AnchorRules anchors;
  bool detail = false;       // a detail chunk over the anchors meets the caller's targets
  bool rescue_only = false;  // coded only when no candidate before met the targets
};

// The mesh's size as the candidates see it: vertices, the box's longest
// side and diagonal.
struct MeshSize {
  int32_t num_vertices = 0;
  double extent = 0, diagonal = 0;
};

// The candidates for `options` (checked) on a mesh of `size`, in the order
// they are coded. O(q).
std::vector<EncodeCandidate> encode_candidates(const EncodeOptions& options, const MeshSize& size);

// The dense regime's retry of an anchors-only candidate `tried` that placed
// `anchors` anchors: true with *retry set when that was over
// kDenseAnchorFraction of the vertices and a coarser grid is open to the
// encoder (q not fixed, an RMS target). O(q).
bool dense_grid_candidate(const EncodeOptions& options, const MeshSize& size, const EncodeCandidate& tried,
                          int32_t anchors, EncodeCandidate* retry);

// The least the rest of the detail search may leave of a fitted detail
// chunk: 0.84-1.0 measured on the shared meshes at 3e-4..3e-5 (feline at
// 3e-4: 0.84; the blend and the rate-distortion rounding suit candidates
// of one mesh differently, up to 10% apart, so a fit does not rank them),
// with a margin below.
constexpr double kLeastDetailGain = 0.7;

}  // namespace gab
