// The .gab file format, version 1: what an embedder needs to recognise a file
// and read its header (the codec reads and writes it; decoder.h's
// read_gab_info reports it). The method is the paper's (Sorkine, Cohen-Or,
// Irony, Toledo, "Geometry-Aware Bases for Shape Approximation", IEEE TVCG
// 2005); the coders named below live in codec/src. All integers
// little-endian; a chunk or block is framed as  u32 length, u32 CRC-32 of the
// payload, payload.
//
//   magic      8 bytes  89 'G' 'A' 'B' 0D 0A 1A 0A (binary-safe, like PNG's)
//   version    u8 (1), flags u8 (bit 0: geometry only; bit 1: refined;
//              bit 2: levels; bit 3: reordered; bit 4: versioned valence;
//              bit 5: detail),
//              bits q u8, ordering u8 (0: AMD, 1: nested dissection; see
//              kGabOrderingAmd)
//   n, faces   u32, u32   vertex and triangle counts
//   weight     f64        anchor weight w of the relaxed basis
//   box min    3 x f64    quantization grid origin
//   step       f64        grid spacing (codec/src/anchors/quantizer.h)
//   anchors    u32        anchors in the file, over all chunks
//   chunks     u32        chunks in the file (the refinement and detail included)
//   crc        u32        CRC-32 of the 68 bytes above
//   connectivity: in geometry-only mode the u64 connectivity_hash of the
//              mesh the decoder must be given; with bit 4 a framed block,
//              a version byte then the valence section
//              (codec/src/connectivity/valence_section.h), and unless bit 3
//              the framed vertex order (connectivity/order_coder.h); with
//              bit 3 alone the framed valence section, version 1; with
//              neither the framed triangle list (connectivity_coder.h).
//              What each variant means for the decoded mesh:
//              connectivity/connectivity_section.h
//   chunks:    framed payloads: varint anchor count b, then one range-coded
//              stream (codec/src/anchors/anchor_chunk.h): the b anchors as
//              a sorted subset of the vertices not anchored by earlier
//              chunks, then their
//              quantized positions as residuals from the reconstruction of
//              the earlier chunks (chunk 0: from the previous anchor's,
//              the first from the grid's centre).
//              Adaptive statistics carry over from chunk to chunk.
//   chunks with bit 2 (levels; codec/src/anchors/anchor_levels.h): chunk 0
//              is varints spread s, rest r, growth g (sixteenths), then one
//              stream: the
//              s spread anchors as a subset (positions as chunk 0's above),
//              then the r other anchors as a subset of the vertices left.
//              Chunk k >= 1 is level k's positions only (a stream of
//              residuals from the reconstruction of the chunks before it);
//              which anchors form level k the decoder works out from the
//              connectivity (farthest-point order of the r anchors, sizes
//              from s, r and g), so the header's chunk count must be
//              1 + the levels (+ 1 refined).
//   refinement (flag bit 1 only): one framed payload after the anchor
//              chunks correcting every anchor's quantized position towards
//              the least-squares optimal coefficient
//              (codec/src/anchors/refinement_chunk.h); it applies to the
//              whole anchor set only.
//   detail (flag bit 5 only): the last framed payload, a version byte, the
//              residuals' step and blend, then every vertex's position as a
//              quantized residual from a prediction built on the
//              reconstruction of all the anchors (codec/src/detail/
//              detail_chunk.h); it applies to the whole anchor set only.
// Any prefix of whole chunks is a valid coarser approximation. A file
// without bits 1 to 5 is what the first version of this format wrote; a
// reader that does not know a bit refuses such files ("unknown flags"). The
// encoder writes bit 4 (with bit 3 for --reorder) unless geometry only; the
// triangle list and the unversioned valence section are read, not written.
// It writes bit 5 when a detail layer codes smaller (or alone meets the
// target): below about 3e-4 relative RMS (encoder.h DetailMode).
//
// Why the levels are a flag and not version 2: the header, the framing, the
// connectivity section and the refinement are unchanged, and the flag
// combines with the other two; only the meaning of the chunk payloads
// changes, which is what a flag says (as bit 1 did). A version-1 reader
// refuses a levels file cleanly, and every file written before reads as
// before. The encoder writes levels unless the first layout codes smaller
// (encoder.h FileLayout): the selection order that the first layout pays
// for (each chunk a subset of the vertices still free) buys a better
// prediction than the decoder's own farthest-point levels, but less than
// it costs: at 1e-3 the levels alone took 4-10% off the geometry of the
// shared meshes (igea, one level after the spread set, the same).
#pragma once

#include <cstddef>
#include <cstdint>

namespace gab {

constexpr uint8_t kGabMagic[8] = {0x89, 'G', 'A', 'B', 0x0D, 0x0A, 0x1A, 0x0A};
constexpr uint8_t kGabVersion = 1;
constexpr uint8_t kGabFlagGeometryOnly = 1;
constexpr uint8_t kGabFlagRefined = 2;
constexpr uint8_t kGabFlagLevels = 4;
// The vertices are numbered in the valence coder's traversal order (no
// vertex order block). Alone: the connectivity block is the valence
// section, version 1, without a version byte (the first --reorder files).
constexpr uint8_t kGabFlagReordered = 8;
// The connectivity block is a version byte and the valence section of that
// version (the byte versions the vertex order's coder too); unless
// reordered, a framed vertex order block follows, which
// renumbers the decoded mesh as the input was. In both, the triangles are a
// set: their order and first corners are the coder's.
constexpr uint8_t kGabFlagVersionedValence = 16;
// After the anchor chunks (and the refinement) one detail chunk codes every
// vertex's position as a residual from a prediction built on the anchors'
// reconstruction and the positions decoded before it
// (codec/src/detail/detail_chunk.h).
constexpr uint8_t kGabFlagDetail = 32;
// The fill-reducing ordering the encoder factored with (header byte 11,
// once always 0). Decoding is correct with any ordering (the codec's
// predictions are rounded through a guard, codec/src/anchors/quantizer.h;
// gab/codec/matrix_ordering.h); the decoder uses the file's by default.
constexpr uint8_t kGabOrderingAmd = 0;
constexpr uint8_t kGabOrderingNestedDissection = 1;
constexpr int kGabMinBits = 2;
constexpr int kGabMaxBits = 24;
constexpr size_t kGabHeaderBytes = 72;

// The header's fields, as the file stores them.
struct GabHeader {
  uint8_t version = kGabVersion;
  uint8_t flags = 0;
  int bits = 12;
  uint8_t ordering = kGabOrderingAmd;
  int32_t num_vertices = 0;
  int32_t num_triangles = 0;
  double weight = 1.0;
  double box_min[3] = {0, 0, 0};  // the grid's origin
  double step = 0;                // the grid's spacing (0: a box of zero size)
  int32_t anchors = 0;
  int32_t chunks = 0;

  bool geometry_only() const { return (flags & kGabFlagGeometryOnly) != 0; }
  bool refined() const { return (flags & kGabFlagRefined) != 0; }
  bool levels() const { return (flags & kGabFlagLevels) != 0; }
  bool reordered() const { return (flags & kGabFlagReordered) != 0; }
  bool versioned_valence() const { return (flags & kGabFlagVersionedValence) != 0; }
  bool detail() const { return (flags & kGabFlagDetail) != 0; }
  // The connectivity section ends with the input's vertex order.
  bool keeps_coded_order() const { return versioned_valence() && !reordered() && !geometry_only(); }
  // Chunks holding anchors (all but the refinement and the detail).
  int32_t anchor_chunks() const { return chunks - (refined() ? 1 : 0) - (detail() ? 1 : 0); }
  // The index of the refinement chunk (when refined) and of the detail chunk (when detail).
  int32_t refinement_chunk() const { return anchor_chunks(); }
  int32_t detail_chunk() const { return chunks - 1; }
};

}  // namespace gab
