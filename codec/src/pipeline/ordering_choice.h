// Ordering made concrete: the encoder's choice by the mesh's size, the
// decoder's from the file (gab_format.h, header byte 11), and the encoder's
// reuse of one permutation across its factorizations.
#pragma once

#include <cstdint>
#include <vector>

#include "gab/codec/matrix_ordering.h"
#include "gab/mesh/relaxed_reconstruction.h"
#include "gab/status.h"

namespace gab {

// kInvalidArgument naming the codec's orderings unless codec_takes_ordering(asked).
Status check_codec_ordering(Ordering asked);
// `asked` unless kAuto; for kAuto, nested dissection from
// kNestedDissectionFrom vertices, AMD below (resolve_ordering,
// gab/sparse/ordering.h). Never returns kAuto.
Ordering encoder_ordering(Ordering asked, int32_t num_vertices);
// The ordering a header's code (a kGabOrdering* value) names.
Ordering file_ordering(uint8_t file_code);
// The header's code of a concrete ordering.
uint8_t ordering_code(Ordering ordering);
// `asked` unless kAuto; for kAuto the one the file's encoder used
// (file_ordering): the same factor, the same shapes.
Ordering decoder_ordering(Ordering asked, uint8_t file_code);

// One encode's orderings: the choice, and the permutation the first
// analysis computed, which every later factorization of the same
// connectivity reuses (RelaxedReconstruction::set_given_ordering): the
// encoder factors up to a dozen times per file.
class OrderingPlan {
 public:
  explicit OrderingPlan(Ordering choice) : choice_(choice) {}
  Ordering choice() const { return choice_; }
  // Before rec's init: the remembered permutation, else the choice.
  void apply(RelaxedReconstruction* rec) const;
  // After rec's init: keeps its permutation (once).
  void remember(const RelaxedReconstruction& rec);

 private:
  Ordering choice_;
  std::vector<int32_t> perm_;
};

}  // namespace gab
