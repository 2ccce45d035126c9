#include "container/trailing_sections.h"

#include <string>

#include "container/framing.h"
#include "gab/codec/gab_format.h"

namespace gab {

Status read_trailing_sections(ByteReader* in, int32_t sections, std::vector<TrailingSection>* out, bool* truncated) {
  out->clear();
  for (int32_t i = 0; i < sections; ++i) {
    const std::string name = "section " + std::to_string(i);
    TrailingSection s;
    const FrameRead frame = read_framed(in, &s.payload, &s.size);
    if (frame == FrameRead::kTruncated) {
      *truncated = true;
      return Status::Ok();
    }
    if (frame == FrameRead::kCorrupt) {
      return Status::Error(StatusCode::kParseError, name + " is corrupt (checksum mismatch)");
    }
    if (s.size < 2) return Status::Error(StatusCode::kParseError, name + " has no kind and flags");
    s.kind = s.payload[0];
    s.flags = s.payload[1];
    out->push_back(s);
  }
  if (in->remaining() != 0) {
    return Status::Error(StatusCode::kParseError, sections > 0 ? "trailing bytes after the last section"
                                                               : "trailing bytes after the last chunk");
  }
  return Status::Ok();
}

Status check_unknown_section(const TrailingSection& section, int32_t index) {
  if ((section.flags & kGabSectionRequired) == 0) return Status::Ok();
  return Status::Error(StatusCode::kUnsupported, "section " + std::to_string(index) + " is of kind " +
                                                     std::to_string(section.kind) +
                                                     ", which this build does not know and the file requires");
}

}  // namespace gab
