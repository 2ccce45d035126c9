// Operator 3's parameters (docs/format.md 5.2.3): operator 2's shape with
// its sweeps and final steps chosen by the encoder and written at the head
// of chunk 0, so the encoder can trade a decode's work against the file's
// bytes without a new operator. Operator 2 is operator 3 with
// kOperator2Tuning.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "gab/mesh/iterative_reconstruction.h"
#include "gab/status.h"

namespace gab {

struct IterativeTuning {
  // Harmonic sweeps of a chunk's prediction (the start at its vertices) and
  // of the final shape's start: 0..IterativeReconstruction::kMostStartSweeps.
  int32_t prediction_sweeps = IterativeReconstruction::kStartSweeps;
  int32_t final_sweeps = IterativeReconstruction::kStartSweeps;
  // The final shape's conjugate-gradient steps for k anchors on n vertices:
  // min(final_most, ceil(final_steps16 n / (16 k))), each in 0..kMostFinalSteps.
  int32_t final_steps16 = 16;
  int32_t final_most = 32;
};
constexpr int32_t kMostFinalSteps = 64;
// Operator 2's fixed parameters.
constexpr IterativeTuning kOperator2Tuning = {};

// The final shape's steps the tuning gives for k anchors on n vertices.
int32_t final_steps(const IterativeTuning& tuning, int32_t n, int32_t k);

// Whether every field is in range.
bool tuning_in_range(const IterativeTuning& tuning);

// The tuning's bytes (kIterativeTuningBytes: the four fields as u8 in
// order), put before `chunk`'s payload.
constexpr size_t kIterativeTuningBytes = 4;
void prepend_iterative_tuning(const IterativeTuning& tuning, std::vector<uint8_t>* chunk);
// Reads them from the head of a chunk 0 payload: *offset just past them;
// kParseError naming the field when one is out of range or the payload is
// too short.
Status parse_iterative_tuning(const uint8_t* payload, size_t size, IterativeTuning* tuning, size_t* offset);

}  // namespace gab
