// The framed sections after a .gab file's geometry chunks (gab_format.h):
// each payload starts with its kind (u8) and flags (u8). Later revisions of
// the format put attributes there; this build knows no kind yet, so it
// skips a section unless the section says it is required.
#pragma once

#include <cstdint>

#include "container/byte_io.h"
#include "gab/status.h"

namespace gab {

// Reads the file's last part: `sections` sections from `in`, checking each
// frame, then nothing more. Counts the skipped sections; sets *truncated and
// stops when the file ends inside one. kParseError for a checksum mismatch,
// a payload without its two leading bytes or bytes after the last frame,
// kUnsupported for a required section. O(bytes read).
Status skip_trailing_sections(ByteReader* in, int32_t sections, int32_t* skipped, bool* truncated);

}  // namespace gab
