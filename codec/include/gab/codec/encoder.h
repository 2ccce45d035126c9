// Compression of a mesh to a .gab file (DESIGN.md sections 1 and 5): a
// well-spread initial set of anchors, then greedy batches at the largest
// errors, in a closed loop (the encoder reconstructs from exactly the
// quantized coefficients the decoder will get), coded chunk by chunk.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "gab/mesh/greedy_anchors.h"
#include "gab/mesh/mesh.h"
#include "gab/status.h"

namespace gab {

// How a file arranges its anchor chunks (gab_format.h).
//  * kSelectionOrder: the first layout, chunks in selection order, each
//    coding its anchors as a subset of the vertices still free.
//  * kLevels: flag bit 2: chunk 0 codes the whole anchor set once and the
//    decoder orders it into levels (anchor_levels.h).
//  * kSmaller: both, keeping the levels unless the first codes smaller.
// At 1e-3 on the shared meshes the levels alone (growth 2) took 4-10% off
// the geometry (bits per vertex: bunny-small 12.27 -> 11.72, camel-head
// 1.651 -> 1.591, horse 1.596 -> 1.437, max-planck 4.05 -> 3.66, nefertiti
// 3.46 -> 3.14; igea the same: one level after the spread set, no order to
// save); small smooth meshes (a 40 x 20 torus) can code 1-3% smaller in
// selection order, whose greedy batches predict best there. The level
// layout costs the encoder a decoder's work on top of the greedy loop.
enum class FileLayout { kSmaller, kLevels, kSelectionOrder };

struct EncodeOptions {
  // Stopping rules; at least one must be set. The loop also stops when every
  // vertex is an anchor (then the error is the quantization's).
  int32_t max_anchors = 0;      // anchors in the file (0: no count limit)
  double target_rms_rel = 0;    // relative vertex RMS (over the bounding-box diagonal)
  double target_linf_rel = 0;   // relative max vertex error
  // q: bits per coordinate (kGabMinBits..kGabMaxBits); 0: chosen from the
  // error target (default_bits), 12 (the paper's) for an anchor count alone.
  int bits = 0;
  double weight = 100;          // anchor weight w of the relaxed basis
  bool geometry_only = false;   // store a connectivity hash instead of the triangles
  // Spread set size (at least one per component); 0: default_initial_anchors,
  // at most half of max_anchors.
  int32_t initial_anchors = 0;
  // Greedy batch: up to ceil(batch_fraction * anchors so far) local maxima
  // of the error per step (0: one anchor per step, the paper's rule;
  // negative: default_batch_fraction of the factorization's cost). Near an
  // RMS target the batch shrinks to the anchors the error curve's recent
  // slope says are still needed, so the file does not overshoot.
  double batch_fraction = -1;
  // A chunk closes when the anchor count has grown by this factor since it
  // opened: fewer chunks decode faster (each costs the decoder a solve and
  // an update or refactorization), more predict better. Non-positive:
  // default_chunk_growth of the factorization's cost.
  double chunk_growth = -1;
  // The file's layout (gab_format.h): see FileLayout.
  FileLayout layout = FileLayout::kSmaller;
  // Least-squares refinement (Sorkine et al. 2005, sec. IV; DESIGN.md
  // section 5): a last chunk moving every anchor's coefficient from its
  // quantized position towards the coefficients whose reconstruction is
  // closest to the shape. With an anchor count the refined shape is 20-27%
  // closer (q = 12: camel-head 466 anchors 2.05e-3 -> 1.64e-3 RMS, igea
  // 13,434 7.16e-4 -> 5.75e-4) for 38-44% more bytes; at equal bytes more
  // anchors do as well (camel-head 650 plain anchors: 1.34e-3 in fewer
  // bytes), so it is not the default. With an RMS target the greedy loop stops as soon as the
  // refined shape meets it; at q = 9 that saved 4% of the bits on horse but
  // cost 6% on camel-head and 3% on feline (the grid rounds most of the gain
  // away; the corrections cost ~1.4 bits per coordinate). Kept only where it
  // lowers the RMS without breaking an L-inf target.
  bool refine = false;
  // Conjugate-gradient iterations of the refinement (each two solves):
  // 4 reach within 1% of the converged error on horse (2: +3.6%).
  int refine_iterations = 4;
  // Threads for the factorizations. The file is byte-identical for any
  // count (every factor is; see factor_schedule.h).
  int32_t threads = 1;
  // Called after every reconstruction (anchors so far, relative RMS).
  std::function<void(int32_t, double)> progress;
};

struct EncodeStats {
  int32_t num_vertices = 0, num_triangles = 0;
  int32_t anchors = 0, chunks = 0;
  int bits = 0;                   // q used
  size_t bytes = 0;               // whole file
  size_t connectivity_bytes = 0;  // the connectivity block with its framing (or the hash)
  size_t geometry_bytes = 0;      // everything else: header and anchor chunks
  double rms_rel = 0, linf_rel = 0;  // of the decoded shape against the input
  bool refined = false;              // the file ends with a refinement chunk
  bool levels = false;               // the file is in the level layout (FileLayout)
  double unrefined_rms_rel = 0;      // the shape of the anchor chunks alone
  size_t refinement_bytes = 0;       // the refinement chunk with its framing
  bool target_met = true;         // false if an error target was out of reach at these bits
  std::vector<GreedyStep> curve;  // after every greedy step
  std::vector<int32_t> chunk_anchors;  // anchors per chunk
  double encode_s = 0;
};

// The q the encoder picks for an error target on a mesh whose longest box
// side over its diagonal is `extent_over_diagonal`: the smallest q whose
// grid alone errs (RMS s/2, max s sqrt(3)/2 for step s) by at most 0.8 of
// an RMS target or 0.5 of an L-inf one; 12 (the paper's) without a target.
// Measured on camel-head and horse, the best q for RMS targets 3e-3, 1e-3
// and 3e-4 was 8, 9 and 11: what this rule gives; q = 12 costs 15-30% more.
int default_bits(double extent_over_diagonal, double target_rms_rel, double target_linf_rel);

// The farthest-point spread set the greedy loop starts from: n / 1000 up to
// 50,000 vertices, growing as n^4 / 1.25e17 beyond (at most n / 50), so
// large meshes take fewer, costlier greedy steps. igea at 1e-3 (median of
// runs on this machine): 2,606 anchors, encode 3.2-3.5 s at 1.27 bits per
// vertex, against 969 anchors: 4.9-5.9 s at 1.17 (each greedy step there
// is a refactorization). Below 50,000 vertices a larger set costs rate
// (n / 100 on camel-head and feline: +5%).
int32_t default_initial_anchors(int32_t n);

// The greedy batch fraction for a system whose factorization costs `flops`:
// 5% (what the reference quality needs; measured 1.78 bits per vertex on
// horse at 1e-3 against 1.86 / 1.96 / 2.13 at 10 / 20 / 35%) while a
// refactorization is cheap, growing as (flops / 2e9)^0.8 up to 12% so that
// large meshes need a bounded number of steps. igea sits at the cap; at 1e-3
// on two threads (tree-parallel factorization) 12% gave 1.058 bits per
// vertex in 3.0 s, against 1.084 in 2.6-3.1 s at 15%, 1.113 in 2.4-2.5 s at
// 20% (one thread: 3.8-4.4 s), 1.16 at 33%; at 13,434 anchors and q = 12,
// 12% / 15% / 20% reach RMS 6.91e-4 / 6.98e-4 / 7.16e-4 (reference 7.02e-4).
double default_batch_fraction(double flops);

// Chunk growth for a system whose factorization costs `flops`: 4 while a
// refactorization is cheap (measured at 1e-3 on camel-head and horse:
// growth 2, 3, 4, 8 gave 1.71/1.65/1.69/1.76 and 1.78/1.76/1.74/1.76 bits
// per vertex, and fewer chunks decode faster), growing as (flops / 2e9)^0.6
// beyond, since each chunk costs the decoder a refactorization (igea: ~17,
// i.e. two chunks: 1.17 bits per vertex and a 1.4 s decode against 1.20 and
// 1.8 s with growth 4).
double default_chunk_growth(double flops);

// Level growth (FileLayout::kLevels) for a system whose factorization
// costs `flops`: 2 while a refactorization is cheap (measured at 1e-3
// against 1.5, 2.5, 3 and 4: best or within 0.3% on the shared meshes but
// bunny-small, 0.4% better at 3; 1.5 adds levels for nothing, 4 costs
// 1-3%), growing as (flops / 2e9)^0.6 beyond like default_chunk_growth
// (igea: ~8.4, one level after the spread set).
double default_level_growth(double flops);

// Compresses `mesh` (valid per validate_mesh) into `file`.
Status encode_mesh(const Mesh& mesh, const EncodeOptions& options, std::vector<uint8_t>* file, EncodeStats* stats);

}  // namespace gab
