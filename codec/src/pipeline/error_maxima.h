// Where the greedy loop anchors next (Sorkine et al. 2005, sec. IV: the
// vertex whose reconstruction is farthest from the original), and, for a
// batch, which of the error's local maxima.
#pragma once

#include <cstdint>
#include <vector>

#include "gab/mesh/edge_graph.h"
#include "reconstruction/shape_operator.h"

namespace gab {

// The `count` (> 1) vertices not anchored in `rec` among the 1-ring local
// maxima of `error` (at least every neighbour's) whose error has the largest
// mean over their closed 1-ring, largest first, ties to the smaller index.
// With count == 1 the worst free vertex (the paper's rule), local maximum or
// not; if no free vertex is a local maximum, the worst free vertex, so a
// greedy loop always progresses. With `separation` > 0 hops a batch takes
// the maxima in that order but none within `separation` hops of one taken
// before it (so it may hold fewer than `count`): a large batch then spreads
// its anchors as one at a time would, rather than putting several on one
// broad bump that one anchor pulls into place. Needs a free vertex.
// O(V + E + c log c), c the local maxima, plus the separation's balls.
std::vector<int32_t> pick_error_maxima(const EdgeGraph& graph, const std::vector<double>& error,
                                       const ShapeOperator& rec, int32_t count, int32_t separation = 0);

}  // namespace gab
