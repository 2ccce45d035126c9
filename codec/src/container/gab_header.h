// The .gab header (its fields: gab/codec/gab_format.h), written and read
// with its checks, and the table of the format's flags.
#pragma once

#include <cstddef>
#include <cstdint>

#include "container/byte_io.h"
#include "gab/codec/gab_format.h"
#include "gab/status.h"

namespace gab {

// Every flag this build knows, one row each; a reader refuses any other
// bit. A new flag is a new row (and a constant in gab_format.h).
struct GabFlagRow {
  uint8_t bit;
  const char* name;
};
constexpr GabFlagRow kGabFlagTable[] = {
    {kGabFlagGeometryOnly, "geometry-only"},  // a connectivity hash instead of the triangles
    {kGabFlagRefined, "refined"},             // a refinement chunk follows the anchor chunks
    {kGabFlagLevels, "levels"},               // the anchor chunks are in the level layout
    {kGabFlagReordered, "reordered"},         // traversal numbering: no vertex order block
    {kGabFlagDetail, "detail"},               // a detail chunk ends the geometry
};

// The bits of kGabFlagTable together. O(rows).
constexpr uint8_t known_gab_flags() {
  uint8_t known = 0;
  for (const GabFlagRow& row : kGabFlagTable) known = static_cast<uint8_t>(known | row.bit);
  return known;
}

// The header (kGabMinHeaderBytes..kGabMaxHeaderBytes), its CRC-32 last. O(1).
void write_gab_header(const GabHeader& header, ByteWriter* out);

// Reads and checks the header: magic, version, CRC, flags, every field's
// range, and that the counts are plausible for a file of `file_size` bytes
// (so a forged header cannot make a decoder allocate without bound; the
// triangle count is checked against the connectivity block's size when it
// is decoded). kParseError with a message naming the field otherwise;
// kUnsupported for another version, an unknown flag, ordering or
// reconstruction operator, or the reserved byte in use. On success `in` is
// just past the header. O(1).
Status read_gab_header(ByteReader* in, size_t file_size, GabHeader* header);

}  // namespace gab
