// gab_ordering_from_name and the GAB_ORDERING_* codes: the names are the
// engine's (parse_ordering, gab/sparse/ordering.h), the codes the C door's.
#include "ordering_codes.h"

#include "gab/codec/matrix_ordering.h"
#include "gab/gab.h"

namespace gab {
namespace capi {
namespace {

struct OrderingCode {
  int32_t code;
  Ordering ordering;
};

// The codec's orderings, each with its code.
constexpr OrderingCode kCodes[] = {{GAB_ORDERING_AUTO, Ordering::kAuto},
                                   {GAB_ORDERING_AMD, Ordering::kAmd},
                                   {GAB_ORDERING_ND, Ordering::kNestedDissection}};

}  // namespace

bool ordering_of_code(int32_t code, Ordering* ordering) {
  for (const OrderingCode& row : kCodes) {
    if (row.code == code) {
      *ordering = row.ordering;
      return true;
    }
  }
  return false;
}

}  // namespace capi
}  // namespace gab

extern "C" int gab_ordering_from_name(const char* name) {
  gab::Ordering ordering;
  if (name == nullptr || !gab::parse_ordering(name, &ordering) || !gab::codec_takes_ordering(ordering)) return -1;
  for (const gab::capi::OrderingCode& row : gab::capi::kCodes) {
    if (row.ordering == ordering) return row.code;
  }
  return -1;
}
