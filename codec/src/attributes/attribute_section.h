// One attribute in one trailing section of a .gab file (docs/format.md
// 6.2-6.5): its description, its quantization, then one range-coded stream
// walking the vertices in the corner table's visit order: per vertex the
// seams between its corners (per-corner attributes), then each new
// element's residual from a prediction: for every kind the parallelogram
// across a decoded triangle (else the mean of decoded neighbours, else the
// previous element), integers over the connectivity alone, so any level of
// detail decodes it; for normals also the decoded surface's normal,
// rounded through the guard band, which needs the whole decoded shape.
// Internal to the codec.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "attributes/attribute_quantizer.h"
#include "attributes/corner_table.h"
#include "gab/mesh/mesh_attribute.h"
#include "gab/status.h"

namespace gab {

// The section kind (its payload's first byte) of an attribute.
constexpr uint8_t kGabSectionAttribute = 1;

// What coding one attribute did.
struct AttributeCoding {
  int bits = 0;             // its quantization's (integer-typed: the span's)
  bool per_corner = false;  // coded per corner (seams); false: per vertex
  int64_t elements = 0;     // elements coded: vertices, or wedges of corners with one value
  bool surface = false;     // normals predicted from the decoded surface (the decoder needs the whole shape)
  // The largest error of a decoded value: degrees between directions for
  // normals, value units otherwise (0: exact).
  double max_error = 0;
};

// The section's payload for `attribute` (valid for the mesh of `table`,
// numbered as the decoder returns it), quantized at `bits` (normals: the
// lattice's, 2..16; float-typed: the grid's, 1..31; integer-typed: ignored,
// exact). A per-corner attribute with no seam is coded per vertex. Every
// predictor the attribute can take is tried and the smallest stream kept:
// the parallelogram and the values in the wedge's triangles; for normals,
// given `positions` (the decoded shape, bit for bit the decoder's), also
// the decoded surface's normal in four ways. O(elements + corners) per
// predictor.
std::vector<uint8_t> encode_attribute_section(const MeshAttribute& attribute, const CornerTable& table, int bits,
                                              const std::vector<double>* positions, AttributeCoding* coding);

// A section's description: what it holds and how it is quantized, read
// without decoding (gab info).
struct AttributeDescription {
  MeshAttribute attribute;  // kind, type, components, name; no values
  AttributeQuantizer quantizer;
  bool per_corner = false;
  uint8_t predictor = 0;     // docs/format.md 6.4
  bool surface = false;      // predicted from the decoded surface (predictors 1, 2): needs the whole decoded shape
  uint64_t elements = 0;     // as declared
  size_t stream_offset = 0;  // where the range-coded stream starts in the payload
};
// kParseError / kUnsupported as decode_attribute_section. O(1).
Status read_attribute_description(const uint8_t* payload, size_t size, AttributeDescription* description);

// The attribute a section's payload describes, for the mesh of `table`
// whose decoded shape is `positions` (null when it is not the whole shape:
// a level of detail, the detail chunk skipped or cut off). kParseError
// naming what is wrong; kUnsupported for a predictor or a kind this build
// does not know, and for normals predicted from the surface without the
// whole shape. O(payload + elements + corners).
Status decode_attribute_section(const uint8_t* payload, size_t size, const CornerTable& table,
                                const std::vector<double>* positions, MeshAttribute* attribute);

}  // namespace gab
