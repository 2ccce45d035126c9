// The two arrangements of a selection's anchor chunks (FileLayout): coded
// here, compared and assembled by the encoder (encoder.cpp).
#pragma once

#include <cstdint>
#include <vector>

#include "container/framing.h"
#include "gab/mesh/edge_graph.h"
#include "gab/status.h"
#include "pipeline/anchor_selection.h"
#include "pipeline/ordering_choice.h"
#include "reconstruction/iterative_tuning.h"

namespace gab {

// One layout's anchor chunks, the anchors in the order the file lists them
// (chunk by chunk, each in vertex order: the refinement's order) and per chunk.
struct ChunkLayout {
  std::vector<std::vector<uint8_t>> chunks;
  std::vector<int32_t> file_order;
  std::vector<int32_t> chunk_anchors;

  void add(std::vector<uint8_t> chunk, const std::vector<int32_t>& anchors) {
    chunks.push_back(std::move(chunk));
    file_order.insert(file_order.end(), anchors.begin(), anchors.end());
    chunk_anchors.push_back(static_cast<int32_t>(anchors.size()));
  }
  size_t bytes() const {
    size_t total = 0;
    for (const std::vector<uint8_t>& c : chunks) total += c.size() + kGabFrameBytes;
    return total;
  }
};

// The selection-order layout: chunk k the schedule's k-th cut, its anchors
// a subset of the vertices the chunks before left free, predicted by the
// reconstruction from those chunks (chunk 0: by the previous anchor). O(n)
// per chunk plus the positions.
ChunkLayout encode_selection_layout(const AnchorSchedule& schedule, const GridPositions& grid);

// The level layout (anchor_levels.h) of the schedule's anchors: chunk 0 the
// spread set and the rest's subset, then one level's positions per chunk,
// each predicted by the reconstruction from the levels before it (level 1:
// from the spread set, the schedule's first shape) by the operator
// `reconstruction` names (global: factored in `ordering`; operator 3 with
// `tuning`). Cost: the decoder's, less the first shape: levels - 1 shapes
// and anchor additions.
Status encode_level_layout(const AnchorSchedule& schedule, const EdgeGraph& graph, double weight, double growth,
                           int32_t threads, const OrderingPlan& ordering, uint8_t reconstruction,
                           const IterativeTuning& tuning, const GridPositions& grid, ChunkLayout* out);

}  // namespace gab
