// The framed sections after a .gab file's geometry chunks (gab_format.h):
// each payload starts with its kind (u8) and flags (u8). Kind 1 is an
// attribute (attributes/attribute_section.h); a reader skips a section of a
// kind it does not know unless the section says it is required.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "container/byte_io.h"
#include "gab/status.h"

namespace gab {

// One section as read: its kind and flags, and its whole payload (those two
// bytes included, inside the file's buffer).
struct TrailingSection {
  uint8_t kind = 0;
  uint8_t flags = 0;
  const uint8_t* payload = nullptr;
  size_t size = 0;
};

// Reads the file's last part: `sections` sections from `in`, checking each
// frame, then nothing more. Sets *truncated and stops when the file ends
// inside one (the complete ones before it are listed). kParseError for a
// checksum mismatch, a payload without its two leading bytes or bytes after
// the last frame. O(bytes read).
Status read_trailing_sections(ByteReader* in, int32_t sections, std::vector<TrailingSection>* out, bool* truncated);

// The error for a section of a kind this build does not know that says it
// is required (kUnsupported), else OK (the section is skipped).
Status check_unknown_section(const TrailingSection& section, int32_t index);

}  // namespace gab
