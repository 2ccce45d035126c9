// What a geometry-only .gab file stores instead of its connectivity: a hash
// of the mesh the decoder must be given (gab/codec/gab_format.h).
#pragma once

#include <cstdint>
#include <vector>

namespace gab {

// 64-bit FNV-1a hash of (n, triangle count, every index as 4 little-endian
// bytes, two's complement). O(T).
uint64_t connectivity_hash(int32_t num_vertices, const std::vector<int32_t>& triangles);

}  // namespace gab
