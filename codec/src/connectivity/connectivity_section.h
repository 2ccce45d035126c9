// The connectivity section of a .gab file (gab/codec/gab_format.h), written
// and read as twins: the framed triangle list (connectivity_coder.h), in a
// reordered file the framed valence section (valence_section.h), or in a
// geometry-only file the hash of the mesh the decoder must be given.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "container/byte_io.h"
#include "gab/codec/gab_format.h"
#include "gab/mesh/mesh.h"
#include "gab/status.h"

namespace gab {

// Writes the section for `mesh`: the hash or the list coder's block as the
// header's flags say, or for a reordered file `valence_block` (the valence
// section of the mesh before it was renumbered, which decodes to `mesh`).
// O(T).
void write_connectivity_section(const Mesh& mesh, const GabHeader& header, const std::vector<uint8_t>& valence_block,
                                ByteWriter* out);

// The section as read: the hash, or the framed block (inside the file's buffer).
struct ConnectivitySection {
  uint64_t hash = 0;
  const uint8_t* block = nullptr;
  size_t size = 0;
};

// Reads the section, checking its frame but decoding nothing; kParseError
// if the file ends inside it or its checksum fails. O(block size).
Status read_connectivity_section(ByteReader* in, const GabHeader& header, ConnectivitySection* section);

// The triangles: decoded from the block (kParseError naming the problem), or
// for a geometry-only file those of `given` once its counts and hash match
// the header's (kInvalidArgument otherwise, or without `given`). O(T).
Status decode_connectivity_section(const ConnectivitySection& section, const GabHeader& header, const Mesh* given,
                                   std::vector<int32_t>* triangles);

}  // namespace gab
