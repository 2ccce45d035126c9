#include "anchors/refinement_chunk.h"

#include <algorithm>
#include <cstdlib>
#include <string>

#include "entropy/axis_context.h"
#include "entropy/int_coder.h"
#include "entropy/range_coder.h"

namespace gab {

namespace {

// Most corrections are 0 or +-1 step; the context separates anchors whose
// other axes moved (their basis function overlaps others a lot) from quiet
// ones. Buckets: |d| = 0, 1, 2-3, 4+.
constexpr int kBuckets = 4;

// Adaptation shift 5: the corrections' statistics are stationary over the
// chunk (measured: shift 4 costs more on horse and igea).
SIntCoder make_coder() { return SIntCoder(3 * kBuckets, 5); }

}  // namespace

std::vector<uint8_t> encode_refinement(const std::vector<int32_t>& deltas) {
  SIntCoder coder = make_coder();
  RangeEncoder enc;
  int32_t previous_max = 0;
  for (size_t a = 0; a + 2 < deltas.size(); a += 3) {
    const int32_t* d = &deltas[a];
    for (int c = 0; c < 3; ++c) coder.encode(&enc, d[c], axis_context(c, d, previous_max, kBuckets));
    previous_max = max_magnitude(d);
  }
  const std::vector<uint8_t> coded = enc.finish();
  ByteWriter out;
  out.varint(deltas.size() / 3);
  out.bytes(coded.data(), coded.size());
  return out.take();
}

Status decode_refinement(const uint8_t* payload, size_t size, int32_t anchors, int32_t max_delta,
                         std::vector<int32_t>* deltas) {
  ByteReader in(payload, size);
  GAB_RETURN_IF_ERROR(read_refinement_count(&in, anchors));
  SIntCoder coder = make_coder();
  RangeDecoder dec(payload + in.offset(), in.remaining());
  deltas->assign(static_cast<size_t>(anchors) * 3, 0);
  int32_t previous_max = 0;
  for (size_t a = 0; a < deltas->size(); a += 3) {
    int32_t* d = &(*deltas)[a];
    for (int c = 0; c < 3; ++c) {
      d[c] = coder.decode(&dec, axis_context(c, d, previous_max, kBuckets));
      if (d[c] > max_delta || d[c] < -max_delta) {
        return Status::Error(StatusCode::kParseError, "refinement of anchor #" + std::to_string(a / 3) +
                                                          " leaves the grid");
      }
    }
    if (dec.overrun()) return Status::Error(StatusCode::kParseError, "refinement is cut short");
    previous_max = max_magnitude(d);
  }
  return Status::Ok();
}

Status read_refinement_count(ByteReader* in, int32_t anchors) {
  uint64_t count = 0;
  if (!in->varint(&count)) return Status::Error(StatusCode::kParseError, "refinement count is cut short");
  if (count != static_cast<uint64_t>(anchors)) {
    return Status::Error(StatusCode::kParseError, "refinement holds " + std::to_string(count) +
                                                      " corrections for " + std::to_string(anchors) + " anchors");
  }
  return Status::Ok();
}

std::vector<uint8_t> encode_refinement_chunk(const std::vector<int32_t>& file_order,
                                             const std::vector<int32_t>& selection,
                                             const std::vector<int32_t>& refined_grid,
                                             const std::vector<int32_t>& grid) {
  std::vector<int32_t> slot(grid.size() / 3, -1);  // per vertex: its place in `selection`
  for (size_t i = 0; i < selection.size(); ++i) slot[selection[i]] = static_cast<int32_t>(i);
  std::vector<int32_t> deltas(file_order.size() * 3);
  for (size_t i = 0; i < file_order.size(); ++i) {
    const size_t v = static_cast<size_t>(file_order[i]), s = static_cast<size_t>(slot[v]);
    for (int c = 0; c < 3; ++c) deltas[3 * i + c] = refined_grid[3 * s + c] - grid[3 * v + c];
  }
  return encode_refinement(deltas);
}

Status decode_refinement_chunk(const uint8_t* payload, size_t size, const std::vector<int32_t>& file_grid,
                               const Quantizer& quantizer, std::vector<double>* coefficients) {
  std::vector<int32_t> deltas;
  GAB_RETURN_IF_ERROR(decode_refinement(payload, size, static_cast<int32_t>(file_grid.size() / 3),
                                        quantizer.max_index, &deltas));
  coefficients->assign(deltas.size(), 0.0);
  for (size_t i = 0; i < deltas.size(); ++i) {
    const int64_t value = int64_t{file_grid[i]} + deltas[i];
    if (value < 0 || value > quantizer.max_index) {
      return Status::Error(StatusCode::kParseError, "anchor #" + std::to_string(i / 3) + " is moved off the grid");
    }
    (*coefficients)[i] = quantizer.dequantize(static_cast<int32_t>(value), static_cast<int>(i % 3));
  }
  return Status::Ok();
}

}  // namespace gab
