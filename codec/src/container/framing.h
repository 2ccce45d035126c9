// Frames: how the .gab file carries its connectivity block and every chunk,
// so a truncated or damaged one is detected (gab/codec/gab_format.h).
#pragma once

#include <cstddef>
#include <cstdint>

#include "container/byte_io.h"

namespace gab {

constexpr size_t kGabFrameBytes = 8;  // a frame's u32 length and u32 CRC-32

// Frames `payload` (u32 length, u32 CRC-32, bytes). O(size).
void write_framed(const uint8_t* payload, size_t size, ByteWriter* out);

enum class FrameRead { kOk, kTruncated, kCorrupt };
// Reads one frame (no copy: *payload points into the reader's buffer);
// kTruncated when the file ends inside it, kCorrupt when the CRC does not
// match. O(size).
FrameRead read_framed(ByteReader* in, const uint8_t** payload, size_t* size);

}  // namespace gab
