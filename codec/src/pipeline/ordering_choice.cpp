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
  // for its ordering time (about 3x AMD's, sparse/src/nested_dissection_graph.h),
  // measured at 1e-3 on one thread (CPU seconds, encode / decode, AMD -> ND;
  // bench/TUNING.md, "Ordering"): igea (134k
  // vertices) 6.10 -> 3.96 / 1.37 -> 1.26; horse and bunny (48k, 35k)
  // encode 18% faster but decode 5-7% slower, nefertiti and feline (50k,
  // 49k) even, max-planck (25k) 15% slower both ways. The file is decoded
  // more often than encoded, so ND starts where decoding gains too.
  return num_vertices >= kNestedDissectionFrom ? MatrixOrdering::kNestedDissection : MatrixOrdering::kAmd;
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
