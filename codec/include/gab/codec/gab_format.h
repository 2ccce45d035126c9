// The .gab file format, version 2: what an embedder needs to recognise a file
// and read its header. docs/format.md specifies the whole format for someone
// writing a second decoder; the codec (codec/src) reads and writes it and
// decoder.h's read_gab_info reports it. All integers little-endian; every
// block after the header is framed as  u32 length, u32 CRC-32 of the payload,
// payload; a varint is LEB128 (7 bits a byte, low first, minimal).
//
//   file   = header (63 to 83 bytes), connectivity, geometry chunks, sections
//   header = magic[8] 89 'G' 'A' 'B' 0D 0A 1A 0A, version u8 (2), flags u8,
//            bits u8, ordering u8, reconstruction u8, reserved u8 (zero),
//            n varint, faces varint, weight f64, box_min f64[3], step f64,
//            anchors varint, chunks varint, sections varint,
//            crc u32 (of every header byte before it)
//
// A reader refuses a version, flag bit, ordering or reconstruction
// operator it does not know and a required section of a kind it does not
// know (kUnsupported; it skips an optional one), and any inconsistency
// (kParseError). The reserved byte and the section kinds
// are where later revisions add what they need (another connectivity coder,
// attributes) without breaking a version-2 file.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace gab {

constexpr uint8_t kGabMagic[8] = {0x89, 'G', 'A', 'B', 0x0D, 0x0A, 0x1A, 0x0A};
constexpr uint8_t kGabVersion = 2;
constexpr size_t kGabMinHeaderBytes = 63;  // every varint one byte
constexpr size_t kGabMaxHeaderBytes = 83;  // every varint five (32 bits)

// Flags (header byte 9).
// The connectivity is not in the file: a u64 hash of the mesh the decoder must be given.
constexpr uint8_t kGabFlagGeometryOnly = 1;
// A refinement chunk follows the anchor chunks (every anchor's coefficient moved towards least squares).
constexpr uint8_t kGabFlagRefined = 2;
// The anchor chunks are in the level layout (chunk 0 the anchor set, then one level's positions per chunk).
constexpr uint8_t kGabFlagLevels = 4;
// The vertices are numbered in the connectivity coder's traversal order: no vertex order block.
constexpr uint8_t kGabFlagReordered = 8;
// A detail chunk ends the geometry: every vertex as a residual from a prediction over the anchors' shape.
constexpr uint8_t kGabFlagDetail = 16;

// The fill-reducing ordering the encoder factored with (header byte 11).
// Decoding is correct with any ordering (every prediction is rounded
// through a guard band); the decoder uses the file's by default.
constexpr uint8_t kGabOrderingAmd = 0;
constexpr uint8_t kGabOrderingNestedDissection = 1;

// The reconstruction operator R(anchors) -> shape that encoder and decoder
// share (header byte 12). 0: the paper's global relaxed least squares,
// factored. 1: the same system by a fixed number of conjugate-gradient steps
// per shape, linear in n, a chunk predicted by such steps too (docs/format.md
// 5.2.1). 2: 1's shape (its start's ties broken another way), a chunk
// predicted by the start alone, evaluated around the chunk's vertices
// (5.2.2). 3: 2 with its sweeps and final steps given at the head of chunk
// 0: the encoder's iterative operator (5.2.3).
constexpr uint8_t kGabReconstructionGlobal = 0;
constexpr uint8_t kGabReconstructionIterative = 1;
constexpr uint8_t kGabReconstructionIterativeLocal = 2;
constexpr uint8_t kGabReconstructionIterativeTuned = 3;

// The operator as an option (EncodeOptions::solver) and in the stats.
// kIterative: cost linear in n, memory a few arrays per vertex. kGlobal:
// files about 10% smaller at 1e-3 (2% at 1e-4), decodes an order of
// magnitude slower in several times the memory (a factor), and the only
// one with the refinement chunk.
// kAuto: kIterative, or kGlobal when the refinement chunk is asked for.
enum class Solver { kAuto, kGlobal, kIterative };
// "auto", "global", "iterative": the names the CLI, its JSON and Python use.
const char* solver_name(Solver solver);
// The solver a name gives; false for any other name.
bool parse_solver(const std::string& name, Solver* solver);
// The solver a header's operator code (byte 12, one the header check
// accepted) stands for: kGlobal or kIterative.
Solver solver_of_header(int reconstruction);

// The largest anchor weight and coordinate magnitude a file holds: w^2
// times a coordinate, the relaxed system's right-hand side, stays finite
// with a wide margin. A header's grid may reach twice as far (its far
// corner rounds past the mesh's box).
constexpr double kGabMaxMagnitude = 1e100;

constexpr int kGabMinBits = 2;
constexpr int kGabMaxBits = 24;

// A trailing section's payload starts with its kind (u8) and its flags
// (u8); a reader skips a section of a kind it does not know unless the
// section says it is required.
constexpr uint8_t kGabSectionRequired = 1;

// The header's fields, as the file stores them.
struct GabHeader {
  uint8_t version = kGabVersion;
  uint8_t flags = 0;
  int bits = 12;
  uint8_t ordering = kGabOrderingAmd;
  uint8_t reconstruction = kGabReconstructionGlobal;
  int32_t num_vertices = 0;
  int32_t num_triangles = 0;
  double weight = 1.0;
  double box_min[3] = {0, 0, 0};  // the grid's origin
  double step = 0;                // the grid's spacing (0: a box of zero size)
  int32_t anchors = 0;
  int32_t chunks = 0;    // geometry chunks: the anchor chunks, the refinement and the detail
  int32_t sections = 0;  // framed sections after the geometry chunks

  bool geometry_only() const { return (flags & kGabFlagGeometryOnly) != 0; }
  bool refined() const { return (flags & kGabFlagRefined) != 0; }
  bool levels() const { return (flags & kGabFlagLevels) != 0; }
  bool reordered() const { return (flags & kGabFlagReordered) != 0; }
  bool detail() const { return (flags & kGabFlagDetail) != 0; }
  // The connectivity section ends with the input's vertex order.
  bool keeps_coded_order() const { return !reordered() && !geometry_only(); }
  // Chunks holding anchors (all but the refinement and the detail).
  int32_t anchor_chunks() const { return chunks - (refined() ? 1 : 0) - (detail() ? 1 : 0); }
  // The index of the refinement chunk (when refined) and of the detail chunk (when detail).
  int32_t refinement_chunk() const { return anchor_chunks(); }
  int32_t detail_chunk() const { return chunks - 1; }
};

}  // namespace gab
