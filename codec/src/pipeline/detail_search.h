// The encoder's choice of the detail chunk (detail/detail_chunk.h) over a
// given smooth shape: the largest step whose decoded shape meets the error
// targets, and the blend (detail_predictor.h) that codes smallest at it.
// Every trial is a real encoding with the decoder's arithmetic, so the
// errors reported are exactly the decoded file's. Internal to the codec.
#pragma once

#include <cstdint>
#include <vector>

#include "detail/detail_chunk.h"
#include "gab/mesh/mesh.h"
#include "gab/status.h"

namespace gab {

struct DetailChoice {
  std::vector<uint8_t> chunk;  // the payload
  DetailParams params;
  double rms_rel = 0, linf_rel = 0;  // of the decoded shape against the mesh
  bool met = false;                  // the targets hold (else: the finest step tried)
  int trials = 0;
};

// The search in two stages, `smooth` the anchors' reconstruction as the
// decoder computes it, `scale` 1 / the box diagonal, at least one target
// positive; each trial costs O(n) predictions and codings (igea: ~70 ms).
// fit_detail: the default blend at the largest step meeting the targets
// (2-3 trials; the finest step tried when none does): what the encoder
// ranks its candidates by.
Status fit_detail(const DetailTopology& topo, const DetailFrame& frame, const std::vector<double>& smooth,
                  const Mesh& mesh, double scale, double target_rms_rel, double target_linf_rel, DetailChoice* out);
// improve_detail: from fit_detail's *choice (same arguments), the blend and
// the rate-distortion rounding that code smallest at the targets (about 17
// trials); *choice unchanged when the fit missed the targets or nothing
// codes smaller.
Status improve_detail(const DetailTopology& topo, const DetailFrame& frame, const std::vector<double>& smooth,
                      const Mesh& mesh, double scale, double target_rms_rel, double target_linf_rel,
                      DetailChoice* choice);

}  // namespace gab
