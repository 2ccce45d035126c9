// Compression of a mesh to a .gab file (gab_format.h): a well-spread initial
// set of anchors, then greedy batches at the largest errors (Sorkine et al.
// 2005, sec. IV), in a closed loop (the encoder reconstructs from exactly the
// quantized coefficients the decoder will get), coded chunk by chunk.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "gab/codec/gab_format.h"
#include "gab/codec/matrix_ordering.h"
#include "gab/mesh/mesh.h"
#include "gab/status.h"

namespace gab {

struct EncodeOptions;
struct EncodeStats;

// Compresses `mesh` (valid per validate_mesh) into `file`. kInvalidArgument
// for a bad option or mesh. The file is byte-identical for any thread count.
//
// Cost: the encoder codes one to three candidate files and keeps the
// smallest that meets the targets (EncodeStats::candidates lists them).
// Each candidate is a greedy loop (a factorization, then per step a solve
// and an update or refactorization), with a detail layer also a search of
// 2-3 O(n) trials. The candidates close to the best (within 2%) are then
// finished: the level layout (a decoder's work) and, with a detail layer,
// about 17 more O(n) trials. Which candidates, by target: one (anchors
// alone) down to a relative RMS of 5e-4, and a second on a coarser grid when
// that anchored over half the vertices; between 5e-4 and 2e-4 anchors alone
// and two with a detail layer; below 2e-4 (or with DetailMode::kOn) the two
// with a detail layer, whose greedy loops stop at about 3e-3. An anchor
// count alone, or DetailMode::kOff, codes one.
Status encode_mesh(const Mesh& mesh, const EncodeOptions& options, std::vector<uint8_t>* file, EncodeStats* stats);
// The same file from a mesh the caller gives up: its arrays are taken
// rather than copied (one copy of them fewer at the factorization's peak);
// `mesh` is left empty unless the options or the mesh are refused
// (or options.geometry_only is set, when it is only read).
Status encode_mesh(Mesh&& mesh, const EncodeOptions& options, std::vector<uint8_t>* file, EncodeStats* stats);

// How a file arranges its anchor chunks (gab_format.h).
enum class FileLayout {
  kSmaller,         // both below, keeping the levels unless selection order codes smaller
  kLevels,          // kGabFlagLevels: chunk 0 codes the anchor set once; the decoder orders it into levels
  kSelectionOrder,  // the first layout: each chunk its anchors as a subset of the vertices still free
};

// The detail layer (gab_format.h, kGabFlagDetail): after the anchors, every
// vertex coded as a small residual from a prediction, which is what keeps
// files small at low error targets (below about 3e-4) and meets any target.
enum class DetailMode {
  kAuto,  // with an error target: the smallest of the files with and without it that meets the target
  kOn,    // with an error target: always (the anchors stop at a coarse target)
  kOff,   // never: the anchors alone (the target may be missed on small meshes)
};

struct EncodeOptions {
  // Stopping rules, at least one (the loop also stops when every vertex is an anchor).
  int32_t max_anchors = 0;     // anchors in the file; 0: no count limit
  double target_rms_rel = 0;   // relative vertex RMS (over the bounding-box diagonal); 0: none
  double target_linf_rel = 0;  // relative max vertex error; 0: none
  // q, bits per coordinate (kGabMinBits..kGabMaxBits); 0: the encoder's, from the target (12 for a count alone).
  int bits = 0;
  double weight = 100;           // anchor weight w of the relaxed basis, in (0, 1e100]
  bool geometry_only = false;    // store a connectivity hash: the decoder must be given the same mesh
  // Drop the input's vertex numbering (flag kGabFlagReordered; the default): the decoded mesh is numbered in
  // the connectivity coder's traversal order (EncodeStats::new_index maps input vertices to decoded ones),
  // its attributes with it, which saves the vertex order block (EncodeStats::order_bytes: 1-2 bytes a
  // vertex); copies of a vertex (equal coordinates: a file split along seams, a triangle soup) are merged
  // into one, their attributes kept per corner (EncodeStats::merged_vertices). false keeps the input's numbering at that price, for data keyed by vertex index outside the
  // file. Either way the triangles come back as a set: in the coder's order, each from the corner it
  // chooses, orientation kept. A geometry-only file keeps the numbering of the mesh its decoder is given,
  // whatever this says.
  bool reorder = true;
  int32_t initial_anchors = 0;   // spread set size (at least one per component); 0: the encoder's
  // Greedy batch, a fraction (<= 1) of the anchors so far, fewer near an RMS target so the file does not
  // overshoot; 0: one anchor per step (the paper's); negative: the encoder's, by the reconstruction operator
  // and the mesh's size, larger while the error is far above an RMS target (the iterative operator keeps a
  // batch's picks apart and trims the last batch to what the target needs).
  double batch_fraction = -1;
  // A chunk closes when the anchor count has grown by this factor (> 1), and it sets the level growth of
  // the level layout too: fewer chunks or levels decode faster, more predict better. Non-positive: the encoder's.
  double chunk_growth = -1;
  FileLayout layout = FileLayout::kSmaller;  // the chunks' arrangement
  // A last chunk moving every anchor's coefficient towards least squares (sec. IV), kept only where it
  // lowers the RMS without breaking an L-inf target; with an RMS target the loop stops once the refined shape meets it.
  bool refine = false;
  // The detail layer (needs an error target; an anchor count alone never uses it). `bits` fixes the
  // anchors' grid only: the detail layer has its own step.
  DetailMode detail = DetailMode::kAuto;
  int refine_iterations = 4;  // conjugate-gradient iterations of the refinement (positive; each costs two solves)
  int32_t threads = 1;        // threads for the factorizations; the file is the same for any count
  // The factorizations' ordering (matrix_ordering.h), recorded in the file: a matter of speed (files from
  // different orderings differ by rounding-level choices of the greedy loop only).
  Ordering ordering = Ordering::kAuto;
  // The reconstruction operator, recorded in the file (gab_format.h, header byte 12).
  Solver solver = Solver::kAuto;
  // The iterative operator's work per decode, recorded in the file (docs/format.md 5.2.3); -1 each: the
  // encoder's (by the mesh's size). Fewer sweeps and steps decode faster and the file grows (more anchors
  // for the same error, rougher predictions). Harmonic sweeps of a chunk's prediction and of the final
  // shape's start (0..16); the final shape's conjugate-gradient steps per anchor spacing n / k, in
  // sixteenths (0..64), and at most (0..64).
  int32_t prediction_sweeps = -1;
  int32_t final_sweeps = -1;
  int32_t final_steps16 = -1;
  int32_t final_most_steps = -1;
  // The attributes' quantization (each coded in its own section after the geometry; docs/format.md 6).
  // Normals: directions on a lattice of about 4^bits points (8: about 0.6 degrees at most, as Draco's -qn 8
  // grid), 2..16. Texture coordinates, float colours and float generic attributes: a grid of 2^bits
  // steps over the attribute's span, 1..31. Integer-typed values (PLY uchar colours, int properties)
  // are coded exactly whatever these say.
  int normal_bits = 8;
  int texcoord_bits = 10;
  int color_bits = 8;
  int generic_bits = 16;
  std::function<void(int32_t, double)> progress;  // after every reconstruction: (anchors so far, relative RMS)
};

// One point of the greedy loop's error curve: after `anchors` anchors, the
// vertex RMS and max 3D distance of the reconstruction, relative to the
// bounding-box diagonal.
struct GreedyStep {
  int32_t anchors;
  double rms_rel;
  double linf_rel;
};

// One attribute as coded (EncodeStats::attributes).
struct AttributeStats {
  std::string label;        // attribute_label: "normals", "texture_coordinates", "vertex_colors", "generic:NAME"
  int bits = 0;             // its quantization's (integer-typed: the span's; exact)
  bool per_corner = false;  // coded per corner, with seams; false: one value per vertex
  // Normals predicted from the decoded surface (smaller where the shape is fine enough; a level of detail or
  // a decode without the detail layer then skips them); false: from the neighbours' values alone.
  bool from_surface = false;
  int64_t elements = 0;     // values coded: vertices, or per corner the wedges of corners sharing one
  size_t bytes = 0;         // its section with its framing
  // The largest error of a decoded value against the input: degrees for normals, value units otherwise.
  double max_error = 0;
};

struct EncodeStats {
  // One candidate file the encoder coded (encode_mesh's cost).
  struct Candidate {
    std::string name;           // "anchors", "anchors on a coarser grid", "detail", "detail over coarse anchors"
    int bits = 0;               // its anchors' q
    int32_t anchors = 0;
    size_t estimate_bytes = 0;  // its chunks after the greedy loop, in selection order, detail at the default blend
    size_t bytes = 0;           // the whole file when finished; 0 when its estimate was too far from the best
    bool target_met = false;
    double seconds = 0;
    bool kept = false;          // the file returned
  };

  int32_t num_vertices = 0, num_triangles = 0;
  int32_t anchors = 0, chunks = 0;
  int bits = 0;                   // q used
  size_t bytes = 0;               // whole file
  size_t connectivity_bytes = 0;  // the triangles: the connectivity block with its framing (or the hash)
  size_t order_bytes = 0;         // the vertex order block with its framing (0 when reordered or geometry only)
  bool reordered = false;         // the file is numbered in traversal order (EncodeOptions::reorder)
  std::vector<int32_t> new_index;  // reordered: the decoded mesh's number for each input vertex
  // Reordered: input vertices merged into an earlier copy at the same position (weld.h); the decoded mesh
  // has num_vertices - merged_vertices vertices, and new_index maps copies onto one.
  int32_t merged_vertices = 0;
  size_t geometry_bytes = 0;      // header and chunks
  size_t attribute_bytes = 0;     // the attribute sections with their framing
  std::vector<AttributeStats> attributes;  // in the mesh's order
  double rms_rel = 0, linf_rel = 0;  // of the decoded shape against the input
  bool refined = false;              // the file ends with a refinement chunk
  bool levels = false;               // the file is in the level layout (FileLayout)
  double unrefined_rms_rel = 0;      // the shape of the anchor chunks alone
  size_t refinement_bytes = 0;       // the refinement chunk with its framing
  bool detail = false;               // the file ends with a detail chunk
  size_t detail_bytes = 0;           // the detail chunk with its framing
  double detail_step_rel = 0;        // its quantization step over the box diagonal
  double anchor_rms_rel = 0;         // with detail: the anchors' shape alone (what a decoder skipping it shows)
  bool target_met = true;         // false if an error target was out of reach at these bits
  std::vector<GreedyStep> curve;  // after every greedy step
  std::vector<int32_t> chunk_anchors;  // anchors per chunk
  Ordering ordering = Ordering::kAmd;  // the factorizations' ordering (never kAuto)
  Solver solver = Solver::kIterative;  // the reconstruction operator of the file (never kAuto)
  std::vector<Candidate> candidates;   // in the order coded
  double encode_s = 0;
};

}  // namespace gab
