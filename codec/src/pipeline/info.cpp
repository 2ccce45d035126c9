// read_gab_info: the header and every frame, checked as the decoder checks
// them (the same readers), decoding no geometry.
#include <string>

#include "anchors/anchor_chunk.h"
#include "anchors/anchor_levels.h"
#include "anchors/refinement_chunk.h"
#include "attributes/attribute_section.h"
#include "connectivity/connectivity_section.h"
#include "container/framing.h"
#include "container/gab_header.h"
#include "container/trailing_sections.h"
#include "detail/detail_chunk.h"
#include "gab/codec/decoder.h"
#include "pipeline/ordering_choice.h"
#include "reconstruction/iterative_tuning.h"

namespace gab {

namespace {

Status corrupt(const std::string& what) { return Status::Error(StatusCode::kParseError, what); }

}  // namespace

Status read_gab_info(const uint8_t* data, size_t size, GabFileInfo* info) {
  *info = GabFileInfo();
  ByteReader in(data, size);
  GabHeader header;
  GAB_RETURN_IF_ERROR(read_gab_header(&in, size, &header));
  info->version = header.version;
  info->num_vertices = header.num_vertices;
  info->num_triangles = header.num_triangles;
  info->bits = header.bits;
  info->weight = header.weight;
  info->geometry_only = header.geometry_only();
  info->refined = header.refined();
  info->levels = header.levels();
  info->reordered = header.reordered();
  info->reconstruction = header.reconstruction;
  if (header.reconstruction == kGabReconstructionIterativeLocal) {
    info->prediction_sweeps = kOperator2Tuning.prediction_sweeps;
    info->final_sweeps = kOperator2Tuning.final_sweeps;
    info->final_steps16 = kOperator2Tuning.final_steps16;
    info->final_most_steps = kOperator2Tuning.final_most;
  }
  info->sections = header.sections;
  info->detail = header.detail();
  info->ordering = file_ordering(header.ordering);
  for (int c = 0; c < 3; ++c) info->box_min[c] = header.box_min[c];
  info->step = header.step;
  info->anchors = header.anchors;
  info->chunks = header.chunks;
  info->bytes = size;
  info->header_bytes = in.offset();
  const size_t before = in.offset();
  ConnectivitySection connectivity;
  GAB_RETURN_IF_ERROR(read_connectivity_section(&in, header, &connectivity));
  info->order_bytes = connectivity.order_bytes;
  info->connectivity_bytes = in.offset() - before - info->order_bytes;
  std::vector<int32_t> level_anchors;  // level layout: anchors of chunks 1.. (from chunk 0's plan)
  for (int32_t chunk = 0; chunk < header.chunks; ++chunk) {
    const size_t at = in.offset();
    const uint8_t* payload = nullptr;
    size_t payload_size = 0;
    const FrameRead frame = read_framed(&in, &payload, &payload_size);
    if (frame == FrameRead::kTruncated) {
      info->truncated = true;
      break;
    }
    if (frame == FrameRead::kCorrupt) {
      return corrupt("chunk " + std::to_string(chunk) + " is corrupt (checksum mismatch)");
    }
    if (header.detail() && chunk == header.detail_chunk()) {
      DetailParams params;
      size_t offset = 0;
      const Status s = read_detail_head(payload, payload_size, detail_frame_of(header), &params, &offset);
      if (s.code() == StatusCode::kUnsupported) return s;
      if (!s.ok()) return corrupt("detail (chunk " + std::to_string(chunk) + "): " + s.message());
      info->detail_bytes = in.offset() - at;
      info->detail_step = params.step;
      info->chunks_present = chunk + 1;
      continue;
    }
    if (chunk == 0 && header.reconstruction == kGabReconstructionIterativeTuned) {
      IterativeTuning tuning;
      size_t offset = 0;
      const Status s = parse_iterative_tuning(payload, payload_size, &tuning, &offset);
      if (!s.ok()) return corrupt("chunk 0: " + s.message());
      info->prediction_sweeps = tuning.prediction_sweeps;
      info->final_sweeps = tuning.final_sweeps;
      info->final_steps16 = tuning.final_steps16;
      info->final_most_steps = tuning.final_most;
      payload += offset;
      payload_size -= offset;
    }
    const bool refinement = header.refined() && chunk == header.refinement_chunk();
    uint64_t count = 0;
    if (header.levels() && chunk == 0) {
      LevelPlan plan;
      size_t offset = 0;
      const Status s = parse_level_plan(payload, payload_size, header.anchors, header.anchor_chunks(), &plan, &offset);
      if (!s.ok()) return corrupt("chunk 0: " + s.message());
      count = static_cast<uint64_t>(plan.spread);
      level_anchors = plan.level_sizes();
    } else if (header.levels() && !refinement) {
      count = static_cast<uint64_t>(level_anchors[chunk - 1]);  // the plan made anchor_chunks - 1 levels
    } else {
      // The decoders' own rules for a chunk's head (the count), against the header.
      ByteReader chunk_in(payload, payload_size);
      const Status s = refinement ? read_refinement_count(&chunk_in, header.anchors)
                                  : read_chunk_anchor_count(&chunk_in, static_cast<uint64_t>(header.anchors), &count);
      if (!s.ok()) return corrupt("chunk " + std::to_string(chunk) + ": anchor count out of range");
    }
    if (refinement) {
      info->refinement_bytes = in.offset() - at;
      info->chunks_present = chunk + 1;
      continue;
    }
    info->chunk_bytes.push_back(in.offset() - at);
    info->chunk_anchors.push_back(static_cast<int32_t>(count));
    info->chunks_present = chunk + 1;
  }
  if (!info->truncated) {
    const size_t sections_start = in.offset();
    std::vector<TrailingSection> sections;
    GAB_RETURN_IF_ERROR(read_trailing_sections(&in, header.sections, &sections, &info->truncated));
    info->section_bytes = in.offset() - sections_start;
    for (size_t i = 0; i < sections.size(); ++i) {
      GabFileInfo::Section entry;
      entry.kind = sections[i].kind;
      entry.bytes = sections[i].size + kGabFrameBytes;
      if (sections[i].kind == kGabSectionAttribute) {
        AttributeDescription d;
        const Status s = read_attribute_description(sections[i].payload, sections[i].size, &d);
        if (s.code() == StatusCode::kParseError) return corrupt("section " + std::to_string(i) + ": " + s.message());
        if (s.ok()) {
          entry.attribute = attribute_label(d.attribute);
          entry.per_corner = d.per_corner;
          entry.elements = static_cast<int64_t>(d.elements);
          entry.bits = d.quantizer.bits;
          entry.predictor = d.predictor;
        }
      }
      info->section_list.push_back(std::move(entry));
    }
  }
  info->geometry_bytes = size - info->connectivity_bytes - info->order_bytes - info->section_bytes;
  return Status::Ok();
}

}  // namespace gab
