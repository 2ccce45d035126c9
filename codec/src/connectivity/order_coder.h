// The input's vertex numbering, coded relative to the valence coder's
// traversal (issue 17: "what comes out is the mesh that went in").
//
// The decoder knows the triangles in traversal numbering; the order block
// gives, for each traversal number k, the input index original[k]. Each one
// is predicted from vertices already placed: the parallelogram rule on the
// *indices* across the edge that brought vertex k in (exact wherever the
// input was numbered row by row, as scans are), else the previous vertex's
// index plus one. It is coded as its rank among the indices not yet used,
// relative to the prediction's rank, so a coherent numbering costs a few
// bits per hundred vertices while any numbering costs at most a uniform
// choice among the remaining indices: the encoder falls back to that
// (log2(n!) bits and a few bytes) when it is smaller, and a numbering that
// already is the traversal's costs one byte.
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
