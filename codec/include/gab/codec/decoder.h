// Decompression of a .gab file (gab_format.h), and a look inside one without
// decoding it.
//
// Contract on untrusted input: every malformed, corrupted or forged file
// gets a kParseError naming what is wrong (header field, connectivity block,
// chunk number); a well-formed file of a newer format (version or flags)
// gets kUnsupported; a file whose matrix or factor exceeds DecodeOptions'
// limits gets kResourceExhausted, and one whose factor's memory cannot be
// had kOutOfMemory. Nothing is read outside the buffer; allocations are
// bounded by the file's size and DecodeOptions' limits. A file cut short decodes to
// the shape of its complete chunks and says so (DecodeStats::truncated).
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "gab/codec/gab_format.h"
#include "gab/codec/matrix_ordering.h"
#include "gab/mesh/mesh.h"
#include "gab/status.h"

namespace gab {

// The automatic decode budget (DecodeOptions::max_memory = 0): bytes of
// memory per byte of the file, and the least.
constexpr int64_t kDecodeMemoryPerFileByte = int64_t{32} << 10;
constexpr int64_t kMinDecodeMemory = int64_t{64} << 20;

struct DecodeOptions {
  int32_t max_anchors = -1;            // decode only the first K anchors (level of detail); -1: all
  // Apply the detail chunk when the file has one and every anchor is decoded
  // (false: the anchors' smooth shape, the level of detail just below).
  bool detail = true;
  const Mesh* connectivity = nullptr;  // the mesh whose triangles a geometry-only file refers to
  // Refuse connectivity whose least-squares matrix (the 2-ring pattern)
  // would have more entries than this, or whose factor would: what keeps a
  // forged fan of triangles from asking for gigabytes.
  int64_t max_matrix_entries = int64_t{1} << 31;
  int64_t max_factor_entries = int64_t{3} << 30;
  // The decode's memory budget in bytes: its factor, matrix and per-vertex
  // arrays, estimated from the header, then the connectivity, then the
  // symbolic analysis, each before what it sizes is built; over it,
  // kResourceExhausted. 0: automatic, kDecodeMemoryPerFileByte per byte of
  // the file and at least kMinDecodeMemory, so an ordinary file gets what its
  // decode needs (igea's 58 KB file: 1.8 GB allowed, 0.33 GB used) and a
  // small file cannot claim gigabytes (a 3.3 KB file of a regular 1M-vertex
  // torus needs 2.9 GB: refused unless raised). Negative: no budget.
  int64_t max_memory = 0;
  // Threads for the factorizations; the shape is bit-identical for any count.
  int32_t threads = 1;
  // The factorization's ordering (matrix_ordering.h); kAuto: the file's. Any other decodes the same anchors
  // and a shape equal up to rounding.
  Ordering ordering = Ordering::kAuto;
  // Called before each chunk is decoded (chunk index, chunks in the file).
  std::function<void(int32_t, int32_t)> progress;
};

struct DecodeStats {
  int32_t num_vertices = 0, num_triangles = 0;
  int32_t anchors = 0, anchors_in_file = 0;
  int32_t chunks = 0, chunks_in_file = 0;
  bool truncated = false;  // the file ended inside a chunk: the shape is of the complete ones
  bool refined = false;    // the refinement chunk was applied (whole anchor set, complete file)
  bool detail = false;     // the detail chunk was applied (gab_format.h, kGabFlagDetail)
  int bits = 0;
  double weight = 0;
  bool geometry_only = false;
  bool reordered = false;  // numbered in the connectivity coder's traversal order (kGabFlagReordered)
  double decode_s = 0, factor_s = 0, solve_s = 0, update_s = 0;
  double connectivity_s = 0;  // decoding the connectivity section
  double detail_s = 0;        // decoding the detail chunk (part of decode_s)
  int32_t refactorizations = 0;  // chunks added by refactoring rather than updates
  int32_t skipped_sections = 0;  // trailing sections of kinds this build does not know (gab_format.h)
  double attributes_s = 0;       // decoding the attribute sections (part of decode_s)
  Ordering ordering = Ordering::kAmd;  // the factorization's ordering (never kAuto)
  Solver solver = Solver::kGlobal;     // the file's reconstruction operator (never kAuto)
  int64_t matrix_entries = 0;          // the least-squares matrix's lower triangle, bounded from the connectivity
  int64_t factor_entries = 0;          // the factor's stored entries (0 before chunk 0 is decoded)
  int64_t memory_limit = 0;            // the budget the decode ran under (DecodeOptions::max_memory resolved)
};

// Decodes `data` into `mesh`: positions, triangles and the attributes the
// file carries (any level of detail decodes them whole: they depend on the
// connectivity only).
Status decode_mesh(const uint8_t* data, size_t size, const DecodeOptions& options, Mesh* mesh, DecodeStats* stats);

struct GabFileInfo {
  int version = 0;
  int reconstruction = 0;  // the reconstruction operator (gab_format.h, header byte 12)
  // Operators 2 and 3: their sweeps and final steps (EncodeOptions's fields of these names; operator 3's
  // from chunk 0, read when it is present); 0 otherwise.
  int32_t prediction_sweeps = 0, final_sweeps = 0, final_steps16 = 0, final_most_steps = 0;
  int32_t sections = 0;    // framed sections after the geometry chunks
  int32_t num_vertices = 0, num_triangles = 0;
  int bits = 0;
  double weight = 0;
  bool geometry_only = false;
  double box_min[3] = {0, 0, 0};
  double step = 0;
  int32_t anchors = 0, chunks = 0;  // as the header declares (chunks: the refinement and detail included)
  int32_t chunks_present = 0;       // complete chunks with a valid checksum
  bool refined = false;             // the last chunk is a refinement (not counted below)
  bool levels = false;              // the level layout (gab_format.h, kGabFlagLevels)
  bool reordered = false;           // traversal numbering, no vertex order (kGabFlagReordered)
  size_t refinement_bytes = 0;      // its framed size when present
  bool detail = false;              // the last chunk is the detail layer (kGabFlagDetail; not counted below)
  size_t detail_bytes = 0;          // its framed size when present
  double detail_step = 0;           // its quantization step (in the mesh's units) when present
  Ordering ordering = Ordering::kAmd;  // the encoder's factorizations' (header byte 11)
  bool truncated = false;
  size_t bytes = 0, connectivity_bytes = 0, geometry_bytes = 0;
  size_t header_bytes = 0;             // the header's size (its counts are varints)
  size_t order_bytes = 0;              // the vertex order block with its framing (0 without)
  std::vector<size_t> chunk_bytes;     // framed size of each complete anchor chunk
  std::vector<int32_t> chunk_anchors;  // anchors each complete anchor chunk declares
  // The trailing sections that have arrived (with a valid checksum), in file order.
  struct Section {
    int kind = 0;            // 1: an attribute (docs/format.md 6)
    size_t bytes = 0;        // with its framing
    std::string attribute;   // an attribute's label ("normals", "generic:quality"); "" for another kind
    bool per_corner = false;
    int64_t elements = 0;
    int bits = 0;
    int predictor = 0;  // 0, 5 the neighbours' values; 1-4, 6 also the decoded surface (docs/format.md 6.4)
  };
  std::vector<Section> section_list;
  size_t section_bytes = 0;  // all of them with their framing (not in geometry_bytes)
};

// Reads the header and walks the chunk frames, checking every checksum,
// without decoding anything. O(file size).
Status read_gab_info(const uint8_t* data, size_t size, GabFileInfo* info);

// Where a file still arriving can be cut: for its first `size` bytes, the
// offset just past each chunk (of every kind, in file order) that has fully
// arrived. Each such prefix decodes on its own (decode_mesh), a coarser shape.
struct GabStreamFrames {
  bool head_complete = false;     // the header and the connectivity section have arrived
  int32_t chunks_in_file = 0;     // as the header declares (0 until it has arrived)
  std::vector<size_t> chunk_ends;  // byte offset just past each complete chunk
};

// Fills *frames from the header and the frames' lengths, without checking
// the checksums (decode_mesh does). kParseError / kUnsupported for a bad
// header, as decode_mesh. O(chunks).
Status find_gab_chunk_ends(const uint8_t* data, size_t size, GabStreamFrames* frames);

}  // namespace gab
