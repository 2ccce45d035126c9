// The connectivity section of a .gab file (gab/codec/gab_format.h), written
// and read as twins. By the header's flags it is:
//   geometry only          the hash of the mesh the decoder must be given
//                          (connectivity_hash.h)
//   otherwise              a framed block: the valence section
//                          (valence_section.h); unless reordered, a second
//                          framed block: the input's vertex order
//                          (order_coder.h)
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "container/byte_io.h"
#include "gab/codec/gab_format.h"
#include "gab/mesh/mesh.h"
#include "gab/status.h"

namespace gab {

// What the encoder codes for a mesh that is not geometry only: the blocks
// and the mesh exactly as the decoder will return it (its triangles in the
// decoder's order and corner order; numbered in traversal order when
// reordered).
struct CodedConnectivity {
  std::vector<uint8_t> valence;  // the valence section
  std::vector<uint8_t> order;    // the vertex order (empty when reordered)
  std::vector<int32_t> triangles;
  // Reordered: new_index[v] is the decoded mesh's number for input vertex
  // v. Empty when the order is kept (the numbering is the input's).
  std::vector<int32_t> new_index;
};

// Codes the triangles of an n-vertex mesh (every index in [0, n)). The
// valence block is decoded again here, so encoder and decoder list the
// triangles alike by construction. O(n log n + T) plus the valence coder's splits.
Status code_connectivity(int32_t n, const std::vector<int32_t>& triangles, bool reorder, CodedConnectivity* coded);

// Writes the section: the hash of `mesh` when geometry only, otherwise the
// blocks of `coded` as the flags say. O(T).
void write_connectivity_section(const Mesh& mesh, const GabHeader& header, const CodedConnectivity& coded,
                                ByteWriter* out);

// The section as read: the hash, or the framed blocks (inside the file's
// buffer).
struct ConnectivitySection {
  uint64_t hash = 0;
  const uint8_t* block = nullptr;
  size_t size = 0;
  const uint8_t* order = nullptr;  // the vertex order's block, when the file keeps it
  size_t order_size = 0;
  size_t order_bytes = 0;  // the order block with its framing (0 without)
};

// Reads the section, checking its frames but decoding nothing; kParseError
// if the file ends inside it or a checksum fails. O(section size).
Status read_connectivity_section(ByteReader* in, const GabHeader& header, ConnectivitySection* section);

// The triangles: decoded from the blocks (kParseError naming the problem),
// or for a geometry-only file those of `given` once its counts and hash
// match the header's (kInvalidArgument otherwise, or without `given`).
// O(n log n + T).
Status decode_connectivity_section(const ConnectivitySection& section, const GabHeader& header, const Mesh* given,
                                   std::vector<int32_t>* triangles);

}  // namespace gab
