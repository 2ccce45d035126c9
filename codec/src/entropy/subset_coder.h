// A sorted set of b distinct positions out of a universe of u, coded in
// about log2 C(u, b) bits (a sorted, gap-coded set: the anchors of a .gab
// chunk) instead of b log2 u: each gap is Golomb-coded with the parameter the
// density b/u implies, its quotient bits adaptive.
#pragma once

#include <cstdint>
#include <vector>

#include "entropy/range_coder.h"

namespace gab {

// Codes `sorted` (strictly increasing, each < universe). The count is not
// coded: the decoder must be told it (the .gab chunk header carries it).
// About log2 C(u, b) bits plus a few hundredths of a bit per position;
// b = u costs 0 bits. O(b + u / m) time, m ~ 0.69 u / b the Golomb parameter.
void encode_subset(RangeEncoder* enc, const std::vector<uint32_t>& sorted, uint32_t universe);

// Decodes `count` positions (count <= universe is the caller's check; false
// if it fails). Returns false if the stream yields a position >= universe
// (impossible by construction: the coder never codes a gap that leaves no
// room for the positions after it) or the decoder overruns its input
// (corrupt or truncated stream). Grows `sorted` as it decodes, never beyond
// `count` entries; O(count + universe / m) time even on garbage.
bool decode_subset(RangeDecoder* dec, uint32_t count, uint32_t universe, std::vector<uint32_t>* sorted);

}  // namespace gab
