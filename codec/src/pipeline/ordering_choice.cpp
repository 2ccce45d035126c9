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
  // Where nested dissection's cheaper factor and shorter update paths pay
  // for its ordering time (about 3x AMD's): below igea's 134k vertices the
  // codec's times under either ordering were within the runs' noise, igea
  // encoded 19-35% faster and decoded as fast, and from 600k vertices the
  // factor is 2-3x cheaper and a third smaller (bench/TUNING.md, "Ordering").
  return num_vertices >= kNestedDissectionFrom ? MatrixOrdering::kNestedDissection : MatrixOrdering::kAmd;
}

MatrixOrdering file_ordering(uint8_t file_code) {
  return file_code == kGabOrderingNestedDissection ? MatrixOrdering::kNestedDissection : MatrixOrdering::kAmd;
}

MatrixOrdering decoder_ordering(MatrixOrdering asked, uint8_t file_code) {
  return asked != MatrixOrdering::kAuto ? asked : file_ordering(file_code);
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
