#include "pipeline/ordering_choice.h"

#include <string>

#include "gab/codec/gab_format.h"

namespace gab {

bool codec_takes_ordering(Ordering ordering) {
  return ordering == Ordering::kAuto || ordering == Ordering::kAmd || ordering == Ordering::kNestedDissection;
}

Status check_codec_ordering(Ordering asked) {
  if (codec_takes_ordering(asked)) return Status::Ok();
  return Status::Error(StatusCode::kInvalidArgument, std::string("the codec factors with the auto, amd or nd ordering, not ") +
                                                         ordering_name(asked));
}

Ordering encoder_ordering(Ordering asked, int32_t num_vertices) {
  return resolve_ordering(asked, num_vertices);
}

Ordering file_ordering(uint8_t file_code) {
  return file_code == kGabOrderingNestedDissection ? Ordering::kNestedDissection : Ordering::kAmd;
}

Ordering decoder_ordering(Ordering asked, uint8_t file_code) {
  return asked != Ordering::kAuto ? asked : file_ordering(file_code);
}

uint8_t ordering_code(Ordering ordering) {
  return ordering == Ordering::kNestedDissection ? kGabOrderingNestedDissection : kGabOrderingAmd;
}

void OrderingPlan::apply(RelaxedReconstruction* rec) const {
  if (!perm_.empty()) {
    rec->set_given_ordering(perm_);
  } else {
    rec->set_ordering(choice_ == Ordering::kNestedDissection ? Ordering::kNestedDissection : Ordering::kAmd);
  }
}

void OrderingPlan::remember(const RelaxedReconstruction& rec) {
  if (perm_.empty() && rec.cholesky().factorized()) perm_ = rec.cholesky().symbolic().perm;
}

}  // namespace gab
