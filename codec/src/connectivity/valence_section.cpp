#include "connectivity/valence_section.h"

#include <algorithm>
#include <string>

#include "connectivity/valence_coder.h"
#include "entropy/int_coder.h"
#include "entropy/range_coder.h"
#include "gab/mesh/manifold_cut.h"

namespace gab {

namespace {

// The counts and indices after the valences: stitches (a decoded vertex
// that is a copy the cut made, and the earlier decoded vertex it copies),
// then the degenerate triangles.
struct SectionModels {
  UIntCoder stitch_count, stitch_gap, stitch_back, degenerate_count, index;
};

// A closed region's triangles are at most twice its vertices plus four per
// handle, and each vertex and handle costs a coded decision at least: so at
// most 6 triangles a decision (the dummies' triangles included).
constexpr uint64_t kMaxTrianglesPerDecision = 6;
// A UIntCoder value is its bit length, 6 decisions at least (int_coder.h).
constexpr uint64_t kMinDecisionsPerIndex = 6;

}  // namespace

ValenceSection encode_valence_section(int32_t n, const std::vector<int32_t>& triangles) {
  ManifoldCut cut = cut_to_manifold(n, triangles);
  // The cut's copies and degenerate triangles are read below; its triangles
  // and opposites become the closed mesh's.
  const ClosedMesh closed = close_boundaries(&cut);
  RangeEncoder enc;
  std::vector<int32_t> order;
  const int64_t walked = encode_valences(closed, &enc, &order);

  // The decoder numbers each input vertex where it first meets it (or one
  // of its copies); a later copy is a stitch back to that first meeting.
  ValenceSection section;
  section.walked = walked;
  section.new_index.assign(static_cast<size_t>(n), -1);
  std::vector<int32_t> first_met(static_cast<size_t>(n), -1);
  std::vector<int32_t> stitch_at, stitch_to;
  int32_t next = 0;
  for (int32_t k = 0; k < static_cast<int32_t>(order.size()); ++k) {
    const int32_t v = order[k];
    if (closed.dummy[v]) continue;
    const int32_t original = v < n ? v : cut.copy_of[v - n];
    if (first_met[original] < 0) {
      first_met[original] = k;
      section.new_index[original] = next++;
    } else {
      stitch_at.push_back(k);
      stitch_to.push_back(first_met[original]);
    }
  }
  for (int32_t& index : section.new_index) {
    if (index < 0) index = next++;  // on no proper triangle
  }

  SectionModels models;
  models.stitch_count.encode(&enc, static_cast<uint32_t>(stitch_at.size()));
  for (size_t i = 0; i < stitch_at.size(); ++i) {
    models.stitch_gap.encode(&enc, static_cast<uint32_t>(stitch_at[i] - (i > 0 ? stitch_at[i - 1] : 0)));
    models.stitch_back.encode(&enc, static_cast<uint32_t>(stitch_at[i] - stitch_to[i] - 1));
  }
  models.degenerate_count.encode(&enc, static_cast<uint32_t>(cut.degenerate.size() / 3));
  for (int32_t v : cut.degenerate) models.index.encode(&enc, static_cast<uint32_t>(section.new_index[v]));
  section.bytes = enc.finish();
  return section;
}

Status decode_valence_section(const uint8_t* data, size_t size, int32_t n, int32_t t,
                              std::vector<int32_t>* triangles) {
  auto corrupt = [](const std::string& what) {
    return Status::Error(StatusCode::kParseError, "connectivity: " + what);
  };
  if (n < 1 || t < 0) return Status::Error(StatusCode::kInvalidArgument, "connectivity: bad counts");
  // Each triangle costs a sixth of a decision at least (valence_section.h).
  if (static_cast<uint64_t>(t) > kMaxTrianglesPerDecision * max_decisions(size)) {
    return corrupt("the header's " + std::to_string(t) + " triangles are more than a block of " +
                   std::to_string(size) + " bytes can describe");
  }
  // The closed mesh has at most the cut's vertices (n + 3t copies) plus a
  // dummy per boundary loop (<= t), and t + 3t triangles with the dummies'.
  const int64_t max_vertices = std::min<int64_t>(static_cast<int64_t>(n) + 4 * static_cast<int64_t>(t), INT32_MAX);
  RangeDecoder dec(data, size);
  DecodedConnectivity decoded;
  GAB_RETURN_IF_ERROR(
      decode_valences(&dec, static_cast<int32_t>(max_vertices), 4 * static_cast<int64_t>(t), &decoded, t));

  SectionModels models;
  const uint32_t stitches = models.stitch_count.decode(&dec);
  if (stitches > static_cast<uint32_t>(decoded.num_vertices)) return corrupt("stitch count out of range");
  // number[k]: the output index of decoded vertex k (-1 for dummies, -2
  // until known).
  std::vector<int32_t> number(static_cast<size_t>(decoded.num_vertices), -2);
  std::vector<int32_t> stitched_to(static_cast<size_t>(decoded.num_vertices), -1);
  int64_t at = 0;
  for (uint32_t i = 0; i < stitches; ++i) {
    if (dec.overrun()) return corrupt("stream truncated");
    const uint32_t gap = models.stitch_gap.decode(&dec);
    if (i > 0 && gap == 0) return corrupt("stitches out of order");
    at += gap;
    const int64_t back = static_cast<int64_t>(models.stitch_back.decode(&dec)) + 1;
    if (at >= decoded.num_vertices || back > at) return corrupt("stitch out of range");
    stitched_to[at] = static_cast<int32_t>(at - back);
  }
  int32_t next = 0;
  for (int32_t k = 0; k < decoded.num_vertices; ++k) {
    if (decoded.dummy[k]) {
      if (stitched_to[k] >= 0) return corrupt("a boundary's dummy vertex is stitched");
      number[k] = -1;
    } else if (stitched_to[k] >= 0) {
      number[k] = number[stitched_to[k]];
      if (number[k] < 0 || stitched_to[stitched_to[k]] >= 0) return corrupt("a stitch leads to no vertex");
    } else {
      if (next >= n) return corrupt("more vertices than the header says");
      number[k] = next++;
    }
  }
  triangles->clear();
  // At most the decoded triangles (grown by doubling, the array would end up
  // to twice its size).
  triangles->reserve(std::min(decoded.triangles.size(), 3 * static_cast<size_t>(t)));
  for (size_t i = 0; i < decoded.triangles.size(); i += 3) {
    const int32_t a = number[decoded.triangles[i]], b = number[decoded.triangles[i + 1]],
                  c = number[decoded.triangles[i + 2]];
    if (a < 0 || b < 0 || c < 0) continue;  // a dummy's triangle
    if (static_cast<int64_t>(triangles->size()) >= 3 * static_cast<int64_t>(t)) {
      return corrupt("more triangles than the header says");
    }
    triangles->insert(triangles->end(), {a, b, c});
  }
  const uint32_t degenerate = models.degenerate_count.decode(&dec);
  if (dec.overrun()) return corrupt("stream truncated");
  if (static_cast<uint64_t>(degenerate) + triangles->size() / 3 != static_cast<uint64_t>(t)) {
    return corrupt("triangle count disagrees with the header");
  }
  // Each index is at least kMinDecisionsPerIndex decisions: a count the
  // rest of the stream cannot hold is refused before the loop, and the loop
  // stops where the stream ends.
  if (3 * static_cast<uint64_t>(degenerate) * kMinDecisionsPerIndex > max_decisions(size - dec.bytes_consumed())) {
    return corrupt(std::to_string(degenerate) + " degenerate triangles are more than the stream's last " +
                   std::to_string(size - dec.bytes_consumed()) + " bytes can describe");
  }
  for (uint32_t i = 0; i < 3 * degenerate; ++i) {
    if (dec.overrun()) return corrupt("stream truncated");
    const uint32_t v = models.index.decode(&dec);
    if (v >= static_cast<uint32_t>(n)) return corrupt("degenerate triangle's vertex out of range");
    triangles->push_back(static_cast<int32_t>(v));
  }
  if (dec.overrun()) return corrupt("stream truncated");
  if (dec.bytes_consumed() != size) return corrupt("trailing bytes");
  return Status::Ok();
}

}  // namespace gab
