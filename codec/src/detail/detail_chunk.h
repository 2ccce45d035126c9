// The detail chunk (gab_format.h, flag "detail"): after the anchor chunks
// (and the refinement), every vertex's position coded as a quantized
// residual from a prediction (detail_predictor.h), in the walk's order
// (detail_topology.h). Where the anchors' smooth reconstruction leaves the
// shape off by more than the target, this is what brings it there: its
// error is the residuals' quantization alone, at most step * sqrt(3) / 2 per
// vertex, about step / 2 in RMS.
//
// Payload: u8 version (1); f64 step, the residuals' quantization step
// (positive, between kMinDetailStep and kMaxDetailStep times the header's
// grid extent); u8 alpha_n, u8 alpha_t (0..16: the blend, sixteenths); then
// one range-coded stream:
//  1. the smooth shape on a lattice kSmoothDivisions times finer than the
//     step: the reconstruction x~ of all anchors scaled by
//     kSmoothDivisions / step from the header's box minimum and rounded;
//     per vertex and axis a near-tie flag (and the direction when set), as
//     the anchor chunks do (anchors/quantizer.h), so that both sides round
//     alike although their x~ may differ in the last bits (another SIMD
//     level, another update path). Rounded, x~ is the same on both sides,
//     and every prediction built on it too;
//  2. per vertex in the walk's order, three signed residuals (normal, t1,
//     t2 of the prediction's frame), contexts by frame axis and by the mean
//     magnitude of that axis's residuals at the vertex's decoded
//     neighbours.
// Internal to the codec.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "detail/detail_topology.h"
#include "gab/codec/gab_format.h"
#include "gab/status.h"

namespace gab {

constexpr uint8_t kDetailVersion = 1;
// The detail step's range, relative to the header's grid extent (the grid
// step times 2^q - 1): below the minimum the lattice would need more than 53
// bits, and the near-tie guard would come close to the solvers' rounding
// differences; above the maximum the layer would be pointless.
constexpr double kMinDetailStep = 1.0 / (int64_t{1} << 24);
constexpr double kMaxDetailStep = 4.0;
// The smooth shape's lattice: fine enough that its rounding (s / 8 / sqrt(12)
// per axis) adds nothing measurable to the predictions' errors (step s on
// the lattice itself cost igea 3% at 1e-4).
constexpr double kSmoothDivisions = 8;
// The near-tie guard of its rounding, in steps of that lattice: the larger
// of kDetailGuard and kDetailGuardFloor times the header's grid extent.
// Both stay far above the solvers' rounding differences (about 1e-14 of the
// coordinates): s / 65536 is 3e-9 of the diagonal at 1e-4, and the floor,
// 2^-30 of the extent, takes over only for steps below about 2^-14 of it. A
// near-tie flag costs about 0.0035 bits per coordinate (a guard of 1/2048:
// 0.011, 100 bytes more on bunny at 3e-5).
constexpr double kDetailGuard = 1.0 / 8192;
constexpr double kDetailGuardFloor = 1.0 / (int64_t{1} << 30);

struct DetailParams {
  double step = 0;
  int alpha_normal16 = 4;
  int alpha_tangent16 = 0;
  // The encoder's alone (not in the file): a residual is rounded one step
  // towards zero when that lowers (error / step)^2 + rate_weight * bits, bits
  // from a gamma-code estimate. A rate-distortion trade the step search then
  // pays for with a finer step; 0: plain rounding.
  double rate_weight = 0;
};

// Where the lattice sits: the header's box minimum and grid extent.
struct DetailFrame {
  double origin[3] = {0, 0, 0};
  double extent = 0;
};

// The header's: its box minimum, and its grid step times 2^q - 1. O(1).
DetailFrame detail_frame_of(const GabHeader& header);

// Work space an encoder may keep between chunks over the same topology,
// frame and smooth shape (a search codes many): the smooth shape's lattice,
// normals and near ties for the last step, and per-chunk buffers.
struct DetailScratch {
  double step = 0;
  std::vector<double> lattice, normals;
  std::vector<uint8_t> ties;  // per coordinate: 0 none, 1 a near tie rounded down, 2 rounded up
  std::vector<int32_t> magnitude;
};

// The chunk's payload for the input positions `target` (3 per vertex) over
// the anchors' reconstruction `smooth` (3 per vertex); *decoded receives the
// positions a decoder will output. The params must be valid (step in range
// for `frame`, alphas in 0..16). `scratch` (optional) must only ever see the
// same topo, frame and smooth. O(vertices + the walk's lists).
std::vector<uint8_t> encode_detail_chunk(const DetailTopology& topo, const DetailFrame& frame,
                                         const std::vector<double>& smooth, const std::vector<double>& target,
                                         const DetailParams& params, std::vector<double>* decoded,
                                         DetailScratch* scratch = nullptr);

// The decoded positions (3 per vertex) from a payload and the decoder's own
// reconstruction `smooth`. kUnsupported for a newer version, kParseError for
// anything inconsistent.
Status decode_detail_chunk(const uint8_t* payload, size_t size, const DetailTopology& topo, const DetailFrame& frame,
                           const std::vector<double>& smooth, std::vector<double>* decoded);

// Reads the payload's head (version, step, blend) and checks it against
// `frame`: the rule the decoder and read_gab_info share. O(1).
Status read_detail_head(const uint8_t* payload, size_t size, const DetailFrame& frame, DetailParams* params,
                        size_t* stream_offset);

}  // namespace gab
