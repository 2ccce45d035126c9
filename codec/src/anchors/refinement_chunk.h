// The refinement chunk (flag "refined", gab/codec/gab_format.h): after the
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

#include "anchors/quantizer.h"
#include "container/byte_io.h"
#include "gab/status.h"

namespace gab {

// The chunk, from the refined grid indices (3 per anchor) of the anchors in
// `selection` order and every vertex's own grid indices (3 per vertex); the
// corrections follow `file_order` (the same anchors). O(n + anchors).
std::vector<uint8_t> encode_refinement_chunk(const std::vector<int32_t>& file_order,
                                             const std::vector<int32_t>& selection,
                                             const std::vector<int32_t>& refined_grid,
                                             const std::vector<int32_t>& grid);
// The refined coefficients (3 per anchor, file order) from a chunk and the
// anchors' decoded grid indices in file order (3 each). kParseError naming
// the problem, also for a correction that leaves the grid. O(anchors).
Status decode_refinement_chunk(const uint8_t* payload, size_t size, const std::vector<int32_t>& file_grid,
                               const Quantizer& quantizer, std::vector<double>* coefficients);

// The payload's head: its correction count, which must be `anchors` (the
// rule the decoder and read_gab_info share). kParseError otherwise. O(1).
Status read_refinement_count(ByteReader* in, int32_t anchors);

// The corrections alone, `deltas` 3 per anchor.
std::vector<uint8_t> encode_refinement(const std::vector<int32_t>& deltas);

// Decodes a payload that must hold exactly `anchors` corrections (3 per
// anchor in *deltas, each within +-max_delta). kParseError on anything else.
Status decode_refinement(const uint8_t* payload, size_t size, int32_t anchors, int32_t max_delta,
                         std::vector<int32_t>* deltas);

}  // namespace gab
