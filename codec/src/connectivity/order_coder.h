// The input's vertex numbering, coded relative to the valence coder's
// traversal (issue 17: "what comes out is the mesh that went in").
//
// The decoder knows the triangles in traversal numbering; the order block
// gives, for each traversal number k, the input index original[k]. Both
// sides walk the input numbering i = 0, 1, ... and place the vertex that i
// names: a coherent numbering puts it next to the vertices that i - 1,
// i - 2 or i - (a row's length) name, so it is coded as its position among
// their unplaced neighbours, ranked by what has been right so far (most
// often the first: a fraction of a bit). A miss is coded as the gap back
// to the latest input index among its placed neighbours and its place among
// that vertex's neighbours; a vertex with no placed neighbour by its rank
// among the unplaced ones. An arbitrary numbering costs at most a uniform
// choice among the remaining vertices each time: the encoder falls back to
// that (log2(n!) bits and a few bytes) when it is smaller, and a numbering
// that already is the traversal's costs one byte. Figures per shared mesh:
// bench/order_sizes (igea, numbered along strips: 0.07 of log2(n!)).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "gab/status.h"

namespace gab {

// Codes `original` (a permutation of [0, n)) for a decoder that knows
// `triangles` over [0, n) (the valence section's output). O(n log n + T).
std::vector<uint8_t> encode_vertex_order(int32_t n, const std::vector<int32_t>& triangles,
                                         const std::vector<int32_t>& original);

// Decodes what encode_vertex_order coded. Untrusted input: a rank out of
// range, a stream cut short or trailing bytes is a kParseError naming it;
// the result is always a permutation. O(n log n + T).
Status decode_vertex_order(const uint8_t* data, size_t size, int32_t n, const std::vector<int32_t>& triangles,
                           std::vector<int32_t>* original);

}  // namespace gab
