// The fill-reducing orderings, named once for every door: the engine's
// analysis, the codec's options, the CLI's --ordering and the C API all use
// this enum and these names.
#pragma once

#include <cstdint>
#include <string>

namespace gab {

enum class Ordering {
  kAuto,              // by size: nested dissection from kNestedDissectionFrom columns, AMD below
  kAmd,               // approximate minimum degree (amd.h): cheapest to compute, more fill at size
  kNestedDissection,  // nested dissection (nested_dissection.h): less fill, shorter update paths, dearer to compute
  kNatural,           // identity, then postorder of the elimination tree
  kGiven,             // AnalyzeOptions::given_perm, then postorder (no name: a caller's own permutation)
};

// Where kAuto turns to nested dissection (columns, i.e. mesh vertices).
constexpr int32_t kNestedDissectionFrom = 100000;

// "auto", "amd", "nd", "natural" or "given". O(1).
const char* ordering_name(Ordering ordering);

// The ordering `name` names ("auto", "amd", "nd" or "natural"); false for
// any other text. O(1).
bool parse_ordering(const std::string& name, Ordering* ordering);

// kAuto made concrete for a matrix of n columns; any other ordering as it is. O(1).
Ordering resolve_ordering(Ordering ordering, int32_t n);

}  // namespace gab
