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
#include "gab/sparse/status.h"

namespace gab {

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
  int32_t initial_anchors = 0;  // spread set size; 0: n / 1000 (at least one per component)
  // Greedy batch: up to ceil(batch_fraction * anchors so far) local maxima
  // of the error per step (0: one anchor per step, the paper's rule). Near
  // an RMS target the batch shrinks to the anchors the error curve's recent
  // slope says are still needed, so the file does not overshoot.
  double batch_fraction = 0.05;
  // A chunk closes when the anchor count has grown by this factor since it
  // opened: fewer chunks decode faster, more predict better.
  double chunk_growth = 2.0;
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
  bool target_met = true;         // false if an error target was out of reach at these bits
  std::vector<GreedyStep> curve;  // after every greedy step
  std::vector<int32_t> chunk_anchors;  // anchors per chunk
  double encode_s = 0;
};

// The q the encoder picks for an error target on a mesh whose longest box
// side over its diagonal is `extent_over_diagonal`: the smallest q whose
// grid alone errs (RMS s/2, max s sqrt(3)/2 for step s) by at most 0.65 of
// an RMS target or 0.5 of an L-inf one. Measured on the shared meshes at
// 1e-3: q = 9 or 10 beats 12 by 15-30% in rate at the same error.
int default_bits(double extent_over_diagonal, double target_rms_rel, double target_linf_rel);

// Compresses `mesh` (valid per validate_mesh) into `file`.
Status encode_mesh(const Mesh& mesh, const EncodeOptions& options, std::vector<uint8_t>* file, EncodeStats* stats);

}  // namespace gab
