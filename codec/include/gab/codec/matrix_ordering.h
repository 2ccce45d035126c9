// Which fill-reducing ordering the codec's factorizations of L^T L + w^2 E^T E
// use (gab/sparse/symbolic.h Ordering): a matter of speed. The file records
// the encoder's (gab_format.h, header byte 11) and a decoder uses it unless
// told otherwise: the factorizations the encoder ran on the decoder's
// behalf. Any other ordering decodes too: the codec rounds every prediction
// through a guard (codec/src/anchors/quantizer.h), so the anchors and a
// detail layer's positions come out the same, and a shape solved from the
// anchors differs by rounding only (as at another SIMD level).
#pragma once

namespace gab {

enum class MatrixOrdering {
  kAuto,              // the one measured fastest for the mesh's size (codec/src/pipeline/ordering_choice.h)
  kAmd,               // approximate minimum degree: cheapest to compute, more fill at size
  kNestedDissection,  // multilevel nested dissection: less fill and shorter update paths, dearer to compute
};

// "auto", "amd" or "nd".
const char* matrix_ordering_name(MatrixOrdering ordering);

}  // namespace gab
