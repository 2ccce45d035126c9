#include "anchors/anchor_chunk.h"

#include <algorithm>
#include <string>

#include "entropy/axis_context.h"
#include "entropy/subset_coder.h"

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

uint32_t free_count(const std::vector<char>& anchored) {
  uint32_t count = 0;
  for (char a : anchored) count += a ? 0 : 1;
  return count;
}

// A sorted subset of the vertices not anchored, as ranks among them.
void encode_free_subset(RangeEncoder* enc, const std::vector<int32_t>& sorted, const std::vector<char>& anchored) {
  encode_subset(enc, ranks_of(sorted, anchored), free_count(anchored));
}

// `count` (<= the free vertices: the caller's check) vertices back from
// their ranks. One pass: ranks are strictly increasing.
Status decode_free_subset(RangeDecoder* dec, uint32_t count, const std::vector<char>& anchored,
                          std::vector<int32_t>* vertices) {
  std::vector<uint32_t> ranks;
  if (!decode_subset(dec, count, free_count(anchored), &ranks) || dec->overrun()) {
    return Status::Error(StatusCode::kParseError, "anchor indices are corrupt");
  }
  vertices->clear();
  vertices->reserve(ranks.size());
  uint32_t rank = 0;
  size_t i = 0;
  for (int32_t v = 0; v < static_cast<int32_t>(anchored.size()) && i < ranks.size(); ++v) {
    if (anchored[v]) continue;
    if (rank == ranks[i]) {
      vertices->push_back(v);
      ++i;
    }
    ++rank;
  }
  if (vertices->size() != ranks.size()) return Status::Error(StatusCode::kParseError, "anchor indices are corrupt");
  return Status::Ok();
}

}  // namespace

void AnchorChunkCoder::predict(int32_t v, const double* prediction, const EdgeGraph* graph,
                               const std::vector<int32_t>& coded, double s[3]) const {
  for (int c = 0; c < 3; ++c) s[c] = q_.scaled(prediction[3 * static_cast<size_t>(v) + c], c);
  if (!graph) return;
  double error[3] = {0, 0, 0};
  int known = 0;
  for (int32_t p = graph->offsets[v]; p < graph->offsets[v + 1]; ++p) {
    const int32_t u = graph->neighbors[p];
    const int32_t slot = slot_[u];
    if (slot < 0) continue;
    for (int c = 0; c < 3; ++c) {
      error[c] += coded[3 * static_cast<size_t>(slot) + c] - q_.scaled(prediction[3 * static_cast<size_t>(u) + c], c);
    }
    ++known;
  }
  if (known == 0) return;
  for (int c = 0; c < 3; ++c) s[c] += kLocalErrorShare * error[c] / known;
}

void AnchorChunkCoder::begin_local(const EdgeGraph* graph) {
  if (graph && slot_.size() != static_cast<size_t>(graph->num_vertices())) slot_.assign(graph->num_vertices(), -1);
}

void AnchorChunkCoder::end_local(const EdgeGraph* graph, const std::vector<int32_t>& anchors) {
  if (!graph) return;
  for (int32_t v : anchors) slot_[v] = -1;
}

void AnchorChunkCoder::encode_positions(RangeEncoder* enc, const std::vector<int32_t>& anchors,
                                        const std::vector<int32_t>& grid, const double* prediction,
                                        const EdgeGraph* graph) {
  begin_local(graph);
  std::vector<int32_t> coded(graph ? anchors.size() * 3 : 0);  // what the decoder has so far, as it will
  const bool flat = !(q_.step > 0);
  const int32_t centre = (q_.max_index + 1) / 2;
  int32_t previous[3] = {centre, centre, centre};  // without a prediction: the previous anchor's position
  int32_t previous_max = 0;
  for (size_t a = 0; a < anchors.size(); ++a) {
    const int32_t v = anchors[a];
    int32_t r[3] = {0, 0, 0};
    double scaled[3] = {0, 0, 0};
    if (prediction && !flat) predict(v, prediction, graph, coded, scaled);
    for (int c = 0; c < 3 && !flat; ++c) {
      const int32_t target = grid[3 * static_cast<size_t>(v) + c];
      if (!prediction) {
        models_->initial_.encode(enc, target - previous[c], c);
        previous[c] = target;
        continue;
      }
      const double s = scaled[c];
      const bool near = prediction_is_near_tie(s);
      enc->encode(&models_->near_tie_[c], near ? 1 : 0);
      bool up = false;
      const int32_t predicted = static_cast<int32_t>(round_prediction(s, &up));  // s lies on the grid
      if (near) enc->encode(&models_->round_up_[c], up ? 1 : 0);
      r[c] = target - predicted;
      models_->residual_.encode(enc, r[c], axis_context(c, r, previous_max, AnchorModels::kBuckets));
      if (graph) coded[3 * a + c] = target;
    }
    previous_max = max_magnitude(r);
    if (graph) slot_[v] = static_cast<int32_t>(a);
  }
  end_local(graph, anchors);
}

Status AnchorChunkCoder::decode_positions(RangeDecoder* dec, const std::vector<int32_t>& anchors,
                                          const double* prediction, std::vector<int32_t>* grid,
                                          const EdgeGraph* graph) {
  begin_local(graph);
  const bool flat = !(q_.step > 0);
  const int32_t centre = (q_.max_index + 1) / 2;
  int32_t previous[3] = {centre, centre, centre};
  grid->assign(anchors.size() * 3, 0);
  int32_t previous_max = 0;
  Status status = Status::Ok();
  for (size_t a = 0; a < anchors.size(); ++a) {
    const int32_t v = anchors[a];
    int32_t r[3] = {0, 0, 0};
    double scaled[3] = {0, 0, 0};
    if (prediction && !flat) predict(v, prediction, graph, *grid, scaled);
    for (int c = 0; c < 3 && !flat; ++c) {
      int64_t value = 0;
      if (!prediction) {
        value = int64_t{previous[c]} + models_->initial_.decode(dec, c);
      } else {
        const double s = scaled[c];
        const bool near = dec->decode(&models_->near_tie_[c]) != 0;
        const bool up = near && dec->decode(&models_->round_up_[c]) != 0;
        r[c] = models_->residual_.decode(dec, axis_context(c, r, previous_max, AnchorModels::kBuckets));
        value = resolve_prediction(s, near, up) + r[c];
      }
      if (value < 0 || value > q_.max_index) {
        status = Status::Error(StatusCode::kParseError, "anchor " + std::to_string(v) + " lies off the grid");
        break;
      }
      (*grid)[3 * a + c] = static_cast<int32_t>(value);
      previous[c] = static_cast<int32_t>(value);
    }
    // (A garbage residual may be INT32_MIN: stop before taking magnitudes.)
    if (!status.ok()) break;
    if (dec->overrun()) {
      status = Status::Error(StatusCode::kParseError, "anchor positions are cut short");
      break;
    }
    previous_max = max_magnitude(r);
    if (graph) slot_[v] = static_cast<int32_t>(a);
  }
  end_local(graph, anchors);
  return status;
}

std::vector<uint8_t> AnchorChunkCoder::encode(const std::vector<int32_t>& anchors, const std::vector<char>& anchored,
                                              const std::vector<int32_t>& grid, const double* prediction) {
  RangeEncoder enc;
  encode_free_subset(&enc, anchors, anchored);
  encode_positions(&enc, anchors, grid, prediction);
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
  GAB_RETURN_IF_ERROR(read_chunk_anchor_count(&in, free_count(anchored), &count));
  *chunk_count = static_cast<int32_t>(count);
  RangeDecoder dec(payload + in.offset(), in.remaining());
  GAB_RETURN_IF_ERROR(decode_free_subset(&dec, static_cast<uint32_t>(count), anchored, anchors));
  if (max_anchors >= 0 && anchors->size() > static_cast<size_t>(max_anchors)) anchors->resize(max_anchors);
  return decode_positions(&dec, *anchors, prediction, grid);
}

std::vector<uint8_t> AnchorChunkCoder::encode_level_head(const LevelPlan& plan, const std::vector<int32_t>& spread,
                                                         const std::vector<int32_t>& rest,
                                                         const std::vector<int32_t>& grid) {
  std::vector<char> anchored(grid.size() / 3, 0);
  RangeEncoder enc;
  encode_free_subset(&enc, spread, anchored);
  encode_positions(&enc, spread, grid, nullptr);
  for (int32_t v : spread) anchored[v] = 1;
  if (!rest.empty()) encode_free_subset(&enc, rest, anchored);
  const std::vector<uint8_t> coded = enc.finish();
  ByteWriter out;
  out.varint(static_cast<uint64_t>(plan.spread));
  out.varint(static_cast<uint64_t>(plan.rest));
  out.varint(plan.growth16);
  out.bytes(coded.data(), coded.size());
  return out.take();
}

Status AnchorChunkCoder::decode_level_head(const uint8_t* stream, size_t size, int32_t n, const LevelPlan& plan,
                                           std::vector<int32_t>* spread, std::vector<int32_t>* spread_grid,
                                           std::vector<int32_t>* rest) {
  // parse_level_plan checked spread >= 1 and spread + rest <= anchors <= n.
  std::vector<char> anchored(n, 0);
  RangeDecoder dec(stream, size);
  GAB_RETURN_IF_ERROR(decode_free_subset(&dec, static_cast<uint32_t>(plan.spread), anchored, spread));
  GAB_RETURN_IF_ERROR(decode_positions(&dec, *spread, nullptr, spread_grid));
  for (int32_t v : *spread) anchored[v] = 1;
  rest->clear();
  if (plan.rest > 0) GAB_RETURN_IF_ERROR(decode_free_subset(&dec, static_cast<uint32_t>(plan.rest), anchored, rest));
  return Status::Ok();
}

std::vector<uint8_t> AnchorChunkCoder::encode_level(const std::vector<int32_t>& anchors,
                                                    const std::vector<int32_t>& grid, const double* prediction,
                                                    const EdgeGraph& graph) {
  RangeEncoder enc;
  encode_positions(&enc, anchors, grid, prediction, &graph);
  return enc.finish();
}

Status AnchorChunkCoder::decode_level(const uint8_t* payload, size_t size, const std::vector<int32_t>& anchors,
                                      const double* prediction, const EdgeGraph& graph, std::vector<int32_t>* grid) {
  RangeDecoder dec(payload, size);
  return decode_positions(&dec, anchors, prediction, grid, &graph);
}

Status read_chunk_anchor_count(ByteReader* in, uint64_t limit, uint64_t* count) {
  if (!in->varint(count)) return Status::Error(StatusCode::kParseError, "anchor count is cut short");
  if (*count < 1 || *count > limit) {
    return Status::Error(StatusCode::kParseError, "anchor count " + std::to_string(*count) + " out of range (" +
                                                      std::to_string(limit) + " free vertices)");
  }
  return Status::Ok();
}

Status parse_level_plan(const uint8_t* payload, size_t size, int32_t anchors, int32_t anchor_chunks, LevelPlan* plan,
                        size_t* stream_offset) {
  auto bad = [](const std::string& what) { return Status::Error(StatusCode::kParseError, what); };
  ByteReader in(payload, size);
  uint64_t spread = 0, rest = 0, growth16 = 0;
  if (!in.varint(&spread) || !in.varint(&rest) || !in.varint(&growth16)) return bad("level plan is cut short");
  if (spread < 1 || spread > static_cast<uint64_t>(anchors) || rest != static_cast<uint64_t>(anchors) - spread) {
    return bad("level plan: " + std::to_string(spread) + " + " + std::to_string(rest) +
               " anchors do not add up to the header's " + std::to_string(anchors));
  }
  if (growth16 < kMinLevelGrowth16 || growth16 > kMaxLevelGrowth16) {
    return bad("level plan: growth " + std::to_string(growth16) + "/16 out of range");
  }
  plan->spread = static_cast<int32_t>(spread);
  plan->rest = static_cast<int32_t>(rest);
  plan->growth16 = static_cast<uint32_t>(growth16);
  // At most a few hundred levels whatever the plan (growth >= 17/16).
  const size_t levels = plan->level_sizes().size();
  if (levels + 1 != static_cast<size_t>(anchor_chunks)) {
    return bad("level plan makes " + std::to_string(levels) + " levels; the header declares " +
               std::to_string(anchor_chunks - 1));
  }
  *stream_offset = in.offset();
  return Status::Ok();
}

}  // namespace gab
