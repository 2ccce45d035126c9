#include "anchor_chunk.h"

#include <algorithm>
#include <cstdlib>
#include <string>

#include "axis_context.h"
#include "gab/codec/byte_io.h"
#include "gab/codec/subset_coder.h"

namespace gab {

namespace {

// Ranks of sorted vertices among those not anchored, and back.
std::vector<uint32_t> ranks_of(const std::vector<int32_t>& vertices, const std::vector<char>& anchored) {
  std::vector<uint32_t> ranks;
  ranks.reserve(vertices.size());
  uint32_t rank = 0;
  size_t i = 0;
  for (int32_t v = 0; v < static_cast<int32_t>(anchored.size()) && i < vertices.size(); ++v) {
    if (anchored[v]) continue;
    if (v == vertices[i]) {
      ranks.push_back(rank);
      ++i;
    }
    ++rank;
  }
  return ranks;
}

}  // namespace

std::vector<uint8_t> AnchorChunkCoder::encode(const std::vector<int32_t>& anchors, const std::vector<char>& anchored,
                                              const std::vector<int32_t>& grid, const double* prediction) {
  uint32_t free_count = 0;
  for (char a : anchored) free_count += a ? 0 : 1;
  RangeEncoder enc;
  encode_subset(&enc, ranks_of(anchors, anchored), free_count);
  const bool flat = !(q_.step > 0);
  const int32_t centre = (q_.max_index + 1) / 2;
  int32_t previous[3] = {centre, centre, centre};  // chunk 0: the previous anchor's position
  int32_t previous_max = 0;
  for (int32_t v : anchors) {
    int32_t r[3] = {0, 0, 0};
    for (int c = 0; c < 3 && !flat; ++c) {
      const int32_t target = grid[3 * static_cast<size_t>(v) + c];
      if (!prediction) {
        models_->initial_.encode(&enc, target - previous[c], c);
        previous[c] = target;
        continue;
      }
      const double s = q_.scaled(prediction[3 * static_cast<size_t>(v) + c], c);
      const bool near = prediction_is_near_tie(s);
      enc.encode(&models_->near_tie_[c], near ? 1 : 0);
      bool up = false;
      const int32_t predicted = round_prediction(s, &up);
      if (near) enc.encode(&models_->round_up_[c], up ? 1 : 0);
      r[c] = target - predicted;
      models_->residual_.encode(&enc, r[c], axis_context(c, r, previous_max, AnchorModels::kBuckets));
    }
    previous_max = max_magnitude(r);
  }
  const std::vector<uint8_t> coded = enc.finish();
  ByteWriter out;
  out.varint(anchors.size());
  out.bytes(coded.data(), coded.size());
  return out.take();
}

Status AnchorChunkCoder::decode(const uint8_t* payload, size_t size, const std::vector<char>& anchored,
                                const double* prediction, int32_t max_anchors, std::vector<int32_t>* anchors,
                                std::vector<int32_t>* grid, int32_t* chunk_count) {
  ByteReader in(payload, size);
  uint64_t count = 0;
  if (!in.varint(&count)) return Status::Error(StatusCode::kParseError, "anchor count is cut short");
  uint32_t free_count = 0;
  for (char a : anchored) free_count += a ? 0 : 1;
  if (count < 1 || count > free_count) {
    return Status::Error(StatusCode::kParseError, "anchor count " + std::to_string(count) + " out of range (" +
                                                      std::to_string(free_count) + " free vertices)");
  }
  *chunk_count = static_cast<int32_t>(count);
  RangeDecoder dec(payload + in.offset(), in.remaining());
  std::vector<uint32_t> ranks;
  if (!decode_subset(&dec, static_cast<uint32_t>(count), free_count, &ranks) || dec.overrun()) {
    return Status::Error(StatusCode::kParseError, "anchor indices are corrupt");
  }
  // Ranks -> vertices, one pass (ranks are strictly increasing).
  anchors->clear();
  anchors->reserve(ranks.size());
  uint32_t rank = 0;
  size_t i = 0;
  for (int32_t v = 0; v < static_cast<int32_t>(anchored.size()) && i < ranks.size(); ++v) {
    if (anchored[v]) continue;
    if (rank == ranks[i]) {
      anchors->push_back(v);
      ++i;
    }
    ++rank;
  }
  if (anchors->size() != ranks.size()) return Status::Error(StatusCode::kParseError, "anchor indices are corrupt");
  if (max_anchors >= 0 && anchors->size() > static_cast<size_t>(max_anchors)) anchors->resize(max_anchors);

  const bool flat = !(q_.step > 0);
  const int32_t centre = (q_.max_index + 1) / 2;
  int32_t previous[3] = {centre, centre, centre};
  grid->assign(anchors->size() * 3, 0);
  int32_t previous_max = 0;
  for (size_t a = 0; a < anchors->size(); ++a) {
    const int32_t v = (*anchors)[a];
    int32_t r[3] = {0, 0, 0};
    for (int c = 0; c < 3 && !flat; ++c) {
      int64_t value = 0;
      if (!prediction) {
        value = int64_t{previous[c]} + models_->initial_.decode(&dec, c);
      } else {
        const double s = q_.scaled(prediction[3 * static_cast<size_t>(v) + c], c);
        const bool near = dec.decode(&models_->near_tie_[c]) != 0;
        const bool up = near && dec.decode(&models_->round_up_[c]) != 0;
        r[c] = models_->residual_.decode(&dec, axis_context(c, r, previous_max, AnchorModels::kBuckets));
        value = int64_t{resolve_prediction(s, near, up)} + r[c];
      }
      if (value < 0 || value > q_.max_index) {
        return Status::Error(StatusCode::kParseError, "anchor " + std::to_string(v) + " lies off the grid");
      }
      (*grid)[3 * a + c] = static_cast<int32_t>(value);
      previous[c] = static_cast<int32_t>(value);
    }
    if (dec.overrun()) return Status::Error(StatusCode::kParseError, "anchor positions are cut short");
    previous_max = max_magnitude(r);
  }
  return Status::Ok();
}

}  // namespace gab
