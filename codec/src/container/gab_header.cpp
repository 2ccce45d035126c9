#include "container/gab_header.h"

#include <cmath>
#include <cstring>
#include <string>

#include "container/crc32.h"

namespace gab {

namespace {

Status header_error(const std::string& what) {
  return Status::Error(StatusCode::kParseError, "bad .gab header: " + what);
}

std::string hex_byte(unsigned byte) {
  const char* digits = "0123456789abcdef";
  return std::string("0x") + digits[(byte >> 4) & 15] + digits[byte & 15];
}

}  // namespace

void write_gab_header(const GabHeader& h, ByteWriter* out) {
  const size_t start = out->size();
  out->bytes(kGabMagic, sizeof kGabMagic);
  out->u8(h.version);
  out->u8(h.flags);
  out->u8(static_cast<uint8_t>(h.bits));
  out->u8(h.ordering);
  out->u32(static_cast<uint32_t>(h.num_vertices));
  out->u32(static_cast<uint32_t>(h.num_triangles));
  out->f64(h.weight);
  for (int c = 0; c < 3; ++c) out->f64(h.box_min[c]);
  out->f64(h.step);
  out->u32(static_cast<uint32_t>(h.anchors));
  out->u32(static_cast<uint32_t>(h.chunks));
  out->u32(crc32(out->data().data() + start, out->size() - start));
}

Status read_gab_header(ByteReader* in, size_t file_size, GabHeader* h) {
  const uint8_t* raw = nullptr;
  if (!in->bytes(sizeof kGabMagic, &raw) || std::memcmp(raw, kGabMagic, sizeof kGabMagic) != 0) {
    return Status::Error(StatusCode::kParseError, "not a .gab file (bad magic)");
  }
  uint8_t version = 0, flags = 0, bits = 0, ordering = 0;
  uint32_t n = 0, faces = 0, anchors = 0, chunks = 0, crc = 0;
  double weight = 0, min[3] = {0, 0, 0}, step = 0;
  if (!in->u8(&version) || !in->u8(&flags) || !in->u8(&bits) || !in->u8(&ordering) || !in->u32(&n) ||
      !in->u32(&faces) || !in->f64(&weight) || !in->f64(&min[0]) || !in->f64(&min[1]) || !in->f64(&min[2]) ||
      !in->f64(&step) || !in->u32(&anchors) || !in->u32(&chunks)) {
    return header_error("file ends inside the header");
  }
  if (version != kGabVersion) {
    return Status::Error(StatusCode::kUnsupported, "unsupported .gab version " + std::to_string(version) +
                                                      " (this build reads version " +
                                                      std::to_string(kGabVersion) + ")");
  }
  const size_t covered = in->offset();
  if (!in->u32(&crc)) return header_error("file ends inside the header");
  if (crc != crc32(raw, covered)) return header_error("checksum mismatch (the header is corrupt)");
  // The header's checksum holds, so unknown flags come from a newer writer,
  // not from damage.
  const unsigned known = known_gab_flags();
  if ((flags & ~known) != 0) {
    return Status::Error(StatusCode::kUnsupported,
                         "unsupported .gab flags " + hex_byte(flags) + " (this build knows " + hex_byte(known) + ")");
  }
  if (ordering > kGabOrderingNestedDissection) {
    return Status::Error(StatusCode::kUnsupported, "unsupported .gab ordering " + std::to_string(ordering) +
                                                       " (this build knows 0: amd, 1: nd)");
  }
  if (bits < kGabMinBits || bits > kGabMaxBits) return header_error("bits " + std::to_string(bits) + " out of range");
  if (n < 1 || n > 0x7FFFFFFFu || faces < 1 || faces > 0x7FFFFFFFu / 3) {
    return header_error("vertex or triangle count out of range");
  }
  if (!(weight > 0) || !std::isfinite(weight)) return header_error("anchor weight is not positive and finite");
  for (double m : min) {
    if (!std::isfinite(m)) return header_error("bounding box is not finite");
  }
  if (!(step >= 0) || !std::isfinite(step)) return header_error("grid step is not finite and non-negative");
  if (anchors < 1 || anchors > n) return header_error("anchor count out of range");
  const uint32_t trailing = ((flags & kGabFlagRefined) != 0 ? 1 : 0) + ((flags & kGabFlagDetail) != 0 ? 1 : 0);
  if (chunks < 1 + trailing || chunks - trailing > anchors) return header_error("chunk count out of range");
  // Every vertex is on a triangle or isolated, and an isolated vertex is an
  // anchor of chunk 0 costing bits in the file; real files stay far inside
  // this bound, forged counts do not.
  const uint64_t plausible = 3ull * faces + 64ull * file_size;
  if (n > plausible) return header_error("vertex count is implausible for a file of this size");
  h->version = version;
  h->flags = flags;
  h->bits = bits;
  h->ordering = ordering;
  h->num_vertices = static_cast<int32_t>(n);
  h->num_triangles = static_cast<int32_t>(faces);
  h->weight = weight;
  for (int c = 0; c < 3; ++c) h->box_min[c] = min[c];
  h->step = step;
  h->anchors = static_cast<int32_t>(anchors);
  h->chunks = static_cast<int32_t>(chunks);
  return Status::Ok();
}

}  // namespace gab
