#include "container/gab_header.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "container/crc32.h"
#include "container/framing.h"

namespace gab {

namespace {

Status header_error(const std::string& what) {
  return Status::Error(StatusCode::kParseError, "bad .gab header: " + what);
}

std::string hex_byte(unsigned byte) {
  const char* digits = "0123456789abcdef";
  return std::string("0x") + digits[(byte >> 4) & 15] + digits[byte & 15];
}

// Reads the header's fields in order, remembering why the first read that
// failed did: the file ended, or a count is not a minimal LEB128 varint of
// at most 32 bits (5 bytes).
struct FieldReader {
  ByteReader* in;
  bool truncated = false, malformed = false;

  bool ok() const { return !truncated && !malformed; }
  void u8(uint8_t* v) {
    if (ok() && !in->u8(v)) truncated = true;
  }
  void f64(double* v) {
    if (ok() && !in->f64(v)) truncated = true;
  }
  void count(uint64_t* v) {
    *v = 0;
    for (int i = 0; i < 5 && ok(); ++i) {
      uint8_t byte = 0;
      u8(&byte);
      if (!ok()) return;
      *v |= static_cast<uint64_t>(byte & 0x7F) << (7 * i);
      if ((byte & 0x80) == 0) {
        malformed = (i > 0 && byte == 0) || *v > 0xFFFFFFFFu;
        return;
      }
    }
    if (ok()) malformed = true;  // a sixth byte would follow
  }
};

}  // namespace

void write_gab_header(const GabHeader& h, ByteWriter* out) {
  const size_t start = out->size();
  out->bytes(kGabMagic, sizeof kGabMagic);
  out->u8(h.version);
  out->u8(h.flags);
  out->u8(static_cast<uint8_t>(h.bits));
  out->u8(h.ordering);
  out->u8(h.reconstruction);
  out->u8(0);  // reserved
  out->varint(static_cast<uint32_t>(h.num_vertices));
  out->varint(static_cast<uint32_t>(h.num_triangles));
  out->f64(h.weight);
  for (int c = 0; c < 3; ++c) out->f64(h.box_min[c]);
  out->f64(h.step);
  out->varint(static_cast<uint32_t>(h.anchors));
  out->varint(static_cast<uint32_t>(h.chunks));
  out->varint(static_cast<uint32_t>(h.sections));
  out->u32(crc32(out->data().data() + start, out->size() - start));
}

Status read_gab_header(ByteReader* in, size_t file_size, GabHeader* h) {
  const uint8_t* raw = nullptr;
  if (!in->bytes(sizeof kGabMagic, &raw) || std::memcmp(raw, kGabMagic, sizeof kGabMagic) != 0) {
    return Status::Error(StatusCode::kParseError, "not a .gab file (bad magic)");
  }
  uint8_t version = 0;
  if (!in->u8(&version)) return header_error("file ends inside the header");
  if (version != kGabVersion) {
    return Status::Error(StatusCode::kUnsupported,
                         "unsupported .gab version " + std::to_string(version) + " (this build reads version " +
                             std::to_string(kGabVersion) + (version < kGabVersion ? "; re-encode the mesh" : "") +
                             ")");
  }
  uint8_t flags = 0, bits = 0, ordering = 0, reconstruction = 0, reserved = 0;
  uint64_t n = 0, faces = 0, anchors = 0, chunks = 0, sections = 0;
  uint32_t crc = 0;
  double weight = 0, min[3] = {0, 0, 0}, step = 0;
  FieldReader f{in};
  f.u8(&flags);
  f.u8(&bits);
  f.u8(&ordering);
  f.u8(&reconstruction);
  f.u8(&reserved);
  f.count(&n);
  f.count(&faces);
  f.f64(&weight);
  for (double& m : min) f.f64(&m);
  f.f64(&step);
  f.count(&anchors);
  f.count(&chunks);
  f.count(&sections);
  if (f.truncated) return header_error("file ends inside the header");
  if (f.malformed) return header_error("a count in the header is not a minimal 32-bit varint");
  const size_t covered = in->offset();
  if (!in->u32(&crc)) return header_error("file ends inside the header");
  if (!checksum_matches(crc, crc32(raw, covered))) return header_error("checksum mismatch (the header is corrupt)");
  // The header's checksum holds, so an unknown value comes from a newer
  // writer, not from damage.
  const unsigned known = known_gab_flags();
  if ((flags & ~known) != 0) {
    return Status::Error(StatusCode::kUnsupported,
                         "unsupported .gab flags " + hex_byte(flags) + " (this build knows " + hex_byte(known) + ")");
  }
  if (ordering > kGabOrderingNestedDissection) {
    return Status::Error(StatusCode::kUnsupported, "unsupported .gab ordering " + std::to_string(ordering) +
                                                       " (this build knows 0: amd, 1: nd)");
  }
  if (reconstruction > kGabReconstructionIterativeTuned) {
    return Status::Error(StatusCode::kUnsupported,
                         "unsupported .gab reconstruction operator " + std::to_string(reconstruction) +
                             " (this build knows 0: global least squares, 1: iterative, 2: iterative, local "
                             "predictions, 3: iterative, local predictions, tuned)");
  }
  if (reserved != 0) {
    return Status::Error(StatusCode::kUnsupported, "unsupported .gab header: reserved byte 13 is " + hex_byte(reserved));
  }
  if (bits < kGabMinBits || bits > kGabMaxBits) return header_error("bits " + std::to_string(bits) + " out of range");
  if (n < 1 || n > 0x7FFFFFFFu || faces < 1 || faces > 0x7FFFFFFFu / 3) {
    return header_error("vertex or triangle count out of range");
  }
  if (!(weight > 0) || !(weight <= kGabMaxMagnitude)) return header_error("anchor weight is not in (0, 1e100]");
  for (double m : min) {
    if (!std::isfinite(m)) return header_error("bounding box is not finite");
  }
  if (!(step >= 0) || !std::isfinite(step)) return header_error("grid step is not finite and non-negative");
  // The grid's coordinates lie between min and min + step (2^bits - 1).
  const double span = step * static_cast<double>((uint32_t{1} << bits) - 1);
  for (double m : min) {
    if (!(std::max(std::fabs(m), std::fabs(m + span)) <= 2 * kGabMaxMagnitude)) {
      return header_error("the grid reaches past 2e100");
    }
  }
  if (anchors < 1 || anchors > n) return header_error("anchor count out of range");
  const uint32_t trailing = ((flags & kGabFlagRefined) != 0 ? 1 : 0) + ((flags & kGabFlagDetail) != 0 ? 1 : 0);
  if (chunks < 1 + trailing || chunks - trailing > anchors) return header_error("chunk count out of range");
  // Every vertex is on a triangle or isolated, and an isolated vertex is an
  // anchor of chunk 0 costing bits in the file; real files stay far inside
  // this bound, forged counts do not.
  const uint64_t plausible = 3ull * faces + 64ull * file_size;
  if (n > plausible) return header_error("vertex count is implausible for a file of this size");
  // A section is at least its frame and its kind and flags bytes; a prefix
  // of a file may hold fewer, so the bound is the whole format's.
  if (sections > 0x7FFFFFFFu / (kGabFrameBytes + 2)) return header_error("section count out of range");
  h->version = version;
  h->flags = flags;
  h->bits = bits;
  h->ordering = ordering;
  h->reconstruction = reconstruction;
  h->num_vertices = static_cast<int32_t>(n);
  h->num_triangles = static_cast<int32_t>(faces);
  h->weight = weight;
  for (int c = 0; c < 3; ++c) h->box_min[c] = min[c];
  h->step = step;
  h->anchors = static_cast<int32_t>(anchors);
  h->chunks = static_cast<int32_t>(chunks);
  h->sections = static_cast<int32_t>(sections);
  return Status::Ok();
}

}  // namespace gab
