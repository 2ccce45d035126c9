#include "container/framing.h"

#include "container/crc32.h"

namespace gab {

void write_framed(const uint8_t* payload, size_t size, ByteWriter* out) {
  out->u32(static_cast<uint32_t>(size));
  out->u32(crc32(payload, size));
  out->bytes(payload, size);
}

FrameRead read_framed(ByteReader* in, const uint8_t** payload, size_t* size) {
  uint32_t length = 0, crc = 0;
  if (!in->u32(&length) || !in->u32(&crc)) return FrameRead::kTruncated;
  if (length > in->remaining()) return FrameRead::kTruncated;
  in->bytes(length, payload);
  *size = length;
  return checksum_matches(crc, crc32(*payload, length)) ? FrameRead::kOk : FrameRead::kCorrupt;
}

}  // namespace gab
