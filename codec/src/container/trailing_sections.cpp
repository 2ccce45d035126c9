#include "container/trailing_sections.h"

#include <string>

#include "container/framing.h"
#include "gab/codec/gab_format.h"

namespace gab {

Status skip_trailing_sections(ByteReader* in, int32_t sections, int32_t* skipped, bool* truncated) {
  *skipped = 0;
  for (int32_t i = 0; i < sections; ++i) {
    const std::string name = "section " + std::to_string(i);
    const uint8_t* payload = nullptr;
    size_t size = 0;
    const FrameRead frame = read_framed(in, &payload, &size);
    if (frame == FrameRead::kTruncated) {
      *truncated = true;
      return Status::Ok();
    }
    if (frame == FrameRead::kCorrupt) {
      return Status::Error(StatusCode::kParseError, name + " is corrupt (checksum mismatch)");
    }
    if (size < 2) return Status::Error(StatusCode::kParseError, name + " has no kind and flags");
    if ((payload[1] & kGabSectionRequired) != 0) {
      return Status::Error(StatusCode::kUnsupported, name + " is of kind " + std::to_string(payload[0]) +
                                                         ", which this build does not know and the file requires");
    }
    ++*skipped;
  }
  if (in->remaining() != 0) {
    return Status::Error(StatusCode::kParseError, sections > 0 ? "trailing bytes after the last section"
                                                               : "trailing bytes after the last chunk");
  }
  return Status::Ok();
}

}  // namespace gab
