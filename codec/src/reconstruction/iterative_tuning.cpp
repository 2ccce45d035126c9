#include "reconstruction/iterative_tuning.h"

#include <algorithm>
#include <string>

namespace gab {

int32_t final_steps(const IterativeTuning& tuning, int32_t n, int32_t k) {
  const int64_t spacing16 = 16 * static_cast<int64_t>(std::max(k, 1));
  const int64_t steps = (static_cast<int64_t>(tuning.final_steps16) * n + spacing16 - 1) / spacing16;
  return static_cast<int32_t>(std::min<int64_t>(steps, tuning.final_most));
}

bool tuning_in_range(const IterativeTuning& t) {
  const int32_t sweeps = IterativeReconstruction::kMostStartSweeps;
  return t.prediction_sweeps >= 0 && t.prediction_sweeps <= sweeps && t.final_sweeps >= 0 &&
         t.final_sweeps <= sweeps && t.final_steps16 >= 0 && t.final_steps16 <= kMostFinalSteps &&
         t.final_most >= 0 && t.final_most <= kMostFinalSteps;
}

void prepend_iterative_tuning(const IterativeTuning& t, std::vector<uint8_t>* chunk) {
  const uint8_t head[kIterativeTuningBytes] = {
      static_cast<uint8_t>(t.prediction_sweeps), static_cast<uint8_t>(t.final_sweeps),
      static_cast<uint8_t>(t.final_steps16), static_cast<uint8_t>(t.final_most)};
  chunk->insert(chunk->begin(), head, head + kIterativeTuningBytes);
}

Status parse_iterative_tuning(const uint8_t* payload, size_t size, IterativeTuning* t, size_t* offset) {
  if (size < kIterativeTuningBytes) {
    return Status::Error(StatusCode::kParseError, "the operator's parameters are cut short");
  }
  const int32_t sweeps = IterativeReconstruction::kMostStartSweeps;
  const struct {
    const char* name;
    int32_t most;
    int32_t* field;
  } fields[] = {{"prediction sweeps", sweeps, &t->prediction_sweeps},
                {"final sweeps", sweeps, &t->final_sweeps},
                {"final steps per spacing (sixteenths)", kMostFinalSteps, &t->final_steps16},
                {"most final steps", kMostFinalSteps, &t->final_most}};
  for (size_t i = 0; i < kIterativeTuningBytes; ++i) {
    if (payload[i] > fields[i].most) {
      return Status::Error(StatusCode::kParseError, std::string("the operator's ") + fields[i].name + " " +
                                                        std::to_string(payload[i]) + " exceeds " +
                                                        std::to_string(fields[i].most));
    }
    *fields[i].field = payload[i];
  }
  *offset = kIterativeTuningBytes;
  return Status::Ok();
}

}  // namespace gab
