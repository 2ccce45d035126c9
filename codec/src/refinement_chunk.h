// The refinement chunk (DESIGN.md section 5, flag "refined"): after the
// anchor chunks, one correction per anchor and axis, in grid steps, that
// moves every quantized coefficient towards the least-squares optimal ones
// (Sorkine et al. 2005, sec. IV: the coefficients whose reconstruction is
// closest to the shape, not the anchors' own positions). Anchors in file
// order: chunk by chunk, each chunk's anchors in vertex order.
//
// Payload: varint anchor count, then one range-coded stream of the
// corrections (signed integers, contexts by axis and by the size of the
// corrections just coded; its own statistics, nothing carried over).
// Internal to the codec.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "gab/status.h"

namespace gab {

// `deltas`: 3 per anchor.
std::vector<uint8_t> encode_refinement(const std::vector<int32_t>& deltas);

// Decodes a payload that must hold exactly `anchors` corrections (3 per
// anchor in *deltas, each within +-max_delta). kParseError on anything else.
Status decode_refinement(const uint8_t* payload, size_t size, int32_t anchors, int32_t max_delta,
                         std::vector<int32_t>* deltas);

}  // namespace gab
