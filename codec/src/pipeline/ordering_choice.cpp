#include "pipeline/ordering_choice.h"

#include <string>

#include "gab/codec/gab_format.h"

namespace gab {

bool codec_takes_ordering(Ordering ordering) {
  return ordering == Ordering::kAuto || ordering == Ordering::kAmd || ordering == Ordering::kNestedDissection;
}

Status check_codec_ordering(MatrixOrdering asked) {
  if (codec_takes_ordering(asked)) return Status::Ok();
  return Status::Error(StatusCode::kInvalidArgument, std::string("the codec factors with the auto, amd or nd ordering, not ") +
                                                         ordering_name(asked));
}

MatrixOrdering encoder_ordering(MatrixOrdering asked, int32_t num_vertices) {
  return resolve_ordering(asked, num_vertices);
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
