#include "pipeline/ordering_choice.h"

#include "gab/codec/gab_format.h"

namespace gab {

const char* matrix_ordering_name(MatrixOrdering ordering) {
  switch (ordering) {
    case MatrixOrdering::kAmd:
      return "amd";
    case MatrixOrdering::kNestedDissection:
      return "nd";
    case MatrixOrdering::kAuto:
      break;
  }
  return "auto";
}

MatrixOrdering encoder_ordering(MatrixOrdering asked, int32_t num_vertices) {
  if (asked != MatrixOrdering::kAuto) return asked;
  // TODO(measure): crossover.
  return num_vertices >= 20000 ? MatrixOrdering::kNestedDissection : MatrixOrdering::kAmd;
}

MatrixOrdering decoder_ordering(MatrixOrdering asked, uint8_t file_code) {
  if (asked != MatrixOrdering::kAuto) return asked;
  return file_code == kGabOrderingNestedDissection ? MatrixOrdering::kNestedDissection : MatrixOrdering::kAmd;
}

uint8_t ordering_code(MatrixOrdering ordering) {
  return ordering == MatrixOrdering::kNestedDissection ? kGabOrderingNestedDissection : kGabOrderingAmd;
}

void OrderingPlan::apply(RelaxedReconstruction* rec) const {
  if (!perm_.empty()) {
    rec->set_given_ordering(perm_);
  } else {
    rec->set_ordering(choice_ == MatrixOrdering::kNestedDissection ? Ordering::kNestedDissection : Ordering::kAmd);
  }
}

void OrderingPlan::remember(const RelaxedReconstruction& rec) {
  if (perm_.empty() && rec.cholesky().factorized()) perm_ = rec.cholesky().symbolic().perm;
}

}  // namespace gab
