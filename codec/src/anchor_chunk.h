// One chunk of anchors (DESIGN.md section 5), coded and decoded by the same
// rules on both sides: the anchors as a sorted subset of the vertices not
// anchored before the chunk (about log2 C(free, b) bits), then per anchor
// and axis the quantized position as a residual from the rounded prediction
// (the reconstruction from the earlier chunks; in chunk 0, which has none,
// the previous anchor's position: vertex order tends to follow the surface,
// so this saved 13% of chunk 0 on igea against the grid's centre).
// Internal to the codec.
#pragma once

#include <cstdint>
#include <vector>

#include "gab/codec/int_coder.h"
#include "gab/codec/quantizer.h"
#include "gab/codec/range_coder.h"
#include "gab/sparse/status.h"

namespace gab {

// Adaptive statistics both sides carry from chunk to chunk.
class AnchorModels {
 public:
  // Residual contexts per axis: the bit length (capped) of the residuals
  // just coded, so the model follows the error level as it falls.
  static constexpr int kBuckets = 8;
  // Residual statistics drift as the error falls: fast adaptation (shift
  // 4; 4.5% smaller than 5 on camel-head). The near-tie flag is rare
  // (about 2 kPredictionGuard) and stationary: it starts at its floor
  // probability with a long memory, costing ~0.001 bit per coordinate.
  AnchorModels() : initial_(3), residual_(3 * kBuckets, 4) {
    for (int c = 0; c < 3; ++c) {
      near_tie_[c] = BitModel(8);
      near_tie_[c].p0 = BitModel::kMax;
    }
  }

 private:
  friend class AnchorChunkCoder;
  SIntCoder initial_;
  SIntCoder residual_;
  BitModel near_tie_[3];
  BitModel round_up_[3];
};

class AnchorChunkCoder {
 public:
  // `quantizer` and `models` must outlive the coder.
  AnchorChunkCoder(const Quantizer& quantizer, AnchorModels* models) : q_(quantizer), models_(models) {}

  // The chunk's payload. `anchors`: sorted, distinct, none with
  // anchored[v] != 0; `grid`: quantized positions of all vertices (3 per
  // vertex); `prediction`: 3 per vertex, or null for chunk 0.
  std::vector<uint8_t> encode(const std::vector<int32_t>& anchors, const std::vector<char>& anchored,
                              const std::vector<int32_t>& grid, const double* prediction);

  // Decodes a payload: at most `max_anchors` of its anchors (all if
  // negative; a prefix in vertex order), their grid indices (3 per anchor)
  // in *grid; *count: the anchors the chunk holds. kParseError on anything
  // inconsistent.
  Status decode(const uint8_t* payload, size_t size, const std::vector<char>& anchored, const double* prediction,
                int32_t max_anchors, std::vector<int32_t>* anchors, std::vector<int32_t>* grid, int32_t* count);

 private:
  const Quantizer& q_;
  AnchorModels* models_;
};

}  // namespace gab
