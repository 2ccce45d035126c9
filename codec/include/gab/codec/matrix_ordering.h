// Which fill-reducing ordering the codec's factorizations of L^T L + w^2 E^T E
// use: the engine's Ordering (gab/sparse/ordering.h: one enum and one set of
// names for every door), of which the codec takes kAuto, kAmd and
// kNestedDissection (kInvalidArgument for the others).
// A matter of speed: the file records the encoder's (gab_format.h, header
// byte 11) and a decoder uses it unless told otherwise. Any other ordering
// decodes too: the codec rounds every prediction through a guard
// (codec/src/anchors/quantizer.h), so the anchors and a detail layer's
// positions come out the same, and a shape solved from the anchors differs
// by rounding only (as at another SIMD level).
#pragma once

#include "gab/sparse/ordering.h"

namespace gab {

// Whether the codec factors with `ordering`: kAuto, kAmd or kNestedDissection. O(1).
bool codec_takes_ordering(Ordering ordering);

}  // namespace gab
