// find_gab_chunk_ends: the frames of a file that is still arriving, for a
// progressive viewer that decodes each prefix of whole chunks as it comes.
#include "container/byte_io.h"
#include "container/gab_header.h"
#include "gab/codec/decoder.h"

namespace gab {
namespace {

// Skips one frame (u32 length, u32 CRC-32, payload) without checking its
// CRC; false when the bytes end inside it.
bool skip_frame(ByteReader* in) {
  uint32_t length = 0, crc = 0;
  const uint8_t* payload = nullptr;
  return in->u32(&length) && in->u32(&crc) && in->bytes(length, &payload);
}

}  // namespace

Status find_gab_chunk_ends(const uint8_t* data, size_t size, GabStreamFrames* frames) {
  *frames = GabStreamFrames();
  // The header's counts are varints: wait for the longest header (a whole
  // file is always longer: the connectivity and chunk 0 follow it).
  if (size < kGabMaxHeaderBytes) return Status::Ok();
  ByteReader in(data, size);
  GabHeader header;
  GAB_RETURN_IF_ERROR(read_gab_header(&in, size, &header));
  frames->chunks_in_file = header.chunks;
  // The connectivity section (gab_format.h): a hash, or one or two frames.
  if (header.geometry_only()) {
    uint64_t hash = 0;
    if (!in.u64(&hash)) return Status::Ok();
  } else {
    if (!skip_frame(&in)) return Status::Ok();
    if (header.keeps_coded_order() && !skip_frame(&in)) return Status::Ok();
  }
  frames->head_complete = true;
  while (static_cast<int32_t>(frames->chunk_ends.size()) < header.chunks && skip_frame(&in)) {
    frames->chunk_ends.push_back(in.offset());
  }
  return Status::Ok();
}

}  // namespace gab
