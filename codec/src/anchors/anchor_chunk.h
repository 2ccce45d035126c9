// One chunk of anchors (gab/codec/gab_format.h), coded and decoded by the same
// rules on both sides: the anchors as a sorted subset of the vertices not
// anchored before the chunk (about log2 C(free, b) bits), then per anchor
// and axis the quantized position as a residual from the rounded prediction
// (the reconstruction from the earlier chunks; in chunk 0, which has none,
// the previous anchor's position: vertex order tends to follow the surface,
// so this saved 13% of chunk 0 on igea against the grid's centre).
//
// The level layout (anchor_levels.h) codes the same things in another
// arrangement: its chunk 0 holds the spread set (subset and positions as
// above) and the subset of all later anchors; each later chunk holds only
// one level's positions, predicted by the reconstruction from the chunks
// before it plus a local correction: kLocalErrorShare times the mean of
// the reconstruction's error, q(u) - recon(u), over the anchor's neighbours
// u already decoded in the same level (vertex order). The reconstruction's
// error is only weakly correlated from a vertex to the next (0.25 between
// neighbouring anchors of bunny-small's last chunk), so a share, not all of
// it: 0.3 and 0.4 saved 1.4% of the geometry on bunny-small, 0.1-0.3% on
// the other shared meshes (0.2: 1.0% on bunny-small; 0.5: 1.3%); a
// parallelogram or a neighbour average of decoded positions, alone or
// mixed in at 0.3-0.5, cost 15-28% there (the surface's detail is at the
// edge scale). Statistics carry over from chunk to chunk in both layouts.
// Internal to the codec.
#pragma once

#include <cstdint>
#include <vector>

#include "anchors/anchor_levels.h"
#include "anchors/quantizer.h"
#include "container/byte_io.h"
#include "entropy/int_coder.h"
#include "entropy/range_coder.h"
#include "gab/status.h"

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

// The share of the neighbours' mean reconstruction error added to a level
// anchor's prediction (see above).
constexpr double kLocalErrorShare = 0.3;

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

  // Level layout, chunk 0: the plan (three varints: spread, rest,
  // growth16), then one range-coded stream: `spread` as a subset of the n
  // vertices, their positions (chunk 0's rule), `rest` as a subset of the
  // others. Both sorted and disjoint.
  std::vector<uint8_t> encode_level_head(const LevelPlan& plan, const std::vector<int32_t>& spread,
                                         const std::vector<int32_t>& rest, const std::vector<int32_t>& grid);
  // Decodes what follows the plan (parse_level_plan gives it and the
  // stream's offset): the spread set, its grid indices (3 per anchor) and
  // the rest, for a mesh of n vertices.
  Status decode_level_head(const uint8_t* stream, size_t size, int32_t n, const LevelPlan& plan,
                           std::vector<int32_t>* spread, std::vector<int32_t>* spread_grid,
                           std::vector<int32_t>* rest);

  // Level layout, a later chunk: the positions of one level's anchors
  // (sorted), residuals from the rounded `prediction` (3 per vertex).
  std::vector<uint8_t> encode_level(const std::vector<int32_t>& anchors, const std::vector<int32_t>& grid,
                                    const double* prediction, const EdgeGraph& graph);
  // Decodes the positions of `anchors`, the level's first anchors in vertex
  // order (a level of detail may stop inside a level), into *grid.
  Status decode_level(const uint8_t* payload, size_t size, const std::vector<int32_t>& anchors,
                      const double* prediction, const EdgeGraph& graph, std::vector<int32_t>* grid);

 private:
  // Per anchor and axis: with a prediction, the near-tie flag (and
  // direction) and the residual; without, the step from the previous
  // anchor (chunk 0).
  void encode_positions(RangeEncoder* enc, const std::vector<int32_t>& anchors, const std::vector<int32_t>& grid,
                        const double* prediction, const EdgeGraph* graph = nullptr);
  Status decode_positions(RangeDecoder* dec, const std::vector<int32_t>& anchors, const double* prediction,
                          std::vector<int32_t>* grid, const EdgeGraph* graph = nullptr);
  // The scaled prediction of anchor v (3 axes): the reconstruction's,
  // plus with `graph` the local correction from the chunk's anchors coded
  // so far (slot_ >= 0; their grid indices in `coded`, 3 per slot).
  void predict(int32_t v, const double* prediction, const EdgeGraph* graph, const std::vector<int32_t>& coded,
               double s[3]) const;
  // slot_ sized for the graph's vertices before a chunk; its anchors reset after.
  void begin_local(const EdgeGraph* graph);
  void end_local(const EdgeGraph* graph, const std::vector<int32_t>& anchors);
  std::vector<int32_t> slot_;  // per vertex: its index in the chunk being coded once coded, else -1 (O(n) once)

  const Quantizer& q_;
  AnchorModels* models_;
};

// The head of a selection-layout chunk: its anchor count, which must lie in
// [1, limit] (decoding: the vertices still free; read_gab_info: the anchors
// the header declares). The one rule both readers apply; kParseError
// otherwise. O(1).
Status read_chunk_anchor_count(ByteReader* in, uint64_t limit, uint64_t* count);

// Reads the plan at the head of a level-layout chunk 0 and checks it against
// the header: `anchors` in the file and `anchor_chunks` (chunk 0 and one per
// level). *stream_offset: where the range-coded stream starts.
Status parse_level_plan(const uint8_t* payload, size_t size, int32_t anchors, int32_t anchor_chunks, LevelPlan* plan,
                        size_t* stream_offset);

}  // namespace gab
