// The orderings' names (ordering.h) and kAuto's rule.
#include "gab/sparse/ordering.h"

namespace gab {
namespace {

struct NamedOrdering {
  Ordering ordering;
  const char* name;
};

// One row per ordering; kGiven's name is never parsed (a permutation has no name).
constexpr NamedOrdering kNames[] = {{Ordering::kAuto, "auto"},
                                    {Ordering::kAmd, "amd"},
                                    {Ordering::kNestedDissection, "nd"},
                                    {Ordering::kNatural, "natural"},
                                    {Ordering::kGiven, "given"}};

}  // namespace

const char* ordering_name(Ordering ordering) {
  for (const NamedOrdering& row : kNames) {
    if (row.ordering == ordering) return row.name;
  }
  return "?";
}

bool parse_ordering(const std::string& name, Ordering* ordering) {
  for (const NamedOrdering& row : kNames) {
    if (row.ordering != Ordering::kGiven && name == row.name) {
      *ordering = row.ordering;
      return true;
    }
  }
  return false;
}

Ordering resolve_ordering(Ordering ordering, int32_t n) {
  if (ordering != Ordering::kAuto) return ordering;
  // Where nested dissection's cheaper factor and shorter update paths pay
  // for its ordering time (about 3x AMD's), measured on the codec's
  // matrices (L^T L + w^2 E^T E): below igea's 134k vertices the codec's
  // times under either ordering were within the runs' noise, igea encoded
  // 19-35% faster and decoded as fast, and from 600k vertices the factor is
  // 2-3x cheaper and a third smaller (docs/tuning-codec.md, "Ordering").
  return n >= kNestedDissectionFrom ? Ordering::kNestedDissection : Ordering::kAmd;
}

}  // namespace gab
