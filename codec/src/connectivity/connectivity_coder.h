// The connectivity block of a .gab file: the triangle list, exactly (order
// and orientation kept, so the decoded mesh is the input mesh), in a compact
// range-coded form. A dedicated connectivity coder comes later; this one
// exploits that triangles glue onto edges of earlier triangles (a triangle
// closing a recent open edge costs that edge's index plus its third vertex;
// later vertices are looked for among the vertices that close an open edge),
// a move-to-front cache of recent vertices, and that meshes tend to
// introduce vertices in order and number neighbours closely. On the shared
// meshes: 4.2 bits/triangle (igea, strip order) to 22 (bunny, order close
// to random, whose order alone is worth about log2(T/e) = 15 bits/triangle).
#pragma once

#include <cstdint>
#include <vector>

#include "gab/status.h"

namespace gab {

// Bytes of the coded triangle list (3 indices per triangle, each in [0, n);
// degenerate and duplicate triangles are fine). The code does not depend on
// n. O(T) expected time, O(T) memory (hash maps of the open edges).
std::vector<uint8_t> encode_connectivity(int32_t num_vertices, const std::vector<int32_t>& triangles);

// Decodes `num_triangles` triangles over `num_vertices` vertices. Untrusted
// input: any index out of range ("connectivity: triangle 12: vertex index 57
// out of range [0, 40)"), a stream overrun or trailing bytes gives a
// kParseError naming the triangle (or the count); negative counts are
// kInvalidArgument. Grows its output as it decodes, so a lying count cannot
// make it allocate or work more than the stream can describe (a coded
// decision costs at least 0.0007 bit, so at most ~3000 triangles a byte).
// O(T) expected time.
Status decode_connectivity(const uint8_t* data, size_t size, int32_t num_vertices, int32_t num_triangles,
                           std::vector<int32_t>* triangles);

// 64-bit FNV-1a hash of (n, triangle count, every index as 4 little-endian
// bytes, two's complement): what a geometry-only file stores instead of the
// connectivity. O(T).
uint64_t connectivity_hash(int32_t num_vertices, const std::vector<int32_t>& triangles);

}  // namespace gab
